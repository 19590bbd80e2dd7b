// Description length: rules, distinct reachable operations, number literals.
#include "graph/description_length.hpp"

#include <gtest/gtest.h>

#include "graph/parser.hpp"

namespace vern {
namespace {

TEST(DescriptionLength, CountsRulesOperationsAndNumbers) {
  const Grammar g = parse_grammar(
      "@scope 12, 8, 9\n"
      "w = 0.7\n"
      "a --> split(x){ w : I(rect) | ~1 : b | w : I(rect) }\n"
      "b --> repeat(x, 2){ I(window) }\n");
  const DescriptionLength d = description_length(g);
  EXPECT_EQ(d.rules, 2u);
  // split, I(rect) twice, the call of b; repeat, I(window).
  EXPECT_EQ(d.operations, 6u);
  // 12, 8, 9; 0.7; ~1; 2 (w is a constant, not a literal, where it is used).
  EXPECT_EQ(d.numbers, 6u);
  EXPECT_EQ(d.total(), 12u);
}

TEST(DescriptionLength, RangesAreTwoNumbersAndAxesNone) {
  const Grammar small = parse_grammar("a --> split(x){ ~1 : I(rect) | ~1 : nil }\n");
  const Grammar random = parse_grammar("a --> split(x){ ~rand(1, 2) : I(rect) | ~1 : nil }\n");
  EXPECT_EQ(description_length(small).numbers, 2u);
  EXPECT_EQ(description_length(random).numbers, 3u);  // a range is two free parameters
  EXPECT_EQ(description_length(small).operations, description_length(random).operations);
}

}  // namespace
}  // namespace vern
