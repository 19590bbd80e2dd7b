// Inference end to end: derived examples -> infer -> derive again.
#include "inverse/infer.hpp"

#include <gtest/gtest.h>

#include "forward/derive.hpp"
#include "graph/parser.hpp"
#include "graph/structural.hpp"
#include "graph/writer.hpp"
#include "inverse/check/check.hpp"
#include "support/derive_helpers.hpp"
#include "support/example_helpers.hpp"

namespace vern {
namespace {

// Do the two sets of parts match one to one, same label and corners within
// tol (after moving `expected` by -offset)? Names the first part without a match.
::testing::AssertionResult same_parts(const std::vector<vern::LabelledBox>& got,
                                      const std::vector<vern::LabelledBox>& expected, glm::dvec3 offset, double tol) {
  if (got.size() != expected.size())
    return ::testing::AssertionFailure() << got.size() << " parts derived, " << expected.size() << " expected";
  std::vector<bool> used(got.size(), false);
  for (const auto& e : expected) {
    bool found = false;
    for (std::size_t i = 0; i < got.size() && !found; ++i) {
      if (used[i] || got[i].label != e.label) continue;
      const glm::dvec3 dmin = glm::abs(got[i].min - (e.min - offset));
      const glm::dvec3 dmax = glm::abs(got[i].max - (e.max - offset));
      if (std::max({dmin.x, dmin.y, dmin.z, dmax.x, dmax.y, dmax.z}) <= tol) used[i] = found = true;
    }
    if (!found)
      return ::testing::AssertionFailure() << "no derived part matches " << e.label << " at (" << e.min.x - offset.x
                                           << ", " << e.min.y - offset.y << ", " << e.min.z - offset.z << ")";
  }
  return ::testing::AssertionSuccess();
}

Derivation derive_seed(const Grammar& g, std::uint64_t seed) {
  DeriveOptions o;
  o.seed = seed;
  return derive(g, o);
}

// Grammars whose buildings have no overlapping parts (all bundled ones).
std::vector<std::string> grammars() { return test::bundled_grammars(); }

TEST(Infer, OneExampleComesBackExactlyForEveryBundledGrammar) {
  for (const auto& file : grammars()) {
    SCOPED_TRACE(file);
    const Grammar source = read_grammar_file(file);
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      const Example example = test::example_of(test::derived_parts(derive_seed(source, seed)));
      const Inference inferred = infer({example}, {});
      // The grammar text parses back to the same graph.
      const Grammar reread = parse_grammar(write_grammar(inferred.grammar));
      ASSERT_TRUE(equal_grammars(reread, inferred.grammar));
      // One example: nothing is random, any seed derives it.
      DeriveOptions o;
      o.seed = 99;
      const Derivation again = derive(reread, o);
      EXPECT_TRUE(same_parts(test::derived_parts(again), example.boxes, example.min, 2 * inferred.tolerance));
    }
  }
}

TEST(Infer, TwentyExamplesAreAllDerivableFromWhatIsInferredFromThem) {
  for (const auto& file : grammars()) {
    SCOPED_TRACE(file);
    const Grammar source = read_grammar_file(file);
    std::vector<Example> examples;
    for (std::uint64_t seed = 1; seed <= 20; ++seed)
      examples.push_back(test::example_of(test::derived_parts(derive_seed(source, seed))));
    const Inference inferred = infer(examples, {});
    const Grammar reread = parse_grammar(write_grammar(inferred.grammar));
    for (const auto& e : examples) {
      std::vector<vern::LabelledBox> boxes = e.boxes;
      for (auto& b : boxes) b.min -= e.min, b.max -= e.min;
      // check's default tolerance, as a user runs it: 1e-6 of this example.
      const CheckResult r = check_example(reread, boxes, example_size(e));
      EXPECT_TRUE(r.derivable) << r.mismatch;
    }
  }
}

TEST(Infer, GarageExamplesGiveAFewRulesWithTheHeightRangeFitted) {
  const Grammar source = read_grammar_file(VERN_SOURCE_DIR "/data/grammars/garage_machine.grm");
  std::vector<Example> examples;
  double lowest = 1e9, highest = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    examples.push_back(test::example_of(test::derived_parts(derive_seed(source, seed))));
    for (const auto& b : examples.back().boxes)
      if (b.label == "rect" && b.max.z - b.min.z < 5) {
        lowest = std::min(lowest, b.max.z - b.min.z);
        highest = std::max(highest, b.max.z - b.min.z);
      }
  }
  // --distributions uniform: the thesis's ranges, every derived garage
  // within the examples' own lowest and highest (to the tolerance the
  // ranges round by). Fitted (the default): the range reaches a little
  // beyond them (the unbiased estimate of a uniform's ends: a ninth of the
  // spread each side for ten examples), never far.
  bool left = false, right = false;
  for (const bool uniform : {true, false}) {
    InferOptions options;
    options.uniform_distributions = uniform;
    const Inference inferred = infer(examples, options);
    EXPECT_LE(inferred.grammar.rules.size(), 5u) << write_grammar(inferred.grammar);
    const double slack = uniform ? 2 * inferred.tolerance : highest - lowest;
    bool beyond = false;
    for (std::uint64_t seed = 0; seed < 400; ++seed) {
      const Derivation d = derive_seed(inferred.grammar, seed);
      for (const auto& b : test::derived_parts(d)) {
        if (b.label != "rect" || b.max.z - b.min.z >= 5) continue;
        const double h = b.max.z - b.min.z;
        EXPECT_GE(h, lowest - slack);
        EXPECT_LE(h, highest + slack);
        beyond = beyond || h < lowest - 2 * inferred.tolerance || h > highest + 2 * inferred.tolerance;
        (b.min.x < 1 ? left : right) = true;
      }
    }
    EXPECT_EQ(beyond, !uniform) << write_grammar(inferred.grammar);
  }
  EXPECT_TRUE(left);
  EXPECT_TRUE(right);
  EXPECT_LT(lowest, highest);
}

}  // namespace
}  // namespace vern

