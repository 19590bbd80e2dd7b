// Which members of a structural group are one kind by their sizes.
#include "inverse/merge/size_clusters.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "graph/import.hpp"
#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "inverse/write/rule_naming.hpp"
#include "support/example_graphs.hpp"

namespace vern {
namespace {

SizedMember member(std::vector<double> lengths, double weight = 1) {
  SizedMember m;
  for (double l : lengths) m.sizes.push_back(Range{l, l});
  m.weight = weight;
  return m;
}

TEST(SizeClusters, UnevenlySpreadPlotsAreOneKind) {
  // Ten plots from 8 to 20 m, with a 27 % gap between 10.1 and 12.8: wide
  // for a quarter, narrow for ten values spread over a factor of 2.5.
  std::vector<SizedMember> plots;
  for (double w : {8.0, 8.6, 9.5, 10.1, 12.8, 14.0, 15.5, 17.0, 18.2, 20.0}) plots.push_back(member({w}));
  EXPECT_EQ(size_clusters(plots), std::vector<std::size_t>(10, 0));
}

TEST(SizeClusters, RailingsWallsAndSlabsSeenOftenAreThreeKinds) {
  const std::vector<SizedMember> parts = {member({0.6}, 12), member({0.2}, 10), member({10}, 8), member({0.21}, 3),
                                          member({9.5}, 2)};
  EXPECT_EQ(size_clusters(parts), (std::vector<std::size_t>{0, 1, 2, 1, 2}));
}

TEST(SizeClusters, WingsOfOneShareOnPlotsOfManyWidthsAreOneKind) {
  // A U plan's wings, a fifth of plots 16 to 36 m wide: 3.2 to 7.2 m, in
  // two clumps far apart in metres, one share of every plot.
  std::vector<SizedMember> wings;
  for (double plot : {16.0, 16.5, 17.0, 17.2, 34.0, 35.0, 35.5, 36.0}) {
    SizedMember m = member({0.2 * plot, 0.6 * plot, 0.2 * plot});
    m.total = plot;
    wings.push_back(m);
  }
  EXPECT_EQ(size_clusters(wings), std::vector<std::size_t>(8, 0));
  // Read as lengths alone (no shares known) they are two kinds.
  for (SizedMember& m : wings) m.total = 0;
  EXPECT_EQ(size_clusters(wings), (std::vector<std::size_t>{0, 0, 0, 0, 1, 1, 1, 1}));
}

TEST(SizeClusters, TwoLengthsSeenAgainAndAgainStayTwoKindsWhateverTheirShares) {
  // Shop windows always 2.8 m in a 4.2 m ground floor, upper windows
  // always 1.4 m in storeys of 2 to 3 m: their shares overlap (0.67 and
  // 0.47 to 0.7), their lengths are two kinds.
  std::vector<SizedMember> windows;
  for (double storey : {2.0, 2.3, 2.6, 2.9, 4.2, 4.2, 4.2, 4.2}) {
    const double window = storey == 4.2 ? 2.8 : 1.4;
    SizedMember m = member({window});
    m.total = storey;
    windows.push_back(m);
  }
  EXPECT_EQ(size_clusters(windows), (std::vector<std::size_t>{0, 0, 0, 0, 1, 1, 1, 1}));
}

TEST(SizeClusters, EveryPartMustAgree) {
  // Alike in the first part, far apart in the second.
  const std::vector<SizedMember> parts = {member({3, 0.2}, 5), member({3.1, 0.21}, 5), member({3.05, 8}, 5)};
  EXPECT_EQ(size_clusters(parts), (std::vector<std::size_t>{0, 0, 1}));
}

TEST(SizeClusters, ValuesWithinAQuarterAreNeverApart) {
  // Two values only, seen very often: their spacing is no evidence.
  const std::vector<SizedMember> parts = {member({3}, 100), member({3.6}, 100)};
  EXPECT_EQ(size_clusters(parts), (std::vector<std::size_t>{0, 0}));
}

TEST(SizeClusters, MergingKeepsABalconysRailingApartFromTheSlab) {
  // The thesis's elongated balcony bars (its figure 12.6): thin railings
  // and thick slabs, one structure, seen in many examples. Merged, each
  // keeps its own size instead of one part ranging from 0.2 to 10.
  Grammar g;
  std::vector<std::string> texts;
  for (int i = 0; i < 6; ++i) {
    const double rail = 0.2 + 0.01 * i, slab = 9.6 + 0.1 * i;
    texts.push_back("split(x){ ~1 : split(z){ ~" + std::to_string(rail) + " : I(rect) | ~3 : nil } | ~1 : split(z){ ~" +
                    std::to_string(slab) + " : I(rect) | ~3 : nil } }");
  }
  const NodeId merged = merge_examples(g, test::example_graphs(g, texts), test::uniform_merge());
  const auto& row = std::get<Split>(g.op(merged));
  ASSERT_NE(row.parts[0].child, row.parts[1].child);
  const auto rail = literal_range(std::get<Split>(g.op(row.parts[0].child)).parts[0].size.value);
  const auto slab = literal_range(std::get<Split>(g.op(row.parts[1].child)).parts[0].size.value);
  ASSERT_TRUE(rail && slab);
  EXPECT_LE(rail->hi, 0.25);
  EXPECT_GE(slab->lo, 9.6);
}

TEST(SizeClusters, ClearlyBimodalHeightsBecomeSeparateAlternatives) {
  // Garages about 3 m high in four examples and about 6 m in four: two
  // alternatives, each ranging over its own heights, not one from 3 to 6.3.
  Grammar g;
  std::vector<std::string> texts;
  for (const double h : {3.0, 6.0, 3.1, 6.2, 3.05, 6.1, 3.15, 6.3})
    texts.push_back("split(x){ ~6 : I(house) | ~3 : split(z){ ~" + std::to_string(h) + " : I(rect) | ~" +
                    std::to_string(9 - h) + " : nil } }");
  const NodeId merged = merge_examples(g, test::example_graphs(g, texts), test::uniform_merge());
  // The houses differ at the garage only: one house, its garage a choice
  // of the two kinds (the same buildings as two alternatives of houses).
  const auto* house = std::get_if<Split>(&g.op(merged));
  ASSERT_NE(house, nullptr) << write_grammar(rules_for(g, merged, {}));
  const auto* alternatives = std::get_if<Choose>(&g.op(house->parts[1].child));
  ASSERT_NE(alternatives, nullptr);
  ASSERT_EQ(alternatives->options.size(), 2u);
  std::vector<Range> heights;
  for (const auto& o : alternatives->options) {
    EXPECT_EQ(o.priority.literal(), 4.0);
    const auto& garage = std::get<Split>(g.op(o.child));
    heights.push_back(*literal_range(garage.parts[0].size.value));
  }
  std::sort(heights.begin(), heights.end(), [](const Range& a, const Range& b) { return a.lo < b.lo; });
  EXPECT_EQ(heights[0].lo, 3.0);
  EXPECT_EQ(heights[0].hi, 3.15);
  EXPECT_EQ(heights[1].lo, 6.0);
  EXPECT_EQ(heights[1].hi, 6.3);
}

}  // namespace
}  // namespace vern

