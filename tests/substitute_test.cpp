// Rebuilding a graph with some nodes replaced.
#include "inverse/merge/substitute.hpp"

#include <gtest/gtest.h>

#include "graph/writer.hpp"
#include "support/example_graphs.hpp"

namespace vern {
namespace {

TEST(Substitute, ReplacesEveryUseAndRebuildsOnlyWhatHoldsOne) {
  Grammar g;
  const auto roots = test::example_graphs(
      g, {"split(x){ ~1 : I(a) | ~1 : split(y){ ~1 : I(a) | ~1 : I(b) } | ~1 : I(c) }", "I(a)", "I(d)", "I(c)"});
  const NodeId a = roots[1], d = roots[2], c = roots[3];
  std::vector<NodeId> replace(g.node_count(), kNoReplacement);
  replace[a] = d;
  const NodeId out = substitute(g, roots[0], replace);
  EXPECT_EQ(write_operation(g, out, {}), "split(x){ ~1 : I(d) | ~1 : split(y){ ~1 : I(d) | ~1 : I(b) } | ~1 : I(c) }");
  EXPECT_EQ(std::get<Split>(g.op(out)).parts[2].child, c);  // untouched parts keep their node
}

TEST(Substitute, NothingToReplaceIsTheSameRoot) {
  Grammar g;
  const auto roots = test::example_graphs(g, {"split(x){ ~1 : I(a) | ~1 : I(b) }"});
  EXPECT_EQ(substitute(g, roots[0], {}), roots[0]);
}

TEST(Substitute, UntilSettledReachesWhatAReplacementHolds) {
  Grammar g;
  // a becomes a split holding b, and b becomes d: one pass leaves b inside
  // the new split (it does not look into a replacement), the next replaces it.
  const auto roots = test::example_graphs(
      g, {"split(x){ ~1 : I(a) | ~1 : I(c) }", "I(a)", "split(y){ ~1 : I(b) | ~1 : I(c) }", "I(b)", "I(d)"});
  std::vector<NodeId> replace(g.node_count(), kNoReplacement);
  replace[roots[1]] = roots[2];
  replace[roots[3]] = roots[4];
  EXPECT_EQ(write_operation(g, substitute(g, roots[0], replace), {}),
            "split(x){ ~1 : split(y){ ~1 : I(b) | ~1 : I(c) } | ~1 : I(c) }");
  EXPECT_EQ(write_operation(g, substitute_until_settled(g, roots[0], replace), {}),
            "split(x){ ~1 : split(y){ ~1 : I(d) | ~1 : I(c) } | ~1 : I(c) }");
}

}  // namespace
}  // namespace vern
