// The nodes a root reaches, each once, in id order.
#include "graph/nodes_below.hpp"

#include <gtest/gtest.h>

#include "support/example_graphs.hpp"

namespace vern {
namespace {

TEST(NodesBelow, EachReachedNodeOnceInIdOrderAndNothingElse) {
  Grammar g;
  // I(a) is written twice below the first root but is one node; the
  // second root's I(c) is not below the first.
  const auto r = test::example_graphs(g, {"split(x){ ~1 : I(a) | ~1 : split(y){ ~1 : I(a) | ~1 : I(b) } }", "I(c)"});
  const std::vector<NodeId> below = nodes_below(g, r[0]);
  EXPECT_TRUE(std::is_sorted(below.begin(), below.end()));
  EXPECT_EQ(std::adjacent_find(below.begin(), below.end()), below.end());
  EXPECT_EQ(below.size(), 4u);  // the two splits, I(a), I(b)
  EXPECT_EQ(std::count(below.begin(), below.end(), r[0]), 1);
  EXPECT_EQ(std::count(below.begin(), below.end(), r[1]), 0);
  EXPECT_EQ(nodes_below(g, r[1]), std::vector<NodeId>{r[1]});
}

}  // namespace
}  // namespace vern
