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

TEST(Substitute, AGraphHundredsOfThousandsDeepIsRebuiltWithoutRunningOutOfStack) {
  // Inference met one deep enough to run the thread's stack out in a
  // recursion (378 CMP facades at --tolerance 0.045).
  Grammar g;
  const auto roots = test::example_graphs(g, {"split(x){ ~1 : I(a) | ~1 : I(b) }", "I(a)", "I(d)"});
  const Split outer = std::get<Split>(g.op(roots[0]));
  NodeId deep = roots[0];
  constexpr int kDepth = 300'000;
  for (int i = 0; i < kDepth; ++i) {
    Split s = outer;
    s.parts[0].child = deep;
    deep = g.intern({s, {}});
  }
  std::vector<NodeId> replace(g.node_count(), kNoReplacement);
  replace[roots[1]] = roots[2];
  const NodeId out = substitute(g, deep, replace);
  ASSERT_NE(out, deep);
  // Down the first parts: kDepth + 1 splits, then the replacement.
  NodeId at = out;
  int splits = 0;
  while (const Split* s = std::get_if<Split>(&g.op(at))) {
    EXPECT_EQ(s->parts[1].child, std::get<Split>(g.op(roots[0])).parts[1].child);  // I(b) kept
    at = s->parts[0].child;
    ++splits;
  }
  EXPECT_EQ(splits, kDepth + 1);
  EXPECT_EQ(at, roots[2]);
}

}  // namespace
}  // namespace vern