namespace vern {
namespace {

TEST(SizeClusters, TwentyHeightsOfOneSpreadAreOneKind) {
  // Houses 4 to 10 m high and garages half as high, ten examples each
  // (drawn from one rand(4, 10)): together one spread, 2.1 to 9.8 m. Its
  // widest gap, 2.18 to 2.84 (1.3 times), is three average spacings
  // wide, as twenty values of one kind often show.
  std::vector<SizedMember> heights;
  for (double h : {4.37, 6.55, 8.53, 5.68, 4.13, 7.41, 9.84, 9.48, 8.45, 8.27}) {
    heights.push_back(member({h}));
    heights.push_back(member({h / 2}));
  }
  EXPECT_EQ(size_clusters(heights), std::vector<std::size_t>(20, 0));
}

TEST(SizeClusters, AirLeftAboveAPartMakesNoKind) {
  // Houses 4 to 9 m high in a 10 m plot, and one 9.9 m high: the air above
  // them is 1 to 6 m, and 0.1 m, ten times less: far apart, but only what
  // the houses leave. One kind of house, 4 to 9.9 m.
  Grammar g;
  std::vector<std::string> texts;
  std::vector<double> heights{9.9};
  for (int i = 0; i <= 20; ++i) heights.push_back(4 + 0.25 * i);
  for (double h : heights)
    texts.push_back("split(z){ ~" + std::to_string(h) + " : I(rect) | ~" + std::to_string(10 - h) + " : nil }");
  const NodeId merged = merge_examples(g, test::example_graphs(g, texts), test::uniform_merge());
  ASSERT_TRUE(std::holds_alternative<Split>(g.op(merged)));
  const auto house = literal_range(std::get<Split>(g.op(merged)).parts[0].size.value);
  ASSERT_TRUE(house);
  EXPECT_NEAR(house->lo, 4, 1e-9);
  EXPECT_NEAR(house->hi, 9.9, 1e-9);
}

}  // namespace
}  // namespace vern

namespace vern {
namespace {

TEST(SizeClusters, ARunOfTilesMakesNoKind) {
  // A door bay after one, two or three bays of 3.5 m, two examples each:
  // the run before the door is 3.5, 7 or 10.5 m long, kinds far apart by
  // their lengths, but a run of tiles is as long as its count makes it.
  // One front, its run ranging over the three, not one front per count.
  Grammar g;
  std::vector<std::string> texts;
  for (int bays : {1, 2, 3, 1, 2, 3}) {
    const double run = 3.5 * bays, rest = 21 - run - 3.5;
    texts.push_back("split(x){ ~" + std::to_string(run) + " : repeat(x, 3.5){ split(x){ ~1 : I(wall) | ~1.5 : " +
                    "I(window) | ~1 : I(wall) } } | ~1 : I(wall) | ~1.5 : I(door) | ~1 : I(wall) | ~" +
                    std::to_string(rest) + " : repeat(x, 3.5){ split(x){ ~1 : I(wall) | ~1.5 : I(window) | ~1 : " +
                    "I(wall) } } }");
  }
  const NodeId merged = merge_examples(g, test::example_graphs(g, texts), test::uniform_merge());
  const auto* front = std::get_if<Split>(&g.op(merged));
  ASSERT_NE(front, nullptr) << write_grammar(rules_for(g, merged, {}));
  const auto run = literal_range(front->parts[0].size.value);
  ASSERT_TRUE(run);
  EXPECT_NEAR(run->lo, 3.5, 1e-9);
  EXPECT_NEAR(run->hi, 10.5, 1e-9);
}

}  // namespace
}  // namespace vern
