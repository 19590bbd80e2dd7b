// Folding runs of equal parts and repeating patterns into stretching
// repeats, on examples' split graphs.
#include "inverse/merge/repeat_folding.hpp"

#include <gtest/gtest.h>

#include "forward/derive.hpp"
#include "graph/nodes_below.hpp"
#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "inverse/check/check.hpp"
#include "inverse/infer.hpp"
#include "support/derive_helpers.hpp"
#include "support/example_helpers.hpp"
#include "support/one_line.hpp"

namespace vern {
namespace {

// A grammar's text on one line (support/one_line.hpp).
constexpr auto flat = test::one_line;

// Folds the start rule's body of a grammar text; returns the result written.
std::string folded(const std::string& text, double tolerance = 1e-6) {
  Grammar g = parse_grammar(text);
  g.rules[0].body = fold_repeats(g, g.rules[0].body, tolerance);
  return flat(write_grammar(g));
}

// The tile sizes written are the shortest decimals just above the tiles
// (3.02 for 3 tiles of 3): a size of exactly 3 would make a fourth tile
// once rounding lengthens the row by a hair.
TEST(RepeatFolding, APeriodicRowBecomesARepeatedTile) {
  const std::string out = folded("a --> split(x){ ~1 : I(rect) | ~2 : I(window) | ~1 : I(rect) | ~2 : I(window) | ~1 : I(rect) | ~2 : I(window) }\n");
  EXPECT_NE(out.find("a --> repeat(x, 3.02){ split(x){ ~1 : I(rect) | ~2 : I(window) } }"), std::string::npos) << out;
}

TEST(RepeatFolding, EndWallsStayAroundTheRun) {
  const std::string out =
      folded("a --> split(x){ ~0.5 : I(wall) | ~2 : I(window) | ~2 : I(window) | ~2 : I(window) | ~0.5 : I(wall) }\n");
  EXPECT_NE(out.find("split(x){ ~0.5 : I(wall) | ~6 : repeat(x, 2.01){ I(window) } | ~0.5 : I(wall) }"), std::string::npos)
      << out;
}

TEST(RepeatFolding, WallWindowWallIsATileAndAWall) {
  const std::string out =
      folded("a --> split(x){ ~1 : I(wall) | ~2 : I(window) | ~1 : I(wall) | ~2 : I(window) | ~1 : I(wall) }\n");
  EXPECT_NE(out.find("~6 : repeat(x, 3.02){ split(x){ ~1 : I(wall) | ~2 : I(window) } } | ~1 : I(wall)"), std::string::npos)
      << out;
}

TEST(RepeatFolding, AMixedRowIsLeftForMerging) {
  const std::string text = "a --> split(x){ ~1 : I(a) | ~1 : I(b) | ~1 : I(c) | ~1 : I(c) | ~1 : I(a) | ~1 : I(b) }\n";
  EXPECT_EQ(folded(text), flat(write_grammar(parse_grammar(text))));
}

TEST(RepeatFolding, RunsOfOneBarePartEitherSideOfADoorAreRepeats) {
  // Walls of one length, three before a door and two after: each run a
  // repeat of the wall (a wider side gets more walls), the door between.
  const std::string out = folded(
      "a --> split(x){ ~2 : I(wall) | ~2 : I(wall) | ~2 : I(wall) | ~1.6 : I(door) | ~2 : I(wall) | "
      "~2 : I(wall) }\n");
  EXPECT_NE(out.find("split(x){ ~6 : repeat(x, 2.01){ I(wall) } | ~1.6 : I(door) | "
                     "~4 : repeat(x, 2.01){ I(wall) } }"),
            std::string::npos)
      << out;
  // Walls of two lengths are no one run of walls; nor are walls beside a
  // door as wide as a wall (a row of unlike tiles, for merging).
  for (const std::string& text :
       {std::string("a --> split(x){ ~2.2 : I(wall) | ~2.2 : I(wall) | ~1.6 : I(door) | ~2.5 : I(wall) | "
                    "~2.5 : I(wall) }\n"),
        std::string("a --> split(x){ ~2.2 : I(wall) | ~2.2 : I(wall) | ~2.2 : I(door) | ~2.2 : I(wall) | "
                    "~2.2 : I(wall) }\n")})
    EXPECT_EQ(folded(text), flat(write_grammar(parse_grammar(text))));
}

TEST(RepeatFolding, WallBaysEitherSideOfADoorInferAsOneRepeatWhateverTheirCount) {
  // Two to four bare walls each side of a door, as many as a 2.5 m tile
  // fits: each side one repeat of a wall, not an alternative per count
  // (a fixed three, and pairs of walls for two and four).
  const Grammar source = parse_grammar(
      "@scope rand(10, 20), 1, 4\n"
      "front --> split(x){ ~1 : repeat(x, 2.5){ I(wall) } | 1.6 : I(door) | ~1 : repeat(x, 2.5){ I(wall) } }\n");
  const Inference inferred = infer(test::derived_examples(source, 10), {});
  const std::string text = write_grammar(inferred.grammar);
  EXPECT_EQ(text.find("repeatN"), std::string::npos) << text;
  EXPECT_EQ(text.find("building -->"), text.rfind("building -->")) << text;  // one alternative
  EXPECT_TRUE(test::source_derives_variants(source, inferred.grammar, 1001, 1030));
}

TEST(RepeatFolding, AStoreyAloneIsARepeatWhereAnotherRowFoldsItsKind) {
  // Above a ground floor, two storeys fold (the storeys' zone); one
  // storey alone folds only once some row has folded storeys of its kind
  // (sizes aside), and only where a tile size that makes that row's
  // count makes one tile of it: 2 * 2.4 m = 4.8 m at most here.
  auto storey = [](double window) {
    return "split(x){ ~1 : I(wall) | ~" + std::to_string(window) + " : I(window) | ~1 : I(wall) }";
  };
  auto house = [&](std::vector<double> heights, double window) {
    std::string t = "split(z){ ~3.5 : I(shop)";
    for (const double h : heights) t += " | ~" + std::to_string(h) + " : " + storey(window);
    return t + " }\n";
  };
  Grammar g = parse_grammar("two --> " + house({2.4, 2.4}, 1.3) + "one --> " + house({2.8}, 1.2) +
                            "tall --> " + house({5}, 1.2));
  RowsSeen seen;
  const NodeId alone = fold_repeats(g, g.rules[1].body, 1e-6, UnlikeTiles::Fold, nullptr, nullptr, &seen);
  EXPECT_EQ(write_operation(g, alone, {}).find("repeat"), std::string::npos) << write_operation(g, alone, {});
  EXPECT_EQ(seen.lone_tiles.size(), 1u);
  const NodeId two = fold_repeats(g, g.rules[0].body, 1e-6, UnlikeTiles::Fold, nullptr, nullptr, &seen);
  ASSERT_NE(write_operation(g, two, {}).find("repeat(z"), std::string::npos) << write_operation(g, two, {});
  const NodeId one = fold_repeats(g, g.rules[1].body, 1e-6, UnlikeTiles::Fold, nullptr, nullptr, &seen);
  EXPECT_NE(flat(write_operation(g, one, {})).find("~2.8 : repeat(z, 2.81){ split(x){"), std::string::npos)
      << write_operation(g, one, {});
  const NodeId tall = fold_repeats(g, g.rules[2].body, 1e-6, UnlikeTiles::Fold, nullptr, nullptr, &seen);
  EXPECT_EQ(write_operation(g, tall, {}).find("repeat"), std::string::npos) << write_operation(g, tall, {});
}

TEST(RepeatFolding, TwoUnlikeStoreysBetweenAGroundFloorAndARoofAreTiles) {
  // Two storeys of one height above a shop, each holding its own bays
  // (blinds and panes in turn, the other way round in the other): tiles,
  // as two equal storeys are, since what they hold trades places; a
  // third storey would make them tiles of unlike contents anyway.
  auto storey = [](const std::string& a, const std::string& b) {
    return "split(x){ ~1 : I(" + a + ") | ~1 : I(" + b + ") | ~1 : I(" + a + ") }";
  };
  const std::string two = "split(z){ ~4 : I(shop) | ~3 : " + storey("blind", "pane") + " | ~3 : " +
                          storey("pane", "blind") + " | ~2 : I(roof) }";
  Grammar g = parse_grammar("a --> " + two + "\n");
  const NodeId folded_row = fold_repeats(g, g.rules[0].body, 1e-6, UnlikeTiles::Fold);
  const auto* s = std::get_if<Split>(&g.op(folded_row));
  ASSERT_NE(s, nullptr);
  ASSERT_EQ(s->parts.size(), 3u) << write_operation(g, folded_row, {});
  const auto* tiles = std::get_if<Repeat>(&g.op(s->parts[1].child));
  ASSERT_NE(tiles, nullptr) << write_operation(g, folded_row, {});
  EXPECT_NE(std::get_if<Choose>(&g.op(tiles->child)), nullptr);
  // A storey beside a bare part as high is no pair; nor are two storeys
  // beside a third part as high (a longer row of unlike tiles), nor two
  // storeys one of which holds a label the other never trades for.
  for (const std::string& text :
       {"a --> split(z){ ~4 : I(shop) | ~3 : " + storey("blind", "pane") + " | ~3 : I(attic) | ~2 : I(roof) }\n",
        "a --> split(z){ ~3 : I(shop) | ~3 : " + storey("blind", "pane") + " | ~3 : " + storey("pane", "blind") +
            " | ~2 : I(roof) }\n",
        "a --> split(z){ ~4 : I(shop) | ~3 : " + storey("blind", "pane") + " | ~3 : " + storey("pane", "door") +
            " | ~2 : I(roof) }\n"})
    EXPECT_EQ(folded(text), flat(write_grammar(parse_grammar(text)))) << text;
}

TEST(RepeatFolding, StoreysBetweenAGroundFloorAndARoofAreARepeat) {
  // A ground floor below, a cornice and a roof above: the storeys between
  // are tiles however many there are, two as well as three, so that houses
  // of two, three and four storeys share one structure.
  const std::string storey = "~3.2 : split(x){ ~1 : I(wall) | ~1 : I(window) }";
  for (const int count : {2, 3, 4}) {
    std::string row = "a --> split(z){ ~4.6 : I(shop)";
    for (int i = 0; i < count; ++i) row += " | " + storey;
    row += " | ~0.7 : I(band) | ~3 : I(roof) }\n";
    const std::string out = folded(row);
    const std::string folded_storeys = " : repeat(z, 3.2";
    const std::size_t at = out.find(folded_storeys);
    ASSERT_NE(at, std::string::npos) << out;
    EXPECT_EQ(out.find(folded_storeys, at + 1), std::string::npos) << out;
    EXPECT_LT(out.find("~4.6 : I(shop) | ~"), at) << out;
    EXPECT_NE(out.find("} } | ~0.7 : I(band) | ~3 : I(roof) }", at), std::string::npos) << out;
  }
  // Two equal halves alone are a pair, not tiles.
  EXPECT_EQ(folded("a --> split(x){ ~1 : I(rect) | ~1 : I(rect) }\n").find("repeat"), std::string::npos);
  // Storeys beside one of another kind as long as they are: a mixed row,
  // left to merging (its storeys may be a repeat of a choice).
  const std::string mixed = "a --> split(z){ ~0.4 : I(slab) | ~4.5 : I(shop) | ~3 : I(flat) | ~3 : I(flat) | ~3 : I(loggia) }\n";
  EXPECT_EQ(folded(mixed).find("repeat"), std::string::npos) << folded(mixed);
}

TEST(RepeatFolding, ARowOfCompoundTilesAroundAnEntranceIsRunsAndTheEntrance) {
  // Shop bays (pier, window, pier) 4 m wide, the entrance bay (wall,
  // door, wall), then bays 3.4 m wide: each run of equal bays a repeat of
  // the bay, the entrance one group between them.
  const std::string bay4 = "~0.5 : I(rect) | ~3 : I(window) | ~0.5 : I(rect)";
  const std::string bay34 = "~0.5 : I(rect) | ~2.4 : I(window) | ~0.5 : I(rect)";
  const std::string out = folded("a --> split(x){ " + bay4 + " | ~1.2 : I(rect) | ~1.6 : I(door) | ~1.2 : I(rect) | " +
                                 bay34 + " | " + bay34 + " | " + bay34 + " }\n");
  EXPECT_NE(out.find("a --> split(x){ ~4 : repeat(x, 4.02){ split(x){ ~0.5 : I(rect) | ~3 : I(window) | ~0.5 : "
                     "I(rect) } } | ~4 : split(x){ ~1.2 : I(rect) | ~1.6 : I(door) | ~1.2 : I(rect) } | ~10.2 : "
                     "repeat(x, 3.42){ split(x){ ~0.5 : I(rect) | ~2.4 : I(window) | ~0.5 : I(rect) } } }"),
            std::string::npos)
      << out;
  // A row the pattern covers less than half of stays as it is.
  const std::string mixed = "a --> split(x){ ~1 : I(rect) | ~2 : I(window) | ~1 : I(rect) | ~2 : I(window) | "
                            "~1 : I(door) | ~1 : I(wall) | ~1 : I(roof) | ~3 : I(rect) | ~1 : I(door) }\n";
  EXPECT_EQ(folded(mixed).find("repeat"), std::string::npos) << folded(mixed);
}

TEST(RepeatFolding, BaysOfFiveOrMorePartsAroundAnEntranceAreRunsAndTheEntrance) {
  // Bays of a pier, two panes with a mullion between, and a pier: five
  // parts a bay, two bays before the entrance and three after, as a
  // random style's storeys drew them. Patterns were looked for up to four
  // parts, so the row stayed one long split in every example.
  const std::string bay = "~1.5 : I(rect) | ~0.5 : I(pane) | ~0.25 : I(mullion) | ~0.5 : I(pane) | ~1.5 : I(rect)";
  const std::string out =
      folded("a --> split(x){ " + bay + " | " + bay + " | ~1.5 : I(rect) | ~1 : I(loggia) | ~1.5 : I(rect) | " +
             bay + " | " + bay + " | " + bay + " }\n");
  const std::string tile =
      "split(x){ ~1.5 : I(rect) | ~0.5 : I(pane) | ~0.25 : I(mullion) | ~0.5 : I(pane) | ~1.5 : I(rect) }";
  EXPECT_NE(out.find("a --> split(x){ ~8.5 : repeat(x, 4.27){ " + tile +
                     " } | ~4 : split(x){ ~1.5 : I(rect) | ~1 : I(loggia) | ~1.5 : I(rect) } | ~12.75 : "
                     "repeat(x, 4.27){ " + tile + " } }"),
            std::string::npos)
      << out;
}

TEST(RepeatFolding, NoiseWithinTheToleranceFoldsAndTheResultDerivesTheSameCuts) {
  const std::string text =
      "a --> split(x){ ~2.0000001 : I(w) | ~1.9999999 : I(w) | ~2.0000002 : I(w) | ~1.9999998 : I(w) }\n";
  Grammar g = parse_grammar(text);
  g.rules[0].body = fold_repeats(g, g.rules[0].body, 1e-6);
  EXPECT_TRUE(std::holds_alternative<Repeat>(g.op(g.rules[0].body)));
  const Derivation before = test::derive_text(text, {8, 1, 1});
  DeriveOptions o;
  o.size = glm::dvec3(8, 1, 1);
  const Derivation after = derive(g, o);
  ASSERT_EQ(after.terminals.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(after.terminals[i].scope.origin.x, before.terminals[i].scope.origin.x, 1e-6);
  }
}

TEST(RepeatFolding, DifferentSizesDoNotFold) {
  const std::string text = "a --> split(x){ ~1 : I(w) | ~1.5 : I(w) | ~1 : I(w) }\n";
  EXPECT_EQ(folded(text), flat(write_grammar(parse_grammar(text))));
}

TEST(RepeatFolding, AdjacentEmptyPartsJoin) {
  const std::string out = folded("a --> split(x){ ~1 : I(a) | ~1 : nil | ~2 : nil | ~1 : I(b) }\n");
  EXPECT_NE(out.find("split(x){ ~1 : I(a) | ~3 : nil | ~1 : I(b) }"), std::string::npos) << out;
}

// Rows of unlike buildings (UnlikeTiles::Fold). A choose cannot be written
// inside an operation, so these read the folded graph.

// The start rule's body folded, in a grammar kept for reading it.
struct Folded {
  Grammar g;
  NodeId body = 0;
};
Folded fold_text(const std::string& text, UnlikeTiles unlike = UnlikeTiles::Fold) {
  Folded f{parse_grammar(text), 0};
  f.body = fold_repeats(f.g, f.g.rules[0].body, 1e-6, unlike);
  return f;
}

// A row written as "a --> split(x){ part | part | ... |" (each piece
// ending in a bar), closed and folded; the split it folds to, or null.
struct FoldedRow {
  Folded f;
  const Split* split = nullptr;
  std::string text() const { return flat(write_operation(f.g, f.body, {})); }
};
FoldedRow fold_row(std::string row) {
  row.pop_back();
  row += "}\n";
  FoldedRow out{fold_text(row)};
  out.split = std::get_if<Split>(&out.f.g.op(out.f.body));
  return out;
}

const std::string kLow = "split(z){ ~1 : I(rect) | ~3 : nil }";
const std::string kTall = "split(z){ ~3 : I(rect) | ~1 : nil }";

TEST(RepeatFolding, UnlikeBuildingsOfOneWidthBecomeARepeatOfTheirChoice) {
  const Folded f = fold_text("a --> split(x){ ~2 : " + kLow + " | ~2 : " + kTall + " | ~2 : " + kLow + " }\n");
  const auto* row = std::get_if<Repeat>(&f.g.op(f.body));
  ASSERT_NE(row, nullptr);
  ASSERT_TRUE(row->size.literal().has_value());
  EXPECT_GT(*row->size.literal(), 2.0);  // just above the tile: three tiles on 6
  EXPECT_LT(*row->size.literal(), 2.02);
  const auto* choice = std::get_if<Choose>(&f.g.op(row->child));
  ASSERT_NE(choice, nullptr);
  ASSERT_EQ(choice->options.size(), 2u);
  EXPECT_EQ(choice->options[0].priority.literal(), 2.0);  // the low building, twice
  EXPECT_EQ(choice->options[1].priority.literal(), 1.0);
  EXPECT_EQ(flat(write_operation(f.g, choice->options[1].child, {})), "split(z){ ~3 : I(rect) | ~1 : nil }");
}

TEST(RepeatFolding, BaysEachAWindowOrADoorAreARepeatOfTheirChoice) {
  // Eight bays of one width, wall | window or door | wall, the doors in
  // the second and the sixth: bays that trade places, not runs of window
  // bays between door bays (which would give every arrangement of doors
  // a structure of its own).
  std::string row = "a --> split(x){";
  for (int bay = 0; bay < 8; ++bay)
    row += std::string(bay ? " |" : "") + " ~1 : I(wall) | ~1.5 : I(" + (bay == 1 || bay == 5 ? "door" : "window") +
           ") | ~1 : I(wall)";
  row += " }\n";
  const Folded f = fold_text(row);
  const auto* bays = std::get_if<Repeat>(&f.g.op(f.body));
  ASSERT_NE(bays, nullptr) << flat(write_operation(f.g, f.body, {}));
  const auto* choice = std::get_if<Choose>(&f.g.op(bays->child));
  ASSERT_NE(choice, nullptr) << flat(write_operation(f.g, f.body, {}));
  ASSERT_EQ(choice->options.size(), 2u);
  EXPECT_EQ(choice->options[0].priority.literal(), 6.0);  // window bays
  EXPECT_EQ(choice->options[1].priority.literal(), 2.0);  // door bays
}

TEST(RepeatFolding, BaysWhoseWindowsDifferInWidthAreOneRunOfTheirChoice) {
  // An entrance bay, then five bays of one width (3.7 m), each window
  // drawn for its bay (1.05 to 1.15 m, piers taking the rest): no two bays
  // alike, yet one run of bays, a repeat of a choice of the five.
  std::string row = "a --> split(x){ ~1.3 : I(rect) | ~1.1 : I(door) | ~1.3 : I(rect)";
  for (const double w : {1.1, 1.06, 1.14, 1.08, 1.12}) {
    const std::string pier = std::to_string((3.7 - w) / 2);
    row += " | ~" + pier + " : I(rect) | ~" + std::to_string(w) + " : I(window) | ~" + pier + " : I(rect)";
  }
  row += " }\n";
  const Folded f = fold_text(row);
  const auto* s = std::get_if<Split>(&f.g.op(f.body));
  ASSERT_NE(s, nullptr) << flat(write_operation(f.g, f.body, {}));
  ASSERT_EQ(s->parts.size(), 2u) << flat(write_operation(f.g, f.body, {}));
  const auto* bays = std::get_if<Repeat>(&f.g.op(s->parts[1].child));
  ASSERT_NE(bays, nullptr) << flat(write_operation(f.g, f.body, {}));
  EXPECT_GT(*bays->size.literal(), 3.7);  // just above the bay: five bays on 18.5
  EXPECT_LT(*bays->size.literal(), 3.74);
  const auto* choice = std::get_if<Choose>(&f.g.op(bays->child));
  ASSERT_NE(choice, nullptr);
  EXPECT_EQ(choice->options.size(), 5u);
  // Read from the phase of the bays (pier, window, pier), not a part later
  // (window, pier, pier), whose occurrences differ in length.
  EXPECT_EQ(flat(write_operation(f.g, choice->options[0].child, {})).find("split(x){ ~"), 0u);
  EXPECT_NE(flat(write_operation(f.g, choice->options[0].child, {})).find("I(window) | ~"), std::string::npos);
  // One example alone comes back as it is.
  const Folded kept = fold_text(row, UnlikeTiles::Keep);
  EXPECT_EQ(flat(write_operation(kept.g, kept.body, {})).find("repeat"), std::string::npos);
}

TEST(RepeatFolding, StoreysOfBaysWithAWindowDrawnForEachBayInferAsARepeatOfBays) {
  // Every bay draws its own window width: no two bays of an example are
  // alike, and the ground floor's entrance keeps its bays from being a
  // row of unlike tiles. Without the run of alike bays the ground floor
  // came back as one long split per example.
  const Grammar source = parse_grammar(R"(
@start front
@scope rand(12, 30), 0.5, rand(7, 14)
front --> split(z){ 3.4 : ground | ~1 : repeat(z, 3.4){ repeat(x, 3.7){ bay } } }
ground --> split(x){ 3.7 : split(x){ ~1 : I(rect) | 1.6 : I(door) | ~1 : I(rect) } | ~1 : repeat(x, 3.7){ bay } }
bay --> split(x){ ~1 : I(rect) | tnormal(1.1, 0.03, 1.02, 1.18) : split(z){ 0.9 : I(rect) | ~1 : I(window) | 0.3 : I(rect) } | ~1 : I(rect) }
)",
                                       "bays.grm");
  const std::vector<Example> examples = test::derived_examples(source, 10);
  const Inference inferred = infer(examples, {});
  const std::string text = write_grammar(inferred.grammar);
  // Bays repeated, never a storey written out bay by bay: no split has
  // more parts than the door bay and a run of bays beside it.
  EXPECT_NE(text.find("repeat(x, "), std::string::npos) << text;
  const Grammar& g = inferred.grammar;
  for (const Rule& rule : g.rules)
    for (const NodeId n : nodes_below(g, rule.body)) {
      if (const auto* s = std::get_if<Split>(&g.op(n))) {
        EXPECT_LE(s->parts.size(), 4u) << text;
      }
    }
  for (const Example& e : examples) {
    const CheckResult r = check_example(inferred.grammar, e.boxes, example_size(e));
    EXPECT_TRUE(r.derivable) << r.mismatch << "\n" << text;
  }
}

TEST(RepeatFolding, OneExampleKeepsItsRowOfUnlikeBuildings) {
  const std::string text = "a --> split(x){ ~2 : " + kLow + " | ~2 : " + kTall + " | ~2 : " + kLow + " }\n";
  const Folded f = fold_text(text, UnlikeTiles::Keep);
  EXPECT_EQ(flat(write_operation(f.g, f.body, {})), flat(write_operation(f.g, f.g.rules[0].body, {})));
  EXPECT_TRUE(std::holds_alternative<Split>(f.g.op(f.body)));
}

TEST(RepeatFolding, PrimitivesOfOneWidthKeepTheirPlaces) {
  // A door between two windows is not a window: no choice of the three.
  const Folded f = fold_text("a --> split(x){ ~1 : I(window) | ~1 : I(door) | ~1 : I(window) }\n");
  EXPECT_TRUE(std::holds_alternative<Split>(f.g.op(f.body)));
}

TEST(RepeatFolding, AGroundFloorWithTheOnlyDoorStaysBelowTheStoreysWhichFold) {
  const Folded f = fold_text(
      "a --> split(z){ ~3 : split(x){ ~1 : I(door) | ~2 : I(wall) } | ~3 : split(x){ ~1 : I(window) | ~2 : I(wall) } |"
      " ~3 : split(x){ ~2 : I(wall) | ~1 : I(window) } | ~3 : split(x){ ~1 : I(window) | ~2 : I(wall) } }\n");
  const auto* house = std::get_if<Split>(&f.g.op(f.body));
  ASSERT_NE(house, nullptr);
  ASSERT_EQ(house->parts.size(), 2u);
  EXPECT_EQ(flat(write_operation(f.g, house->parts[0].child, {})), "split(x){ ~1 : I(door) | ~2 : I(wall) }");
  EXPECT_EQ(house->parts[1].size.value.literal(), 9.0);
  const auto* storeys = std::get_if<Repeat>(&f.g.op(house->parts[1].child));
  ASSERT_NE(storeys, nullptr);
  const auto* choice = std::get_if<Choose>(&f.g.op(storeys->child));
  ASSERT_NE(choice, nullptr);
  EXPECT_EQ(choice->options.size(), 2u);  // window left (twice) or right
}

TEST(RepeatFolding, APlotOfSeveralStripsIsOneTile) {
  // Three plots of 3: a low building, a cluster of three tower strips, a
  // tall building. The strips' cuts are no plot boundaries.
  const Folded f = fold_text("a --> split(x){ ~3 : " + kLow + " | ~1 : " + kTall + " | ~1 : " + kLow + " | ~1 : " + kTall +
                             " | ~3 : " + kTall + " }\n");
  const auto* row = std::get_if<Repeat>(&f.g.op(f.body));
  ASSERT_NE(row, nullptr);
  const auto* choice = std::get_if<Choose>(&f.g.op(row->child));
  ASSERT_NE(choice, nullptr);
  ASSERT_EQ(choice->options.size(), 3u);
  // The cluster's three strips are a row of unlike towers in turn.
  const auto* cluster = std::get_if<Repeat>(&f.g.op(choice->options[1].child));
  ASSERT_NE(cluster, nullptr);
  ASSERT_TRUE(cluster->size.literal().has_value());
  EXPECT_GT(*cluster->size.literal(), 1.0);
  EXPECT_LE(*cluster->size.literal(), 1.01);  // at most a percent above
  const auto* towers = std::get_if<Choose>(&f.g.op(cluster->child));
  ASSERT_NE(towers, nullptr);
  EXPECT_EQ(towers->options.size(), 2u);
}

// A rule of a row of bays (wall | opening | wall), 3 m each, holding the
// given openings in order.
std::string bays(std::initializer_list<const char*> openings, const std::string& rule = "a") {
  std::string row = rule + " --> split(x){";
  bool first = true;
  for (const char* o : openings) {
    row += std::string(first ? "" : " |") + " ~1 : I(wall) | ~1 : " + o + " | ~1 : I(wall)";
    first = false;
  }
  return row + " }\n";
}
const char* const kWindow = "I(window)";
const char* const kBalcony = "split(z){ ~1 : I(balcony) | ~2 : I(window) }";

TEST(RepeatFolding, AnOddBayBeforeARunIsATileWhereOtherRowsShowItTradingPlaces) {
  // A balcony bay before three window bays: alone in its row, it keeps its
  // place where nothing else is known; where another row showed balcony
  // bays trading places with window bays (two of them), the row is four
  // tiles of their choice, not a run of window bays read a wall late.
  const std::string alone = bays({kBalcony, kWindow, kWindow, kWindow}, "b");
  Folded unknown = fold_text(alone);
  EXPECT_EQ(std::get_if<Repeat>(&unknown.g.op(unknown.body)), nullptr) << flat(write_operation(unknown.g, unknown.body, {}));

  Grammar g = parse_grammar(bays({kWindow, kBalcony, kWindow, kBalcony, kBalcony}) + alone);
  RowsSeen trading;
  const NodeId other = fold_repeats(g, g.rules[0].body, 1e-6, UnlikeTiles::Fold, nullptr, nullptr, &trading);
  ASSERT_NE(std::get_if<Repeat>(&g.op(other)), nullptr);
  EXPECT_EQ(trading.seen.count(g.find_label("balcony").value()), 1u);
  const NodeId row = fold_repeats(g, g.rules[1].body, 1e-6, UnlikeTiles::Fold, nullptr, nullptr, &trading);
  const auto* tiles = std::get_if<Repeat>(&g.op(row));
  ASSERT_NE(tiles, nullptr) << flat(write_operation(g, row, {}));
  const auto* choice = std::get_if<Choose>(&g.op(tiles->child));
  ASSERT_NE(choice, nullptr);
  ASSERT_EQ(choice->options.size(), 2u);
  EXPECT_EQ(choice->options[0].priority.literal(), 1.0);  // the balcony bay
  EXPECT_EQ(choice->options[1].priority.literal(), 3.0);  // window bays
}

TEST(RepeatFolding, AlternatingBaysAreARunOfPairsUnlessOtherRowsShowThemTradingPlaces) {
  // Window, balcony, window, balcony: a pattern of pairs as far as this
  // row shows; four tiles of a free choice once another row mixed them in
  // no pattern.
  const std::string pairs = bays({kWindow, kBalcony, kWindow, kBalcony}, "b");
  Folded alone = fold_text(pairs);
  const auto* run = std::get_if<Repeat>(&alone.g.op(alone.body));
  ASSERT_NE(run, nullptr);
  EXPECT_TRUE(std::holds_alternative<Split>(alone.g.op(run->child)));  // the pair

  Grammar g = parse_grammar(bays({kWindow, kBalcony, kBalcony, kWindow, kWindow}) + pairs);
  RowsSeen trading;
  fold_repeats(g, g.rules[0].body, 1e-6, UnlikeTiles::Fold, nullptr, nullptr, &trading);
  const NodeId row = fold_repeats(g, g.rules[1].body, 1e-6, UnlikeTiles::Fold, nullptr, nullptr, &trading);
  const auto* tiles = std::get_if<Repeat>(&g.op(row));
  ASSERT_NE(tiles, nullptr);
  const auto* choice = std::get_if<Choose>(&g.op(tiles->child));
  ASSERT_NE(choice, nullptr) << flat(write_operation(g, row, {}));
  EXPECT_EQ(choice->options.size(), 2u);
}

TEST(RepeatFolding, BaysOfTwoKindsAroundAnOddBayAreRunsOfTheirChoiceAndTheOddBay) {
  // Bays each a balcony or a window bay, their openings drawn bay by bay
  // (no two alike), a bay of paired windows third, and the bays after it
  // a little wider (the rest of the row shared out): runs of pieces of one
  // length, each a repeat of a choice of its bays, around the odd bay.
  auto bay = [](double wall, double opening, bool balcony) {
    return " ~" + std::to_string(wall) + " : I(rect) | ~" + std::to_string(opening) + " : " +
           (balcony ? "split(z){ ~1 : I(balcony) | ~2 : I(pane) }" : "split(z){ ~2 : I(rect) | ~4 : I(pane) | ~1 : I(rect) }") +
           " | ~" + std::to_string(wall) + " : I(rect) |";
  };
  std::string row = "a --> split(x){" + bay(0.95, 1.9, true) + bay(0.9, 2.0, false) +
                    " ~0.9 : I(rect) | ~0.8 : I(pane) | ~0.4 : I(rect) | ~0.8 : I(pane) | ~0.9 : I(rect) |" +
                    bay(1.0, 1.9, true) + bay(0.95, 2.0, false) + bay(1.0, 1.9, true);
  const FoldedRow folded = fold_row(row);
  const Folded& f = folded.f;
  const Split* s = folded.split;
  ASSERT_NE(s, nullptr);
  ASSERT_EQ(s->parts.size(), 3u);
  for (const std::size_t run : {0u, 2u}) {
    const auto* tiles = std::get_if<Repeat>(&f.g.op(s->parts[run].child));
    ASSERT_NE(tiles, nullptr) << run;
    const auto* choice = std::get_if<Choose>(&f.g.op(tiles->child));
    ASSERT_NE(choice, nullptr) << run;
    ASSERT_EQ(choice->options.size(), 2u) << run;
    EXPECT_EQ(choice->options[0].priority.literal(), run == 0 ? 1.0 : 2.0);  // the balcony bays
  }
  EXPECT_DOUBLE_EQ(*s->parts[0].size.value.literal(), 7.6);  // two bays of 3.8
  const auto* pair = std::get_if<Split>(&f.g.op(s->parts[1].child));
  ASSERT_NE(pair, nullptr);
  EXPECT_EQ(pair->parts.size(), 5u);
}

TEST(RepeatFolding, ABayBeforeADoorAsWideAsTheBaysIsARunOfOne) {
  // A bay of panes, then a door as wide as a bay, then bays of panes or
  // panels drawn bay by bay (their sizes differing a little, as the rest
  // of the row is shared out): the bay before the door is a run of one
  // tile, as two bays before it would be a run of two, so that rows with
  // the door after none, one or two bays are one structure; the door
  // keeps its place (a bare primitive is never a tile).
  auto bay = [](double wall, const char* opening) {
    return " ~" + std::to_string(wall) + " : I(wall) | ~" + std::to_string(1.3 * wall) + " : I(" + opening +
           ") | ~" + std::to_string(wall) + " : I(wall) |";
  };
  std::string row = "a --> split(x){" + bay(1, "pane") + " ~3.3 : I(door) |" + bay(0.95, "pane") +
                    bay(0.95, "panel") + bay(0.95, "panel") + bay(0.95, "pane");
  const FoldedRow folded = fold_row(row);
  const Folded& f = folded.f;
  const Split* s = folded.split;
  ASSERT_NE(s, nullptr) << folded.text();
  ASSERT_EQ(s->parts.size(), 3u) << flat(write_operation(f.g, f.body, {}));
  const auto* one = std::get_if<Repeat>(&f.g.op(s->parts[0].child));
  ASSERT_NE(one, nullptr) << flat(write_operation(f.g, f.body, {}));
  EXPECT_TRUE(std::holds_alternative<Primitive>(f.g.op(s->parts[1].child)));
  const auto* after = std::get_if<Repeat>(&f.g.op(s->parts[2].child));
  ASSERT_NE(after, nullptr);
  EXPECT_TRUE(std::holds_alternative<Choose>(f.g.op(after->child)));
}

TEST(RepeatFolding, BaysTakenTwoByTwoGiveWayToTheBaysThemselves) {
  // Balcony and window bays, a door one box as wide as a bay after the
  // third, the bays after it a little wider: pieces of two bays reach
  // further (the third bay and the door are as long as two bays) but
  // each is two pieces of one bay, so the bays are the tiles: a run of
  // three before the door, the door, a run of three after it.
  auto bay = [](double width, bool balcony) {
    const double wall = width / 4;
    return " ~" + std::to_string(wall) + " : I(wall) | ~" + std::to_string(2 * wall) + " : " +
           (balcony ? "split(z){ ~1 : I(balcony) | ~2 : I(pane) }" : "split(z){ ~1 : I(wall) | ~2 : I(pane) }") + " | ~" +
           std::to_string(wall) + " : I(wall) |";
  };
  std::string row = "a --> split(x){" + bay(3.8, true) + bay(3.8, false) + bay(3.8, true) + " ~3.8 : I(door) |" +
                    bay(3.9, false) + bay(3.9, true) + bay(3.9, false);
  const FoldedRow folded = fold_row(row);
  const Folded& f = folded.f;
  const Split* s = folded.split;
  ASSERT_NE(s, nullptr) << folded.text();
  ASSERT_EQ(s->parts.size(), 3u) << flat(write_operation(f.g, f.body, {}));
  for (const std::size_t run : {0u, 2u}) {
    const auto* tiles = std::get_if<Repeat>(&f.g.op(s->parts[run].child));
    ASSERT_NE(tiles, nullptr) << run;
    EXPECT_TRUE(std::holds_alternative<Choose>(f.g.op(tiles->child))) << run;
  }
  EXPECT_NEAR(*s->parts[0].size.value.literal(), 11.4, 1e-9);
  EXPECT_TRUE(std::holds_alternative<Primitive>(f.g.op(s->parts[1].child)));
}

}  // namespace
}  // namespace vern
