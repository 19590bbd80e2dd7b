// A place's choice with plain nested choices spread (weighted_choice.hpp).
#include "inverse/merge/weighted_choice.hpp"

#include <gtest/gtest.h>

namespace vern {
namespace {

NodeId primitive(Grammar& g, const char* label) {
  return g.intern({Primitive{g.label_id(label)}, {}});
}

double weight_of(const Choose& c, NodeId child) {
  for (const auto& o : c.options)
    if (o.child == child) return *o.priority.literal();
  return 0;
}

TEST(WeightedChoice, APlainChoiceHeldAtThePlaceGivesItsOptionsTheirShare) {
  Grammar g;
  const NodeId shop = primitive(g, "shop"), door = primitive(g, "door"), window = primitive(g, "window");
  // "door or window" (1 : 3), held twice; the shop once; the window once more.
  Choose inner;
  inner.options.push_back({Expr{}, Expr::number(1), door});
  inner.options.push_back({Expr{}, Expr::number(3), window});
  const NodeId door_or_window = g.intern({std::move(inner), {}});
  const NodeId out = weighted_choice(g, {{shop, 1}, {door_or_window, 2}, {window, 1}});
  const auto* c = std::get_if<Choose>(&g.op(out));
  ASSERT_NE(c, nullptr);
  ASSERT_EQ(c->options.size(), 3u);
  EXPECT_EQ(c->options[0].child, shop);
  EXPECT_DOUBLE_EQ(weight_of(*c, shop), 1);
  EXPECT_DOUBLE_EQ(weight_of(*c, door), 0.5);
  EXPECT_DOUBLE_EQ(weight_of(*c, window), 2.5);
}

TEST(WeightedChoice, AChoiceWithAConditionStaysWhole) {
  Grammar g;
  const NodeId a = primitive(g, "a"), b = primitive(g, "b");
  Choose guarded;
  guarded.options.push_back({Expr::number(1), Expr::number(1), a});  // a condition, however trivial
  guarded.options.push_back({Expr{}, Expr::number(1), b});
  const NodeId kept = g.intern({std::move(guarded), {}});
  const auto* c = std::get_if<Choose>(&g.op(weighted_choice(g, {{kept, 1}, {b, 1}})));
  ASSERT_NE(c, nullptr);
  ASSERT_EQ(c->options.size(), 2u);
  EXPECT_EQ(c->options[0].child, kept);
}

TEST(WeightedChoice, OneChildHeldAgainAndAgainIsThatChild) {
  Grammar g;
  const NodeId a = primitive(g, "a");
  EXPECT_EQ(weighted_choice(g, {{a, 1}, {a, 4}}), a);
}

}  // namespace
}  // namespace vern