namespace vern {
namespace {

// Splitting examples on several threads changes nothing in the result.
TEST(Infer, ThreadsGiveTheSameGrammar) {
  const Grammar source = read_grammar_file(VERN_SOURCE_DIR "/data/grammars/modern_houses.grm");
  std::vector<Example> examples;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    examples.push_back(test::example_of(test::derived_parts(derive_seed(source, seed))));
  }
  InferOptions one, two;
  one.threads = 1;
  two.threads = 2;
  EXPECT_EQ(write_grammar(infer(examples, one).grammar), write_grammar(infer(examples, two).grammar));
}

// Issue 4, "sizes that scale" and "repeats that stretch": terraces on plots
// of different widths. The learnt grammar keeps the end walls 0.6 m thick
// on any plot, and a wider plot gets more windows, not wider ones.
TEST(Infer, WallsKeepTheirThicknessAndWindowsFollowTheWidth) {
  const Grammar source = read_grammar_file(VERN_SOURCE_DIR "/data/grammars/terrace.grm");
  std::vector<Example> examples;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    examples.push_back(test::example_of(test::derived_parts(derive_seed(source, seed))));
  }
  const Inference inferred = infer(examples, {});
  auto windows_and_walls = [&](double width, std::uint64_t seed) {
    DeriveOptions o;
    o.seed = seed;
    o.size = glm::dvec3(width, 6, 9);
    const Derivation d = derive(inferred.grammar, o);
    std::size_t windows = 0;
    for (const auto& b : test::derived_parts(d)) {
      if (b.label == "window") ++windows;
      const bool end_wall = b.label == "rect" && (b.min.x < 1e-9 || b.max.x > width - 1e-9);
      if (end_wall) {
        EXPECT_NEAR(b.max.x - b.min.x, 0.6, 1e-6) << "width " << width;
      }
    }
    return windows;
  };
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const std::size_t narrow = windows_and_walls(9, seed), wide = windows_and_walls(24, seed);
    EXPECT_GT(narrow, 0u);
    EXPECT_GT(wide, 2 * narrow) << write_grammar(inferred.grammar);
  }
}

