// Repeats settled once merging is done (settle_repeats.hpp): the same count
// on different lengths is that count; varying counts take tile sizes from
// the middle of each count's range. Through merge_examples.
#include "inverse/sizes/settle_repeats.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "inverse/merge/merge.hpp"
#include "support/example_graphs.hpp"

namespace vern {
namespace {

// A row of n equal windows, each w wide.
std::string windows(int n, double w) {
  std::string t = "split(x){";
  for (int i = 0; i < n; ++i) t += std::string(i ? " |" : "") + " ~" + std::to_string(w) + " : I(window)";
  return t + " }";
}

TEST(SettleRepeats, TheSameCountWhereNoTileGivesItIsThatManyTiles) {
  // Six windows on 15 m and six on 18.3 m: no tile makes six on both
  // ([2.5, 3) and [3.05, 3.66)), so the row is six tiles whatever the
  // width: repeatN(x, 6).
  Grammar g;
  const NodeId merged = merge_examples(g, test::example_graphs(g, {windows(6, 2.5), windows(6, 3.05)}), test::uniform_merge());
  const auto* row = std::get_if<RepeatN>(&g.op(merged));
  ASSERT_NE(row, nullptr);
  EXPECT_EQ(row->count.literal(), 6.0);
}

TEST(SettleRepeats, CountsThatOneTileGivesAreThatTile) {
  // Three windows on 9 m and three on 7.5 m: any tile in [3, 3.75) makes
  // three on both, and a wider plot more: the row follows the plot, its
  // tile the shortest decimal there, 3 (not repeatN(x, 3)). Three on 9 m
  // and four on 10 m: [3, 3.33), 3 again (not a range that draws counts
  // neither example had). Three on 9.3 m and three on 7.5 m: [3.1, 3.75),
  // 3.4, the one-decimal size nearest the middle.
  for (const auto& [second, tile] :
       {std::pair{windows(3, 2.5), 3.0}, std::pair{windows(4, 2.5), 3.0}}) {
    Grammar g;
    const NodeId merged = merge_examples(g, test::example_graphs(g, {windows(3, 3), second}), test::uniform_merge());
    const auto* row = std::get_if<Repeat>(&g.op(merged));
    ASSERT_NE(row, nullptr) << second;
    EXPECT_EQ(row->size.literal(), tile) << second;
  }
  Grammar g;
  const NodeId merged = merge_examples(g, test::example_graphs(g, {windows(3, 3.1), windows(3, 2.5)}), test::uniform_merge());
  const auto* row = std::get_if<Repeat>(&g.op(merged));
  ASSERT_NE(row, nullptr);
  EXPECT_EQ(row->size.literal(), 3.4);
}

TEST(SettleRepeats, VaryingCountsNoTileGivesTakeTileSizesFromTheMiddleOfEachCountsRange) {
  // Six windows on 12 m (any tile in [2, 2.4) makes six) and five on
  // 12.25 m ([2.45, 3.06)): no one tile gives both. The middles
  // 12 / 5.5 = 2.18 and 12.25 / 4.5 = 2.72, written as the shortest
  // decimals a quarter of the way to their ranges' nearer ends (2.2 and
  // 2.7), instead of the lower ends 2 and 2.45.
  Grammar g;
  const NodeId merged = merge_examples(g, test::example_graphs(g, {windows(6, 2), windows(5, 2.45)}), test::uniform_merge());
  const auto* row = std::get_if<Repeat>(&g.op(merged));
  ASSERT_NE(row, nullptr);
  const auto tile = literal_range(row->size);
  ASSERT_TRUE(tile);
  EXPECT_EQ(tile->lo, 2.2);
  EXPECT_EQ(tile->hi, 2.7);
  // Each example's own count is still there to be drawn.
  for (const auto& [length, count] : {std::pair{12.0, 6.0}, std::pair{12.25, 5.0}}) {
    EXPECT_GE(std::ceil(length / tile->lo), count) << length;
    EXPECT_LE(std::ceil(length / tile->hi), count) << length;
  }
}

TEST(SettleRepeats, CommonTileKeepsEveryCountAndClearsTheToleranceAtBothEnds) {
  const std::vector<TileSeen> seen{{3, 9.0}, {4, 10.0}, {5, 15.9}};
  // [3, 4.5) and [2.5, 3.33) and [3.18, 3.975): [3.18, 3.33).
  const auto t = common_tile(seen, 1e-6);
  ASSERT_TRUE(t);
  EXPECT_EQ(*t, 3.3);
  for (const TileSeen& s : seen) EXPECT_EQ(repeat_tile_count(s.length, *t), s.count);
  // A length known to 0.2 m leaves no room: 3.18 + 0.04 .. 3.33 - 0.067.
  EXPECT_FALSE(common_tile({{3, 9.0}, {4, 10.0}, {5, 15.9}, {5, 16.6}}, 0.2));
}

TEST(SettleRepeats, LengthsOfWholeTilesInCentimetresAreTheTile) {
  // Bays of 4.5 m, one or two before a door (whole bays), the rest a
  // stretching repeat on lengths drawn at random: these alone allow
  // [4.5, 5.67), whose shortest decimal is 5; but lengths drawn at random
  // are never whole tiles of 4.5 m.
  const std::vector<TileSeen> seen{{1, 4.5}, {2, 9.0}, {3, 12.3456}, {2, 6.789}, {4, 17.01234}};
  EXPECT_EQ(common_tile(seen, 1e-6), 4.5);
  // On a centimetre grid every length is whole centimetres, and one of
  // them whole tiles of something by chance: two lengths must tell.
  EXPECT_EQ(common_tile({{2, 9.0}, {3, 12.35}, {2, 6.79}, {4, 17.01}}, 1e-6), 5.0);
  EXPECT_EQ(common_tile({{2, 9.0}, {3, 13.5}, {3, 12.35}, {2, 6.79}, {4, 17.01}}, 1e-6), 4.5);
}

TEST(SettleRepeats, TilesThatDivideALengthExactlyAreTheTileDespiteFloatNoise) {
  // A run of six bays of exactly 3.8 m measured a hair long (its parts'
  // lengths summed as derived: 22.800000000005 m), beside rows of 20, 26
  // and 34.5 m ([3.8, 3.83) gives every count): 3.8, which gives six
  // tiles there too (repeat_tile_count forgives the noise), not the 3.82
  // just above the noise, which gives some fresh rows a bay fewer.
  const std::vector<TileSeen> seen{{6, 22.800000000005}, {6, 20.0}, {7, 26.0}, {10, 34.5}};
  const auto t = common_tile(seen, 1e-6);
  ASSERT_TRUE(t);
  EXPECT_EQ(*t, 3.8);
  for (const TileSeen& s : seen) EXPECT_EQ(repeat_tile_count(s.length, *t), s.count);
}

TEST(SettleRepeats, AConstantTileStaysAsItIs) {
  // Windows 3 m wide on 9 and 12 m: the tile is 3 (just above) in both.
  Grammar g;
  const NodeId merged = merge_examples(g, test::example_graphs(g, {windows(3, 3), windows(4, 3)}), test::uniform_merge());
  const auto* row = std::get_if<Repeat>(&g.op(merged));
  ASSERT_NE(row, nullptr);
  ASSERT_TRUE(row->size.literal().has_value());
  EXPECT_GT(*row->size.literal(), 3.0);
  EXPECT_LT(*row->size.literal(), 3.04);
}

TEST(SettleRepeats, OneTileSizeThatDoesNotGiveTheCountsSeenIsMovedToOneThatDoes) {
  // A row of tiles of 0.97 where the examples showed 31 on 30.132 m and
  // 30 on 29.082 m, known to a centimetre (towers far from the origin): 0.97
  // makes 32 on 30.132 m. The tile must give every count seen, and still
  // on a length a tolerance longer: 1. A tile that gives them firmly stays.
  for (const auto& [tile, settled] : {std::pair{0.97, 1.0}, std::pair{0.99, 0.99}}) {
    Grammar g;
    const NodeId row = test::example_graphs(g, {"repeat(x, " + std::to_string(tile) + "){ I(window) }"})[0];
    const TileCounts counts{{row, {{31, 30.132}, {30, 29.082}}}};
    SampleBook book;
    const NodeId out = settle_repeats(g, row, counts, book, 0.01);
    const auto* repeat = std::get_if<Repeat>(&g.op(out));
    ASSERT_NE(repeat, nullptr);
    EXPECT_EQ(repeat->size.literal(), settled) << tile;
  }
}

// Two rows of storeys along z, as merging kept them (3.3 and 3.6 m), and
// a brick course of 3.6 m, settled with the counts each was seen with:
// the three tile sizes. Each storey size gives its own examples' counts
// (2 storeys on 6.2 m, 3 on 8.5 m...).
std::vector<double> settled_tiles(const std::string& first_storey, const std::string& second_storey) {
  Grammar g;
  const NodeId root = test::example_graphs(g, {"split(x){ ~1 : repeat(z, 3.3){ " + first_storey + " } | ~1 : repeat(z, 3.6){ " +
                                                   second_storey + " } | ~1 : repeat(z, 3.6){ I(brick) } }"})[0];
  const auto& parts = std::get<Split>(g.op(root)).parts;
  const TileCounts counts{{parts[0].child, {{2, 6.2}, {3, 8.5}, {3, 9.0}}},
                          {parts[1].child, {{2, 5.7}, {3, 9.4}, {2, 6.0}}},
                          {parts[2].child, {{2, 6.2}, {3, 9.4}}}};
  SampleBook book;
  const NodeId out = settle_repeats(g, root, counts, book, 1e-6);
  const auto& settled = std::get<Split>(g.op(out)).parts;
  std::vector<double> tiles;
  for (const auto& p : settled) tiles.push_back(*std::get<Repeat>(g.op(p.child)).size.literal());
  // Every count still comes out on its length.
  for (std::size_t i = 0; i < 3; ++i)
    for (const TileSeen& t : counts.at(parts[i].child)) EXPECT_EQ(repeat_tile_count(t.length, tiles[i]), t.count) << i;
  return tiles;
}

TEST(SettleRepeats, RepeatsOfTheSameTilesShareOneTileSize) {
  // Storeys of balconies and windows in two alternatives of a door bay's
  // place: each size was kept, and a house of one alternative stacked a
  // storey more than one of the other on the same height. Together they
  // take one size that gives every count of both. A repeat of other parts
  // keeps its own.
  const auto tiles = settled_tiles("split(x){ ~1 : I(balcony) | ~1 : I(window) }",
                                   "split(x){ ~2 : I(window) | ~1 : I(balcony) }");
  EXPECT_EQ(tiles[0], tiles[1]);
  EXPECT_EQ(tiles[2], 3.6);
}

TEST(SettleRepeats, StoreysOfOneShapeShareOneTileSizeWhateverTheirBays) {
  // The same with balconies in one alternative and infill panels in the
  // other: rows cut along x, made of different parts, still storeys.
  const auto tiles = settled_tiles("split(x){ ~1 : I(balcony) | ~1 : I(window) }",
                                   "split(x){ ~2 : I(infill) | ~1 : I(casement) }");
  EXPECT_EQ(tiles[0], tiles[1]);
  EXPECT_EQ(tiles[2], 3.6);
}

TEST(SettleRepeats, CountsThatDoNotFollowTheLengthsAreDrawnAsCounts) {
  // A street of three to six equal houses on plots 30 to 60 m wide, the
  // count drawn apart from the width (a recursion, row(n)): no tile size
  // gives the counts, and a range of tile sizes would draw two to eleven
  // houses on those widths. As many as the examples had, whatever the
  // width: repeatN(x, randint(3, 6)).
  Grammar g;
  const NodeId row = test::example_graphs(g, {"repeat(x, rand(5.6, 18.4)){ I(house) }"})[0];
  const std::vector<TileSeen> seen{{3, 52.1}, {6, 33.4}, {4, 58.0}, {5, 31.2}, {3, 36.8},
                                   {6, 55.3}, {4, 41.9}, {5, 47.5}, {3, 44.0}, {6, 39.7}};
  const TileCounts counts{{row, seen}};
  SampleBook book;
  const NodeId out = settle_repeats(g, row, counts, book, 1e-6);
  const auto* street = std::get_if<RepeatN>(&g.op(out));
  ASSERT_NE(street, nullptr);
  EXPECT_EQ(street->count, Expr::call(Function::RandInt, {Expr::number(3), Expr::number(6)}));
  // Counts that grow with the length, from a tile of 3 to 4 m, stay tiles.
  Grammar h;
  const NodeId storeys = test::example_graphs(h, {"repeat(z, rand(3, 4)){ I(storey) }"})[0];
  const std::vector<TileSeen> grown{{3, 10.5}, {4, 13.0}, {6, 20.1}, {8, 27.5}, {10, 33.0},
                                    {5, 17.8}, {7, 24.2}, {9, 30.9}, {11, 38.1}, {4, 14.9}};
  const NodeId settled = settle_repeats(h, storeys, {{storeys, grown}}, book, 1e-6);
  EXPECT_TRUE(std::holds_alternative<Repeat>(h.op(settled)));
}

}  // namespace
}  // namespace vern
