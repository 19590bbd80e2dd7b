// Merging example graphs (thesis chapter 10) and writing the result as
// named rules (chapter 11).
#include "inverse/merge/merge.hpp"

#include <gtest/gtest.h>

#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "inverse/write/rule_naming.hpp"
#include "support/example_graphs.hpp"

namespace vern {
namespace {

// Each text one example's graph (support/example_graphs.hpp).
constexpr auto examples = test::example_graphs;

// The thesis's min-max ranges, which these tests of unification read off.
const MergeOptions kUniform = test::uniform_merge();

const std::string kHouse = "split(z){ ~6 : I(rect) | ~3 : I(triangle) }";

std::string right_garage(double height) {
  return "split(x){ ~6 : " + kHouse + " | ~3 : split(z){ ~" + std::to_string(height) + " : I(rect) | ~" +
         std::to_string(9 - height) + " : nil } }";
}

// A placed group (split_graph.hpp): a panel resized past its piece into
// the next, and a column of three equal tiles. Beside it columns of one
// structure vary (of two widths: two as wide would be a run of two
// tiles), so the building varies; the group keeps its own
// split, which check derives as one, not flattened into the building's,
// and its tiles stay three (repeatN, as simplifying writes equal parts),
// not a stretching repeat.
TEST(Merge, APlacedGroupIsCopiedAsItIsBesideWhatVaries) {
  Grammar g;
  const std::string group =
      "split(x){ ~1 : S(~2, ~1, ~1){ I(a) } | ~1 : nil | ~1 : split(z){ ~1 : I(d) | ~1 : I(d) | ~1 : I(d) } }";
  const auto roots = examples(g, {"split(x){ ~3 : " + group + " | ~1 : split(z){ ~1 : I(b) | ~2 : I(c) } | ~1.5 : split(z){ ~2 : I(b) | ~1 : I(c) } }",
                                  "split(x){ ~3 : " + group + " | ~1 : split(z){ ~1 : I(b) | ~1 : I(c) } }"});
  MergeOptions options = kUniform;
  options.placed = {std::get<Split>(g.op(roots[0])).parts[0].child};
  const std::string written = write_grammar(rules_for(g, merge_examples(g, roots, options)));
  EXPECT_NE(written.find("--> split(x){\n    ~1 : S(~2, ~1, ~1){ I(a) } |\n    ~1 : nil |\n    ~1 : repeatN(z, 3){ I(d) } }"),
            std::string::npos)
      << written;
}

TEST(Merge, IdenticalExamplesAreOneGraph) {
  Grammar g;
  const auto roots = examples(g, {right_garage(3), right_garage(3)});
  EXPECT_EQ(roots[0], roots[1]);
  EXPECT_EQ(merge_examples(g, roots, {}), roots[0]);
}

TEST(Merge, EqualStructuresMergeSizesIntoRangesAnywhereAndShapesStayAlternatives) {
  Grammar g;
  const auto roots = examples(g, {right_garage(3), right_garage(3.5),
                                  "split(x){ ~3 : split(z){ ~3.25 : I(rect) | ~5.75 : nil } | ~6 : " + kHouse + " }"});
  const NodeId merged = merge_examples(g, roots, kUniform);
  const auto* choose = std::get_if<Choose>(&g.op(merged));
  ASSERT_NE(choose, nullptr);
  ASSERT_EQ(choose->options.size(), 2u);
  EXPECT_EQ(choose->options[0].priority.literal(), 2.0);  // two examples have the garage on the right
  EXPECT_EQ(choose->options[1].priority.literal(), 1.0);
  const auto& right = std::get<Split>(g.op(choose->options[0].child));
  const auto& left = std::get<Split>(g.op(choose->options[1].child));
  // The garages of both sides have one structure: one node, one range.
  EXPECT_EQ(right.parts[1].child, left.parts[0].child);
  const auto& garage = std::get<Split>(g.op(right.parts[1].child));
  EXPECT_EQ(garage.parts[0].size.value, Expr::call(Function::Rand, {Expr::number(3), Expr::number(3.5)}));
  EXPECT_EQ(garage.parts[1].size.value, Expr::call(Function::Rand, {Expr::number(5.5), Expr::number(6)}));
  // The house is the same node in both alternatives, its sizes exact.
  EXPECT_EQ(right.parts[0].child, left.parts[1].child);
  EXPECT_EQ(std::get<Split>(g.op(right.parts[0].child)).parts[0].size.value, Expr::number(6));
}

TEST(Merge, ParentsOfUnifiedChildrenUnifyInTurn) {
  // Two towers of different heights inside two blocks of different widths:
  // the towers unify, so the blocks have one structure and unify too.
  Grammar g;
  const auto roots = examples(g, {"split(x){ ~2 : split(z){ ~5 : I(rect) | ~1 : nil } | ~3 : nil }",
                                  "split(x){ ~4 : split(z){ ~2 : I(rect) | ~4 : nil } | ~1 : nil }"});
  const NodeId merged = merge_examples(g, roots, kUniform);
  const auto& block = std::get<Split>(g.op(merged));
  EXPECT_EQ(block.parts[0].size.value, Expr::call(Function::Rand, {Expr::number(2), Expr::number(4)}));
  const auto& tower = std::get<Split>(g.op(block.parts[0].child));
  EXPECT_EQ(tower.parts[0].size.value, Expr::call(Function::Rand, {Expr::number(2), Expr::number(5)}));
}

TEST(Merge, RunsOfEqualPartsBecomeRepeatsThatStretch) {
  Grammar g;
  const auto roots = examples(g, {"split(x){ ~0.5 : I(wall) | ~2 : I(window) | ~2 : I(window) | ~2 : I(window) | ~0.5 : I(wall) }"});
  const NodeId merged = merge_examples(g, roots, {});
  const auto& s = std::get<Split>(g.op(merged));
  ASSERT_EQ(s.parts.size(), 3u);
  EXPECT_EQ(s.parts[1].size.value.literal(), 6.0);
  // repeat(x, 2.01): a size just above the tile, so the 6 m part makes 3
  // tiles and a wider one more.
  const auto& rep = std::get<Repeat>(g.op(s.parts[1].child));
  EXPECT_GT(*rep.size.literal(), 2.0);
  EXPECT_LE(*rep.size.literal(), 2.02);
  EXPECT_EQ(g.label(std::get<Primitive>(g.op(rep.child)).label), "window");
}

TEST(Merge, RowsOfDifferentLengthsShareOneStretchingRepeat) {
  // Facades of 3, 4 and 6 windows between 0.5 m walls: one structure, the
  // walls absolute, the windows a repeat whose count follows the width.
  Grammar g;
  auto facade = [](int windows) {
    std::string t = "split(x){ ~0.5 : I(wall)";
    for (int i = 0; i < windows; ++i) t += " | ~2 : I(window)";
    return t + " | ~0.5 : I(wall) }";
  };
  const NodeId merged = merge_examples(g, examples(g, {facade(3), facade(4), facade(6)}), {});
  const auto& s = std::get<Split>(g.op(merged));
  ASSERT_EQ(s.parts.size(), 3u);
  EXPECT_EQ(s.parts[0].size.value.literal(), 0.5);
  EXPECT_FALSE(s.parts[0].size.relative);
  EXPECT_TRUE(s.parts[1].size.relative);
  EXPECT_FALSE(s.parts[2].size.relative);
  EXPECT_NE(std::get_if<Repeat>(&g.op(s.parts[1].child)), nullptr);
}

TEST(Merge, OneStoreyAboveAGroundFloorIsTheStoreysOfTallerHouses) {
  // A shop with one storey above it, and shops with two and three: the
  // storeys are a repeat in the taller ones, and the one storey, which a
  // tile size of theirs would make one tile of, is that repeat too. One
  // structure, not an alternative for the house of one storey. Each
  // example's storey has its own window width: kinds, not sizes, match.
  Grammar g;
  auto storey = [](double window) {
    return "split(x){ ~1 : I(wall) | ~" + std::to_string(window) + " : I(window) | ~1 : I(wall) }";
  };
  auto house = [&](int storeys, double height, double window) {
    std::string t = "split(z){ ~3.5 : I(shop)";
    for (int i = 0; i < storeys; ++i) t += " | ~" + std::to_string(height) + " : " + storey(window);
    return t + " }";
  };
  const NodeId merged =
      merge_examples(g, examples(g, {house(1, 2.8, 1.2), house(2, 2.4, 1.3), house(3, 2.7, 1.1)}), {});
  const auto* s = std::get_if<Split>(&g.op(merged));
  ASSERT_NE(s, nullptr) << write_operation(g, merged, {});
  ASSERT_EQ(s->parts.size(), 2u) << write_operation(g, merged, {});
  EXPECT_NE(std::get_if<Repeat>(&g.op(s->parts[1].child)), nullptr) << write_operation(g, merged, {});
}

TEST(Merge, WholeRunBecomesTheRepeatItself) {
  Grammar g;
  const auto roots = examples(g, {"split(z){ ~3 : I(floor) | ~3 : I(floor) | ~3 : I(floor) }"});
  const NodeId merged = merge_examples(g, roots, {});
  const auto* rep = std::get_if<Repeat>(&g.op(merged));
  ASSERT_NE(rep, nullptr);
  EXPECT_GT(*rep->size.literal(), 3.0);
  EXPECT_LT(*rep->size.literal(), 3.03);
}

TEST(Merge, VaryingSizesGetTheDistributionTheirValuesFit) {
  // Garage heights that take three values, each in several examples: a
  // choice of them; with uniform distributions, the min-max range.
  Grammar g;
  std::vector<std::string> texts;
  for (const double h : {3.0, 3.5, 4.0, 3.0, 3.5, 4.0, 3.0, 3.5}) texts.push_back(right_garage(h));
  const auto roots = examples(g, texts);
  auto garage_height = [&](const MergeOptions& o) {
    const NodeId merged = merge_examples(g, roots, o);
    return std::get<Split>(g.op(std::get<Split>(g.op(merged)).parts[1].child)).parts[0].size.value;
  };
  EXPECT_EQ(garage_height({}), Expr::call(Function::Choice, {Expr::number(3), Expr::number(3.5), Expr::number(4)}));
  EXPECT_EQ(garage_height(kUniform), Expr::call(Function::Rand, {Expr::number(3), Expr::number(4)}));
}

TEST(Merge, NestedSplitsAlongOneAxisAreFlattened) {
  Grammar g;
  const auto roots = examples(g, {"split(x){ ~2 : I(a) | ~6 : split(x){ ~1 : I(b) | ~2 : I(c) } | 3 : split(y){ ~1 : I(d) | ~1 : I(e) } }"});
  const auto& s = std::get<Split>(g.op(merge_examples(g, roots, {})));
  ASSERT_EQ(s.parts.size(), 4u);
  EXPECT_EQ(s.parts[1].size.value.literal(), 2.0);
  EXPECT_EQ(s.parts[2].size.value.literal(), 4.0);
  EXPECT_TRUE(s.parts[2].size.relative);
  EXPECT_EQ(g.label(std::get<Primitive>(g.op(s.parts[2].child)).label), "c");
  EXPECT_NE(std::get_if<Split>(&g.op(s.parts[3].child)), nullptr);  // along y: kept
}

TEST(Merge, PlacesThatCombineFreelyBecomeChoicesAndCoupledOnesStay) {
  // Rows of three cells over three examples: nine distinct fillings of
  // cells holding a, b or c: free combination, each cell a choice.
  Grammar g;
  std::vector<std::string> rows;
  const char* fill[][3] = {{"a", "b", "c"}, {"b", "a", "a"}, {"c", "c", "b"}, {"a", "a", "b"}, {"b", "c", "a"},
                           {"c", "b", "b"}, {"a", "c", "c"}, {"b", "b", "c"}, {"c", "a", "a"}};
  for (int e = 0; e < 3; ++e) {
    std::string t = "split(y)";
    t += "{";
    for (int r = 0; r < 3; ++r) {
      const auto* f = fill[3 * e + r];
      t += std::string(r ? " | " : " ") + "~1 : split(x){ ~1 : I(" + f[0] + ") | ~1 : I(" + f[1] + ") | ~1 : I(" + f[2] + ") }";
    }
    rows.push_back(t + " }");
  }
  const NodeId free_rows = merge_examples(g, examples(g, rows), {});
  // Each cell saw a, b and c: one choice, so a row is three of it, and
  // each example is three of that row. The rows of an example may trade
  // places: each label is in two rows or more, or, in the third example,
  // where b is in one row only, in two rows of the others (RowsSeen).
  // So every example is the tiles of one stretching repeat(y, ~1) of the
  // one row, repeatN(x, 3){ choice }.
  const auto* stretching = std::get_if<Repeat>(&g.op(free_rows));
  ASSERT_NE(stretching, nullptr);
  ASSERT_TRUE(stretching->size.literal().has_value());
  EXPECT_GT(*stretching->size.literal(), 1.0);  // three tiles on the examples' 3 units
  EXPECT_LT(*stretching->size.literal(), 1.5);
  const auto* row = std::get_if<RepeatN>(&g.op(stretching->child));
  ASSERT_NE(row, nullptr);
  const auto* cell = std::get_if<Choose>(&g.op(row->child));
  ASSERT_NE(cell, nullptr);
  ASSERT_EQ(cell->options.size(), 3u);
  for (const auto& o : cell->options) EXPECT_EQ(o.priority.literal(), 9.0);

  // A roof end is two gable halves or two hip corners: two fillings of two
  // places with two alternatives each stay two alternatives, never mixed.
  Grammar h;
  const NodeId ends = merge_examples(
      h, examples(h, {"split(y){ ~1 : I(half_gable) | ~1 : I(other_half) }", "split(y){ ~1 : I(corner) | ~1 : I(other_corner) }"}),
      {});
  const auto& choose = std::get<Choose>(h.op(ends));
  ASSERT_EQ(choose.options.size(), 2u);
  for (const auto& o : choose.options) {
    const auto& s = std::get<Split>(h.op(o.child));
    for (const auto& p : s.parts) EXPECT_NE(std::get_if<Primitive>(&h.op(p.child)), nullptr);
  }
}

TEST(Merge, SizesWithinToleranceAreOneSize) {
  Grammar g;
  const auto roots = examples(g, {right_garage(3), right_garage(3 + 1e-12)});
  MergeOptions o;
  o.tolerance = 1e-9;
  const NodeId merged = merge_examples(g, roots, o);
  const auto& split = std::get<Split>(g.op(merged));
  const auto& garage = std::get<Split>(g.op(split.parts[1].child));
  EXPECT_TRUE(garage.parts[0].size.value.literal().has_value());
}

TEST(RuleNaming, RulesOnlyWhereSharedOrChosenWithNamesFromTheirParts) {
  Grammar g;
  const auto roots = examples(g, {right_garage(3), right_garage(3.5),
                                  "split(x){ ~3 : split(z){ ~3.25 : I(rect) | ~5.75 : nil } | ~6 : " + kHouse + " }"});
  const NodeId merged = merge_examples(g, roots, kUniform);
  const Grammar named = rules_for(g, merged);
  EXPECT_EQ(write_grammar(named),
            "building --> split(x){ ~6 : rectTriangleZ | ~3 : rectZ } : 2\n"
            "building --> split(x){ ~3 : rectZ | ~6 : rectTriangleZ }\n"
            "rectTriangleZ --> split(z){ ~6 : I(rect) | ~3 : I(triangle) }\n"
            "rectZ --> split(z){ ~rand(3, 3.5) : I(rect) | ~rand(5.5, 6) : nil }\n");
}

}  // namespace
}  // namespace vern