// @scope is fitted as every varying size is: heights seen again and again
// (storeys of one height) are a choice of them, widths spread over a
// range reach a little beyond the widest and narrowest seen.
TEST(Infer, PlotSizesGetTheDistributionTheyFit) {
  std::vector<Example> examples;
  for (int i = 0; i < 10; ++i) {
    const double width = 8 + 1.37 * i, height = i % 2 ? 6 : 9;
    examples.push_back(test::example_of({test::part("block", {0, 0, 0}, {width, 5, height})}));
  }
  const Inference inferred = infer(examples, {});
  const std::string text = write_grammar(inferred.grammar);
  auto write_expr = [&](const Expr& e) { return write_expression(inferred.grammar, e, {}); };
  EXPECT_EQ(write_expr(inferred.grammar.scope[1]), "5") << text;
  EXPECT_EQ(write_expr(inferred.grammar.scope[2]), "choice(6, 9)") << text;
  const std::string width = write_expr(inferred.grammar.scope[0]);
  EXPECT_EQ(width.rfind("rand(", 0), 0u) << text;
  double lo = 0, hi = 0;
  ASSERT_EQ(std::sscanf(width.c_str(), "rand(%lf, %lf)", &lo, &hi), 2) << width;
  EXPECT_LT(lo, 8);
  EXPECT_GT(hi, 8 + 1.37 * 9);
  // --distributions uniform keeps the plain range of what was seen.
  InferOptions uniform;
  uniform.uniform_distributions = true;
  const Grammar plain = infer(examples, uniform).grammar;
  EXPECT_EQ(write_expression(plain, plain.scope[2], {}), "rand(6, 9)");
}

// A house's range and a barn's across a yard, with end walls of one
// thickness and bays of two widths: in some examples the bays happen to
// line up across the yard, in others not. The yard is cut first in all of
// them, so they share one structure: one alternative, not one for the
// examples whose cuts line up and another for the rest.
TEST(Infer, RangesAcrossAYardAreOneStructureWhetherOrNotTheirBaysLineUp) {
  const Grammar source = parse_grammar(R"(
@start farmstead
@scope rand(16, 28), 22, 6
farmstead --> split(y){ 7 : range(0.5, 2.5, 1.4) | ~1 : nil | 6 : range(0.5, 3.2, 0.8) }
range(wall, bw, wh) --> split(x){ wall : I(rect) | ~1 : repeat(x, bw){ bay(wh) } | wall : I(rect) }
bay(wh) --> split(x){ ~1 : I(rect) | 1.2 : split(z){ 1 : I(rect) | wh : I(window) | ~1 : I(rect) } | ~2 : I(rect) }
)",
                                       "farmstead.grm");
  std::vector<Example> examples;
  for (std::uint64_t seed = 1; seed <= 10; ++seed)
    examples.push_back(test::example_of(test::derived_parts(derive_seed(source, seed))));
  const Inference inferred = infer(examples, {});
  const std::string text = write_grammar(inferred.grammar);
  EXPECT_FALSE(std::holds_alternative<Choose>(inferred.grammar.op(inferred.grammar.rules[inferred.grammar.start_rule].body)))
      << text;
  const auto* yard = std::get_if<Split>(&inferred.grammar.op(inferred.grammar.rules[inferred.grammar.start_rule].body));
  ASSERT_NE(yard, nullptr) << text;
  EXPECT_EQ(yard->parts.size(), 3u) << text;
  for (const Example& e : examples) {
    const CheckResult r = check_example(inferred.grammar, e.boxes, example_size(e));
    EXPECT_TRUE(r.derivable) << r.mismatch << "\n" << text;
  }
}

// Files from a modelling tool: every coordinate through a float (as a
// transform in single precision leaves it) and written with six decimals,
// as Blender writes OBJ. The grammar is the one the exact examples give,
// ratios and all (~2 : ~1, not ~6.666667 : ~3.333333).
TEST(Infer, ExamplesWrittenWithSixDecimalsGiveTheSameGrammar) {
  // The garage on a 10 m plot: its house takes two thirds, 6.666667 m.
  const Grammar source = read_grammar_file(VERN_SOURCE_DIR "/data/grammars/garage_machine.grm");
  std::vector<Example> exact, written;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    std::vector<vern::LabelledBox> boxes = test::derived_parts(derive_seed(source, seed));
    exact.push_back(test::example_of(boxes));
    for (auto& b : boxes)
      for (glm::dvec3* corner : {&b.min, &b.max})
        for (int a = 0; a < 3; ++a)
          (*corner)[a] = std::round(static_cast<double>(static_cast<float>((*corner)[a])) * 1e6) / 1e6;
    written.push_back(test::example_of(boxes));
  }
  const std::string expected = write_grammar(infer(exact, {}).grammar);
  const Inference inferred = infer(written, {});
  EXPECT_EQ(write_grammar(inferred.grammar), expected);
  for (const Example& e : written) EXPECT_TRUE(check_example(inferred.grammar, e.boxes, example_size(e)).derivable);
}

