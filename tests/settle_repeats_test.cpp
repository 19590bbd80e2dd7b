// Repeats settled once merging is done (settle_repeats.hpp): the same count
// on different lengths is that count; varying counts take tile sizes from
// the middle of each count's range. Through merge_examples.
#include "inverse/settle_repeats.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "inverse/merge.hpp"
#include "support/example_graphs.hpp"

namespace vern {
namespace {

// A row of n equal windows, each w wide.
std::string windows(int n, double w) {
  std::string t = "split(x){";
  for (int i = 0; i < n; ++i) t += std::string(i ? " |" : "") + " ~" + std::to_string(w) + " : I(window)";
  return t + " }";
}

TEST(SettleRepeats, TheSameCountOnDifferentLengthsIsThatManyTiles) {
  // Three windows on 9 m and three on 7.5 m: repeatN(x, 3), whatever the width.
  Grammar g;
  const NodeId merged = merge_examples(g, test::example_graphs(g, {windows(3, 3), windows(3, 2.5)}), {1e-9, true});
  const auto* row = std::get_if<RepeatN>(&g.op(merged));
  ASSERT_NE(row, nullptr);
  EXPECT_EQ(row->count.literal(), 3.0);
}

TEST(SettleRepeats, VaryingCountsTakeTileSizesFromTheMiddleOfEachCountsRange) {
  // Three windows on 9 m (any tile in [3, 4.5) makes three) and four on
  // 10 m ([2.5, 3.33)): the middles 9 / 2.5 = 3.6 and 10 / 3.5 = 2.86,
  // written as the shortest decimals a quarter of the way to their ranges'
  // nearer ends (3.6 and 3), instead of the lower ends 3 and 2.5.
  Grammar g;
  const NodeId merged = merge_examples(g, test::example_graphs(g, {windows(3, 3), windows(4, 2.5)}), {1e-9, true});
  const auto* row = std::get_if<Repeat>(&g.op(merged));
  ASSERT_NE(row, nullptr);
  const auto tile = literal_range(row->size);
  ASSERT_TRUE(tile);
  EXPECT_EQ(tile->lo, 3.0);
  EXPECT_EQ(tile->hi, 3.6);
  // Each example's own count is still there to be drawn.
  for (const auto& [length, count] : {std::pair{9.0, 3.0}, std::pair{10.0, 4.0}}) {
    EXPECT_GE(std::ceil(length / tile->lo), count) << length;
    EXPECT_LE(std::ceil(length / tile->hi), count) << length;
  }
}

TEST(SettleRepeats, AConstantTileStaysAsItIs) {
  // Windows 3 m wide on 9 and 12 m: the tile is 3 (just above) in both.
  Grammar g;
  const NodeId merged = merge_examples(g, test::example_graphs(g, {windows(3, 3), windows(4, 3)}), {1e-9, true});
  const auto* row = std::get_if<Repeat>(&g.op(merged));
  ASSERT_NE(row, nullptr);
  ASSERT_TRUE(row->size.literal().has_value());
  EXPECT_GT(*row->size.literal(), 3.0);
  EXPECT_LT(*row->size.literal(), 3.04);
}

}  // namespace
}  // namespace vern
