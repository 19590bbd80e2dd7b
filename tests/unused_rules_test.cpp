// Rules nothing calls are dropped; what the grammar derives stays the same.
#include "inverse/write/unused_rules.hpp"

#include <gtest/gtest.h>

#include "forward/derive.hpp"
#include "graph/parser.hpp"
#include "graph/writer.hpp"

namespace vern {
namespace {

TEST(UnusedRules, RulesNothingCallsAreDropped) {
  Grammar g = parse_grammar(R"(
@scope 10, 10, 10
start --> split(x){ ~1 : left | ~1 : right }
orphan --> split(z){ ~1 : I(rect) | ~1 : left }
left --> I(rect)
right --> split(z){ ~rand(1, 2) : I(rect) | ~1 : nil }
)",
                            "rules.grm");
  DeriveOptions o;
  o.seed = 7;
  const Derivation before = derive(g, o);
  drop_unused_rules(g);
  ASSERT_EQ(g.rules.size(), 3u) << write_grammar(g);
  EXPECT_FALSE(g.find_rule("orphan"));
  EXPECT_EQ(g.rules[g.start_rule].label, "start");
  const Derivation after = derive(g, o);
  ASSERT_EQ(after.terminals.size(), before.terminals.size());
  for (std::size_t i = 0; i < after.terminals.size(); ++i) {
    const Bounds a = world_bounds(after.terminals[i].scope), b = world_bounds(before.terminals[i].scope);
    EXPECT_EQ(a.min, b.min);
    EXPECT_EQ(a.max, b.max);
  }
}

TEST(UnusedRules, AGrammarUsingEveryRuleIsUnchanged) {
  Grammar g = parse_grammar("a --> split(x){ ~1 : b | ~1 : b }\nb --> I(rect)\n", "used.grm");
  const std::string text = write_grammar(g);
  drop_unused_rules(g);
  EXPECT_EQ(write_grammar(g), text);
}

}  // namespace
}  // namespace vern