TEST(Infer, ACutTreeDeeperThanTheReaderNestsIsWrittenAsRulesItReads) {
  // 300 parts each peeled off the rest: nested splits 301 deep, where the
  // reader takes operations nested 256 deep at most.
  const Example example = test::example_of(test::peeled_layout(300));
  const Inference inferred = infer({example}, {});
  const std::string text = write_grammar(inferred.grammar);
  const Grammar reread = parse_grammar(text);
  EXPECT_TRUE(equal_grammars(reread, inferred.grammar));
  const CheckResult r = check_example(reread, example.boxes, example_size(example));
  EXPECT_TRUE(r.derivable) << r.mismatch;
}

TEST(Infer, PinwheelsNestedInPinwheelsAreDerivedExactly) {
  // Each level's arms are placed as shares of its square; rounded for the
  // 10 m square, the shares put the small arms deep inside off by more than
  // the tolerance.
  for (const int levels : {5, 7}) {
    SCOPED_TRACE(levels);
    const Example example = test::example_of(test::nested_pinwheel(levels, 10, 3));
    const Inference inferred = infer({example}, {});
    const CheckResult r = check_example(inferred.grammar, example.boxes, example_size(example));
    EXPECT_TRUE(r.derivable) << r.mismatch << "\n" << write_grammar(inferred.grammar);
  }
}

// A flat panel at the foot of a cell that a thin box also holds: no cut
// separates them, so they are a placed group (placements.hpp), which
// check follows only by deriving it. Merged with a house whose box of
// the same label tops a taller column, the group's column was unified
// with that one and given a drawn height: no longer one outcome, the
// group could not be checked and infer stopped ("no grammar inferred
// derives"). A fuzzed layout (fuzz/regressions/infer_layout/), in round
// numbers.
TEST(Infer, APlacedGroupIsCopiedAsItIsWhateverItsNeighboursVary) {
  using test::part;
  const Example blocks = test::example_of(
      {part("a", {0, 0, 0}, {0.6, 0.13, 0.8}), part("a", {0, 0.13, 0}, {0.6, 0.2, 0.8}),
       part("a", {0, 0.2, 0}, {0.6, 0.33, 0.8})},
      "blocks.obj");
  const Example group = test::example_of({part("c", {0.8, 0.3, 0.7}, {0.9, 1, 1}), part("d", {0.7, 0.9, 0}, {0.9, 1, 0}),
                                          part("c", {0, 0, 2.8}, {0.4, 0.1, 3.2})},
                                         "group.obj");
  const Inference inferred = infer({blocks, group}, {});
  for (const Example& e : {blocks, group}) {
    const CheckResult r = check_example(inferred.grammar, e.boxes, example_size(e));
    EXPECT_TRUE(r.derivable) << e.source << ": " << r.mismatch << "\n" << write_grammar(inferred.grammar);
  }
}

TEST(Infer, ASizeSharedByTwoSubtreesIsNoChoiceOfTheValuesSeen) {
  // Both side wings of each building take one drawn height h: every
  // example shows its height at two places. Thirty continuous heights are
  // a range (or one draw for both), never choice(...) of the thirty values
  // seen, as each looked like a value seen twice. (A random style,
  // evaluate --random-styles 40 --seed 1, style 15.)
  const Grammar source = parse_grammar(
      "@start lot\n"
      "@scope rand(23.5, 38), rand(7, 10), rand(19.5, 32.5)\n"
      "lot --> layout(rand(4.9, 5.9))\n"
      "layout(h) --> split(x){ ~2.9 : house(rand(3.9, 5), randint(0, 1)) | ~1.1 : side(h) | ~0.5 : nil | "
      "~1.3 : side(h) }\n"
      "house(u, b) --> split(x){ 0.9 : I(pillar) | ~1 : core(u, b) | 0.9 : I(pillar) }\n"
      "core(u, b) --> split(z){ u : I(podium) | 2.5 * u + 1 : repeat(z, 3.3){ storey(b) } | ~1 : I(roof) }\n"
      "storey(b) --> repeat(x, 3.8){ bay(b) }\n"
      "bay(b) : b == 0 --> split(x){ ~1 : I(brick) | ~2.1 : I(panel) | ~1 : I(brick) }\n"
      "bay(b) : b == 1 --> split(x){ ~1 : I(brick) | ~2.1 : split(z){ ~1 : I(loggia) | ~2 : I(pane) } | "
      "~1 : I(brick) }\n"
      "side(h) --> split(z){ h : repeat(x, 3.8){ sideBay } | ~1 : R(z, pi / 2){ I(roof) } }\n"
      "sideBay --> split(x){ ~1 : I(render) | ~1.2 : I(pane) | ~1 : I(render) }\n");
  const Inference inferred = infer(test::derived_examples(source, 30), {});
  const std::string text = write_grammar(inferred.grammar);
  EXPECT_EQ(text.find("choice("), std::string::npos) << text;
}

