// The operation graph's arena (graph/grammar.hpp): interning, and going
// back to a checkpoint.
#include "graph/grammar.hpp"

#include <gtest/gtest.h>

#include "graph/parser.hpp"

namespace vern {
namespace {

Node box(Grammar& g, const char* label) { return Node{Primitive{g.label_id(label)}, {}}; }

// split(axis){ ~share : child | ... }
Node split(Axis axis, const std::vector<std::pair<double, NodeId>>& parts) {
  Split s;
  s.axis = Expr::axis(axis);
  for (const auto& [share, child] : parts) {
    SplitPart p;
    p.size = Size{Expr::number(share), true};
    p.child = child;
    s.parts.push_back(std::move(p));
  }
  return Node{std::move(s), {}};
}

TEST(Grammar, InterningGivesEqualOperationsOneId) {
  Grammar g;
  const NodeId a = g.intern(box(g, "wall"));
  const NodeId b = g.intern(box(g, "roof"));
  EXPECT_NE(a, b);
  EXPECT_EQ(g.intern(box(g, "wall")), a);
  EXPECT_EQ(g.node_count(), 2u);
}

TEST(Grammar, ARollbackForgetsWhatCameAfterItsCheckpoint) {
  Grammar g = parse_grammar("house --> I(door)\n", "test.grm");
  const NodeId wall = g.intern(box(g, "wall"));
  const NodeId roof = g.intern(box(g, "roof"));
  g.intern(split(Axis::Z, {{3, wall}, {1, roof}}));
  const std::size_t nodes = g.node_count();
  const Grammar::Checkpoint before = g.checkpoint();

  // What inference does to a graph while merging: nodes, labels, rules.
  const NodeId chimney = g.intern(box(g, "chimney"));
  for (int k = 0; k < 200; ++k) g.intern(split(Axis::X, {{k + 1.0, chimney}}));
  g.rules.push_back(Rule{"extra", {}, chimney, {}});
  g.start_rule = 1;
  g.primitives = "other.obj";
  ASSERT_GT(g.node_count(), nodes + 200);

  g.rollback(before);
  EXPECT_EQ(g.node_count(), nodes);
  EXPECT_EQ(g.rules.size(), 1u);
  EXPECT_EQ(g.start_rule, 0u);
  EXPECT_EQ(g.primitives, "");
  EXPECT_FALSE(g.find_label("chimney"));
  // Nodes from before keep their ids; one forgotten is made anew.
  EXPECT_EQ(g.intern(box(g, "wall")), wall);
  EXPECT_EQ(g.intern(box(g, "chimney")), static_cast<NodeId>(nodes));
  EXPECT_EQ(g.node_count(), nodes + 1);
}

}  // namespace
}  // namespace vern
