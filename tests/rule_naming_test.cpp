// Names for rules added to a written grammar: after the primitives below
// and what the node does, the way rules_for names the rules it makes.
#include "inverse/write/rule_naming.hpp"

#include <gtest/gtest.h>

#include "graph/parser.hpp"

namespace vern {
namespace {

TEST(RuleNaming, ANodeIsNamedAfterItsLabelsThroughTheRulesItCalls) {
  const Grammar g = parse_grammar("a --> split(z){ ~1 : I(right_angle) | ~1 : b }\nb --> I(roof)\n", "names.grm");
  EXPECT_EQ(node_name(g, g.rules[0].body), "rightAngleRoofZ");
  EXPECT_EQ(node_name(g, g.rules[1].body), "roofPart");
}

TEST(RuleNaming, AFreeLabelIsNoRulesAndNoOperations) {
  const Grammar g = parse_grammar("rectZ --> I(rect)\nrectZ2 --> I(rect)\n", "taken.grm");
  EXPECT_EQ(free_label(g, "rectZ"), "rectZ3");
  EXPECT_EQ(free_label(g, "roofZ"), "roofZ");
  EXPECT_EQ(free_label(g, "split"), "split2");
}

}  // namespace
}  // namespace vern