TEST(Infer, PartsCutSideBySideThatAreASplitInsideASplitKeepTheirProportions) {
  // The front's columns and mass stand in one row with the lodges, but the
  // lodges keep their ratio to the front as a whole: written as one split
  // the mass is a share drawn anew and the buildings lose the proportions.
  // (A random style, evaluate --random-styles 30 --seed 777, style 20.)
  const Grammar source = parse_grammar(
      "@start site\n"
      "@scope rand(21.5, 29.5), rand(7.5, 10.5), rand(6, 8.5)\n"
      "site --> split(x){ ~1.2 : lodge | ~1.1 : lodge | ~2.9 : front }\n"
      "front --> split(x){ 1 : I(column) | ~1 : split(z){ ~1 : I(wall) | 2 : I(roof) } | 1 : I(column) }\n"
      "lodge --> split(z){ ~2.3 : I(pane) | ~1 : I(roof) }\n");
  const Inference inferred = infer(test::derived_examples(source, 10), {});
  EXPECT_TRUE(test::source_derives_variants(source, inferred.grammar, 101, 120));
}

TEST(Infer, AFrontOfColumnsKeepsItsShareBesideAWingOfAnyWidth) {
  // As the test above, with the second lodge drawn in each building: the
  // front is still one part of the site, its mass not a share drawn anew
  // beside the columns and both lodges (no more than one variant in
  // twenty missed, where the lodge's range, widened, reaches past the
  // source's). (A random style, evaluate --random-styles 40 --seed
  // 424242, style 21.)
  const Grammar source = parse_grammar(
      "@start site\n"
      "@scope rand(40, 60), rand(7.5, 10.5), rand(6, 8.5)\n"
      "site --> split(x){ ~2.1 : front | ~0.7 : lodge | ~rand(0.9, 1.3) : lodge }\n"
      "front --> split(x){ 1 : I(column) | ~1 : split(z){ ~1 : I(wall) | 2 : I(roof) } | 1 : I(column) }\n"
      "lodge --> split(z){ ~2.3 : I(pane) | ~1 : I(roof) }\n");
  const Inference inferred = infer(test::derived_examples(source, 30), {});
  EXPECT_TRUE(test::source_derives_variants(source, inferred.grammar, 101, 120, 1));
}

TEST(Infer, AislesBesideANaveKeepTheirProportionToIt) {
  // Two aisles of independent widths beside a nave of one share, on plots
  // of any width: the aisles are drawn beside the nave, in the
  // proportions the examples show, not in metres. (A random style,
  // evaluate --random-styles 30 --seed 778, style 14, whose nave holds a
  // tower of tiers; see docs/inference.md on splits above a recursion.)
  const Grammar source = parse_grammar(
      "@start parcel\n"
      "@scope rand(9, 12.5), rand(25, 44), rand(22.5, 37.5)\n"
      "parcel --> split(y){ ~rand(0.6, 1.1) : I(aisle) | ~2.6 : nave | ~rand(0.6, 1.1) : I(aisle) }\n"
      "nave --> split(z){ 4 : I(plinth) | ~1 : repeat(z, 3.2){ I(storey) } }\n");
  const Inference inferred = infer(test::derived_examples(source, 30), {});
  const std::string text = write_grammar(inferred.grammar);
  for (std::uint64_t seed = 101; seed <= 140; ++seed) {
    double nave = 0;
    std::vector<double> aisles;
    for (const LabelledBox& b : test::derived_parts(inferred.grammar, seed)) {
      if (b.label == "aisle") aisles.push_back(b.max.y - b.min.y);
      if (b.label == "plinth") nave = b.max.y - b.min.y;
    }
    ASSERT_EQ(aisles.size(), 2u) << text;
    for (const double a : aisles) {
      EXPECT_GE(a / nave, 0.6 / 2.6 - 1e-3) << "seed " << seed << "\n" << text;
      EXPECT_LE(a / nave, 1.1 / 2.6 + 1e-3) << "seed " << seed << "\n" << text;
    }
  }
}

