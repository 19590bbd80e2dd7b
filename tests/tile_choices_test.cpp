// Rows of one kind share what their tiles may hold (tile_choices.hpp), and
// repeats of far-apart tile lengths stay different kinds (merge.cpp's
// TileLengths): through merge_examples, on example graphs as inference
// builds them.
#include "inverse/merge/tile_choices.hpp"

#include <gtest/gtest.h>

#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "inverse/merge/merge.hpp"
#include "support/example_graphs.hpp"

namespace vern {
namespace {

// Each text one example's graph (support/example_graphs.hpp).
constexpr auto examples = test::example_graphs;

// Three kinds of building, each its own structure whatever its sizes.
std::string plain(double h) { return "split(z){ ~" + std::to_string(h) + " : I(rect) | ~" + std::to_string(10 - h) + " : nil }"; }
const std::string kRoofed = "split(z){ ~3 : I(rect) | ~1 : I(roof) | ~6 : nil }";
const std::string kTwin = "split(x){ ~1 : " + plain(4) + " | ~1 : " + plain(6) + " }";
const std::string kGlass = "split(z){ ~5 : I(glass) | ~5 : nil }";
const std::string kGlassRoofed = "split(z){ ~5 : I(glass) | ~1 : I(roof) | ~4 : nil }";

// A row of three plots of width w.
std::string row(double w, const std::string& a, const std::string& b, const std::string& c) {
  const std::string s = "~" + std::to_string(w) + " : ";
  return "split(x){ " + s + a + " | " + s + b + " | " + s + c + " }";
}

// The repeat a merged example is (through a choose of one example's form).
const Repeat& repeat_at(const Grammar& g, NodeId id) { return std::get<Repeat>(g.op(id)); }

// What a repeat's tile holds, written with its weights, in order.
std::vector<std::string> alternatives(const Grammar& g, const Repeat& r) {
  std::vector<std::string> out;
  if (const auto* c = std::get_if<Choose>(&g.op(r.child))) {
    for (const auto& o : c->options)
      out.push_back(write_operation(g, o.child, {}) + " : " + std::to_string(int(*o.priority.literal())));
  } else {
    out.push_back(write_operation(g, r.child, {}));
  }
  return out;
}

TEST(TileChoices, RowsSharingABuildingKindShareEveryKindTheyHeld) {
  // Both rows hold plain buildings; one also roofed ones, the other twin
  // towers: one row kind choosing among all three. (A roofed building
  // alone in its row would be the row's odd one out, which folding keeps
  // in its place: repeat_folding_test.)
  Grammar g;
  const auto roots = examples(g, {row(2, kRoofed, plain(5), kRoofed), row(2, plain(4), kTwin, plain(2))});
  const NodeId merged = merge_examples(g, roots, test::uniform_merge());
  const Repeat& r = repeat_at(g, merged);
  const auto held = alternatives(g, r);
  ASSERT_EQ(held.size(), 3u) << ::testing::PrintToString(held);
  EXPECT_NE(held[0].find("I(roof)"), std::string::npos) << held[0];
  EXPECT_NE(held[0].find(" : 2"), std::string::npos) << held[0];  // two roofed plots
  EXPECT_NE(held[1].find("rand(2, 6)"), std::string::npos) << held[1];  // plain, over all five heights
  EXPECT_NE(held[1].find(" : 3"), std::string::npos) << held[1];
  EXPECT_NE(held[2].find("repeatN(x, 2)"), std::string::npos) << held[2];  // the twin towers
}

TEST(TileChoices, RowsSharingNothingStayApart) {
  // A row of brick buildings and a row of glass ones: no alternative in
  // common, so each keeps its own choice.
  Grammar g;
  const auto roots = examples(g, {row(2, kRoofed, plain(5), kRoofed), row(2, kGlassRoofed, kGlass, kGlassRoofed)});
  const NodeId merged = merge_examples(g, roots, test::uniform_merge());
  const auto& forms = std::get<Choose>(g.op(merged));
  ASSERT_EQ(forms.options.size(), 2u);
  EXPECT_EQ(alternatives(g, repeat_at(g, forms.options[0].child)).size(), 2u);
  EXPECT_EQ(alternatives(g, repeat_at(g, forms.options[1].child)).size(), 2u);
}

TEST(TileChoices, TilesOfFarApartLengthsAreDifferentKinds) {
  // Rows of plots 2 and 2.2 wide (three and four of them) are one kind of
  // row; strips 0.5 wide, holding the same kinds of building, are another:
  // their tile lengths stay apart instead of ranging from 0.5 to 2.5.
  Grammar g;
  const std::string four = "split(x){ ~2.2 : " + kRoofed + " | ~2.2 : " + plain(4) + " | ~2.2 : " + kRoofed + " | ~2.2 : " +
                           plain(6) + " }";
  const auto roots = examples(g, {row(2, kRoofed, plain(5), kRoofed), four, row(0.5, plain(4), kTwin, plain(2))});
  const NodeId merged = merge_examples(g, roots, test::uniform_merge());
  const auto& forms = std::get<Choose>(g.op(merged));
  ASSERT_EQ(forms.options.size(), 2u);
  const Repeat& plots = repeat_at(g, forms.options[0].child);
  const Repeat& strips = repeat_at(g, forms.options[1].child);
  const auto strip_tile = literal_range(strips.size);
  ASSERT_TRUE(strip_tile);
  // One tile gives 3 plots on 6 ([2, 3)) and 4 on 8.8 ([2.2, 2.93)): 2.6.
  EXPECT_EQ(plots.size.literal(), 2.6);
  EXPECT_GT(strip_tile->lo, 0.5);
  EXPECT_LT(strip_tile->hi, 0.51);
  EXPECT_EQ(forms.options[0].priority.literal(), 2.0);
}

TEST(TileChoices, NothingToUniteLeavesTheGraphAsItIs) {
  Grammar g;
  const auto roots = examples(g, {row(2, plain(3), plain(3), plain(3))});
  const TileChoiceUnion u = unite_tile_choices(g, roots[0]);
  EXPECT_EQ(u.root, roots[0]);
  EXPECT_TRUE(u.replaced.empty());
}

TEST(TileChoices, ARowWhoseTilesAllHeldOneKindSharesTheChoiceOfRowsThatHeldMore) {
  // A row of three plain buildings of one height (a split tile, no
  // choice: a run of equal parts) and a row of plain and roofed ones: one
  // row kind, whose tiles hold either, not two forms of the example.
  Grammar g;
  const auto roots = examples(g, {row(2, plain(4), plain(4), plain(4)), row(2, kRoofed, plain(4), kRoofed)});
  const NodeId merged = merge_examples(g, roots, test::uniform_merge());
  ASSERT_TRUE(std::holds_alternative<Repeat>(g.op(merged))) << write_operation(g, merged, {});
  const auto held = alternatives(g, repeat_at(g, merged));
  ASSERT_EQ(held.size(), 2u) << ::testing::PrintToString(held);
  EXPECT_EQ(held[0].find("I(roof)"), std::string::npos) << held[0];  // the plain buildings
  EXPECT_NE(held[1].find("I(roof)"), std::string::npos) << held[1];
}

TEST(TileChoices, ARowOfOneKindWeighsEveryTileItHolds) {
  // Two rows of three plain buildings and one of a roofed building between
  // two plain ones: seven plain tiles against two roofed, not one
  // observation per row of one kind (a city whose edge blocks are all
  // small buildings came back with its towers three times as common).
  Grammar g;
  const auto roots = examples(g, {row(2, plain(4), plain(4), plain(4)), row(2, plain(4), plain(4), plain(4)),
                                  row(2, kRoofed, plain(4), kRoofed)});
  const NodeId merged = merge_examples(g, roots, test::uniform_merge());
  ASSERT_TRUE(std::holds_alternative<Repeat>(g.op(merged))) << write_operation(g, merged, {});
  const auto held = alternatives(g, repeat_at(g, merged));
  ASSERT_EQ(held.size(), 2u) << ::testing::PrintToString(held);
  EXPECT_NE(held[0].find(" : 7"), std::string::npos) << held[0];
  EXPECT_NE(held[1].find("I(roof)"), std::string::npos) << held[1];
  EXPECT_NE(held[1].find(" : 2"), std::string::npos) << held[1];
}

TEST(TileChoices, TilesOfOneFrameAreOneFrameWithAChoiceWhereTheyDiffer) {
  // Storeys of glass and a wall, or glass and a balcony, all walls in one
  // house: one row kind whose frame stays, its part the choice, not a
  // choice of two whole storeys (one_frame; AlternativeLengths' street of
  // houses of one to four storeys shows where that matters).
  Grammar g;
  const std::string wall = "split(x){ ~1 : I(wall) | ~3 : I(glass) }";
  const std::string balcony = "split(x){ ~1 : I(balcony) | ~3 : I(glass) }";
  auto storeys = [](const std::vector<std::string>& kinds) {
    std::string text = "split(z){";
    for (std::size_t i = 0; i < kinds.size(); ++i) text += std::string(i ? " |" : "") + " ~3 : " + kinds[i];
    return text + " }";
  };
  const auto roots = examples(g, {storeys({wall, wall, wall}), storeys({balcony, wall, wall, balcony})});
  const NodeId merged = merge_examples(g, roots, test::uniform_merge());
  ASSERT_TRUE(std::holds_alternative<Repeat>(g.op(merged))) << g.op(merged).index();
  const auto* frame = std::get_if<Split>(&g.op(repeat_at(g, merged).child));
  ASSERT_NE(frame, nullptr);
  ASSERT_EQ(frame->parts.size(), 2u);
  EXPECT_TRUE(std::holds_alternative<Choose>(g.op(frame->parts[0].child)));
}

}  // namespace
}  // namespace vern