TEST(Infer, AGrammarMadeAgainAndPassedIsWritten) {
  // The first grammar does not derive one of these thirty examples; made
  // again within the smallest tolerance it does (joining sizes checks it).
  // That second grammar is written, not refused for the first one's
  // failure. (A random style, evaluate --random-styles 300 --seed
  // 1796395335, style 198.)
  const Grammar source = parse_grammar(
      "@start site\n"
      "@scope rand(31.5, 55.5), rand(7, 9.5), rand(15.5, 22.5)\n"
      "site --> split(x){ ~rand(2.1, 3) : mansion(rand(3.6, 5.6)) | ~tnormal(0.9, 0.15, 0.6, 1.2) : lodge }\n"
      "mansion(u) --> split(x){ 0.4 : I(pier) | ~1 : shell(u) | 0.4 : I(pier) }\n"
      "shell(u) --> split(z){ u : ground(randint(0, 3)) | 0.5 * u + 3 : repeat(z, 3.4){ level } | ~1 : covering }\n"
      "ground(k) --> split(x){ 3.6 * k : repeatN(x, k){ travee } | 3.6 : porch | ~1 : repeat(x, 3.6){ travee } }\n"
      "porch --> split(x){ ~1 : I(render) | 1.3 : split(z){ 2.1 : I(door) | ~1 : I(render) } | ~1 : I(render) }\n"
      "level --> repeat(x, 3.6){ travee }\n"
      "travee --> split(x){ ~1 : I(render) | 1.1 : split(x){ ~1 : I(window) | ~0.4 : I(render) | ~1 : I(window) } | "
      "~1 : I(render) }\n"
      "covering --> I(pyramid)\n"
      "lodge --> split(z){ ~tnormal(2.2, 0.25, 1.7, 2.7) : repeat(x, 3.6){ lodgeBay } | ~1 : annexRoof }\n"
      "lodgeBay --> split(x){ ~1 : I(render) | 1 : I(window) | ~1 : I(render) }\n"
      "annexRoof --> I(hip)\n");
  const std::vector<Example> examples = test::derived_examples(source, 30);
  const Inference inferred = infer(examples, {});
  for (const Example& e : examples) {
    const CheckResult r = check_example(inferred.grammar, e.boxes, example_size(e));
    EXPECT_TRUE(r.derivable) << e.source << ": " << r.mismatch;
  }
}

// Where every attempt's grammar misses an example, the last leaves rows of
// unlike tiles as each example has them (MergeOptions::fold_unlike): a
// grammar with fewer generalisations, not an error. Bays in equal thirds
// whose kinds are drawn tile by tile were read as tiles a third long.
TEST(Infer, RowsOfUnlikeTilesThatNoFoldingDerivesStillGiveAGrammar) {
  const Grammar source = read_grammar_file(VERN_SOURCE_DIR "/tests/data/thirds_tile_choice.grm");
  const std::vector<Example> examples = test::derived_examples(source, 10);
  Inference inferred;
  ASSERT_NO_THROW(inferred = infer(examples, {}));
  EXPECT_TRUE(test::derives_every_example(inferred.grammar, examples));
}

TEST(Infer, StoreysLineUpOnADoorThatIsOneBoxAfterOneBayOrMore) {
  // The ground floor's bays before a bare door (one bay is a run of one,
  // as two are a run of two) are the storeys' bays before their balcony
  // bay: one size drawn once, so variants keep the storeys on the door.
  const Grammar source = read_grammar_file(VERN_SOURCE_DIR "/tests/data/door_after_bays.grm");
  const std::vector<Example> examples = test::derived_examples(source, 30);
  const Inference inferred = infer(examples, {});
  EXPECT_TRUE(test::source_derives_variants(source, inferred.grammar, 1001, 1040, 4));
  EXPECT_TRUE(test::derives_every_example(inferred.grammar, examples));
}

}  // namespace
}  // namespace vern
