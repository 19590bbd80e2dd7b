// Derivation semantics (docs/grammar.md: split, "Derivation and randomness") checked on the
// facts a user can compute by hand.
#include "forward/derive.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "support/derive_helpers.hpp"

namespace vern {
namespace {

using test::boxes;
using test::derive_text;

constexpr double kEps = 1e-12;

TEST(Derive, RelativeSizesShareTheScope) {
  // split(x){~2:A|~1:B} on a 9-wide scope gives parts of 6 and 3.
  const auto d = derive_text("plot --> split(x){ ~2 : I(A) | ~1 : I(B) }", {9, 1, 1});
  const auto b = boxes(d);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].label, "A");
  EXPECT_NEAR(b[0].max.x - b[0].min.x, 6, kEps);
  EXPECT_EQ(b[1].label, "B");
  EXPECT_NEAR(b[1].min.x, 6, kEps);
  EXPECT_NEAR(b[1].max.x - b[1].min.x, 3, kEps);
}

TEST(Derive, SizeReadsTheScopeWhereTheExpressionStands) {
  // On a plot 8 x 1 x 10: a quarter of its width (the split's sizes read
  // the split's scope), then the rest, passed its own width as an
  // argument (the call stands in the part, 6 m wide), its height checked
  // in a condition.
  const auto d = derive_text(
      "plot --> split(x){ size(x) / 4 : I(A) | ~1 : b(size(x)) }\n"
      "b(w) : size(z) > 5 --> split(z){ w : I(B) | ~1 : split(x){ size(x) / 3 : I(C) | ~1 : nil } }\n"
      "b(w) : size(z) <= 5 --> I(D)\n",
      {8, 1, 10});
  const auto b = boxes(d);
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(b[0].label, "A");
  EXPECT_NEAR(b[0].max.x - b[0].min.x, 2, kEps);
  EXPECT_EQ(b[1].label, "B");
  EXPECT_NEAR(b[1].max.z - b[1].min.z, 6, kEps);
  EXPECT_EQ(b[2].label, "C");
  EXPECT_NEAR(b[2].max.x - b[2].min.x, 2, kEps);  // a third of b's 6 m
  EXPECT_EQ(boxes(derive_text("plot --> b(1)\nb(w) : size(z) > 5 --> I(B)\nb(w) : size(z) <= 5 --> I(D)\n", {8, 1, 4}))[0].label,
            "D");
}

TEST(Derive, TerminalsNotKeptLeaveTheRestAsItWas) {
  const std::string text =
      "p --> split(x){ ~1 : colour(1, 0, 0) | ~rand(1, 2) : I(a) } : 1\np --> repeat(y, 0.3){ I(b) } : 1";
  const Grammar g = parse_grammar(text, "g.grm");
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    DeriveOptions kept, dropped;
    kept.seed = dropped.seed = seed;
    dropped.keep_terminals = false;
    const Derivation a = derive(g, kept), b = derive(g, dropped);
    EXPECT_FALSE(a.terminals.empty());
    EXPECT_TRUE(b.terminals.empty());
    EXPECT_EQ(a.labels, b.labels);
    EXPECT_EQ(a.warnings, b.warnings);
  }
}

TEST(Derive, TracedTerminalsSayWhatInsertedThemAndThroughWhichRules) {
  const Grammar g = parse_grammar(
      "p --> split(x){ ~1 : f(2) | ~1 : I(b) }\n"
      "f(n) --> repeatN(x, n){ I(a) }\n"
      "f(n) : n > 5 --> nil\n",
      "g.grm");
  DeriveOptions options;
  const Derivation plain = derive(g, options);
  EXPECT_TRUE(plain.traces.empty());
  options.trace = true;
  const Derivation traced = derive(g, options);
  ASSERT_EQ(traced.terminals.size(), 3u);
  ASSERT_EQ(traced.traces.size(), 3u);
  // Terminals as without tracing.
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(traced.terminals[i].scope, plain.terminals[i].scope);
  EXPECT_EQ(traced.traces[0].at.line, 2u);
  EXPECT_EQ(traced.traces[0].at.column, 25u);
  EXPECT_EQ(traced.traces[0].chain, "p > f(2)");
  EXPECT_EQ(traced.traces[0].rules, (std::vector<RuleId>{0, 1}));  // the first f: an alternative is its own rule
  EXPECT_EQ(traced.traces[2].at.line, 1u);
  EXPECT_EQ(traced.traces[2].chain, "p");
  EXPECT_EQ(traced.traces[2].rules, std::vector<RuleId>{0});
}

TEST(Derive, TracedTerminalsSayWhichPartsAndTilesTheyLieIn) {
  const Grammar g = parse_grammar(
      "@scope 9, 4, 6\n"
      "house --> split(z){ ~1 : floor | ~1 : floor | ~1 : I(roof) }\n"
      "floor --> repeatN(x, 3){ split(x){ ~1 : I(wall) | ~1 : I(window) } }\n",
      "g.grm");
  DeriveOptions options;
  options.trace = true;
  const Derivation d = derive(g, options);
  ASSERT_EQ(d.terminals.size(), 13u);  // 2 floors x 3 bays x 2, and the roof
  const auto& window = d.traces[3];  // floor 0, bay 1, its window
  EXPECT_EQ(d.labels[d.terminals[3].label], "window");
  ASSERT_EQ(window.path.size(), 3u);
  EXPECT_EQ(window.path[0].axis, Axis::Z);
  EXPECT_EQ(window.path[0].index, 0u);  // the first floor
  EXPECT_EQ(window.path[1].axis, Axis::X);
  EXPECT_EQ(window.path[1].index, 1u);  // the second bay
  EXPECT_EQ(window.path[2].index, 1u);  // the window half of it
  // The same bay of the other floor: another storey, the same column.
  const auto& above = d.traces[9];
  EXPECT_EQ(d.labels[d.terminals[9].label], "window");
  EXPECT_EQ(above.path[0].index, 1u);
  EXPECT_EQ(above.path[1], window.path[1]);
  EXPECT_EQ(d.traces[12].path.size(), 1u);  // the roof: the third part of the split along z
  EXPECT_EQ(d.traces[12].path[0].index, 2u);
  // Without tracing nothing is recorded, and the buildings are the same.
  options.trace = false;
  const Derivation plain = derive(g, options);
  EXPECT_TRUE(plain.traces.empty());
  for (std::size_t i = 0; i < plain.terminals.size(); ++i) EXPECT_EQ(plain.terminals[i].scope, d.terminals[i].scope);
}

TEST(Derive, AbsoluteSizesComeFirstAndRelativeShareTheRest) {
  const auto b = boxes(derive_text("p --> split(y){ 1 : I(a) | ~1 : I(b) | ~3 : I(c) | 2 : I(d) }", {1, 11, 1}));
  ASSERT_EQ(b.size(), 4u);
  const double expected[] = {1, 2, 6, 2};
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(b[i].max.y - b[i].min.y, expected[i], kEps) << i;
  EXPECT_NEAR(b[3].max.y, 11, kEps);
}

TEST(Derive, OversizedAbsolutePartsShrinkAndRelativeGetNothing) {
  const auto b = boxes(derive_text("p --> split(x){ 3 : I(a) | ~1 : I(b) | 1 : I(c) }", {2, 1, 1}));
  ASSERT_EQ(b.size(), 2u);  // the relative part has zero length: not derived
  EXPECT_NEAR(b[0].max.x - b[0].min.x, 1.5, kEps);
  EXPECT_NEAR(b[1].max.x - b[1].min.x, 0.5, kEps);
  EXPECT_EQ(b[1].label, "c");
}

TEST(Derive, RepeatMakesCeilingManyEqualTiles) {
  // repeat(x, 3) on 10 gives 4 tiles of 2.5.
  const auto b = boxes(derive_text("p --> repeat(x, 3){ I(t) }", {10, 1, 1}));
  ASSERT_EQ(b.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(b[i].min.x, 2.5 * i, kEps);
    EXPECT_NEAR(b[i].max.x - b[i].min.x, 2.5, kEps);
  }
  // The original spelling means the same, and a tile larger than the scope gives one.
  EXPECT_EQ(boxes(derive_text("p --> repeat(x){ 3 : I(t) }", {10, 1, 1})).size(), 4u);
  EXPECT_EQ(boxes(derive_text("p --> repeat(x, 30){ I(t) }", {10, 1, 1})).size(), 1u);
  // Float noise does not add a sliver tile: 0.7 / 0.1 is 7 tiles.
  EXPECT_EQ(boxes(derive_text("p --> repeat(z, 0.1){ I(t) }", {1, 1, 0.7})).size(), 7u);
}

TEST(Derive, RepeatNRoundsItsCountAndSkipsNonPositive) {
  EXPECT_EQ(boxes(derive_text("p --> repeatN(y, 2.6){ I(t) }", {1, 9, 1})).size(), 3u);
  EXPECT_EQ(boxes(derive_text("p --> repeatN(y, 0){ I(t) }", {1, 9, 1})).size(), 0u);
  EXPECT_EQ(boxes(derive_text("p --> repeatN(y, -2){ I(t) }", {1, 9, 1})).size(), 0u);
}

TEST(Derive, QuarterTurnKeepsTheBoxAndSwapsSizes) {
  const auto d = derive_text("p --> R(z, pi/2){ I(roof) }", {4, 2, 3});
  ASSERT_EQ(d.terminals.size(), 1u);
  const Scope& s = d.terminals[0].scope;
  EXPECT_EQ(s.size, glm::dvec3(2, 4, 3));
  const Bounds b = world_bounds(s);
  EXPECT_EQ(b.min, glm::dvec3(0, 0, 0));  // exact: quarter turns are snapped
  EXPECT_EQ(b.max, glm::dvec3(4, 2, 3));
  // The frame is turned counter-clockwise: local x now points along world y.
  EXPECT_EQ(s.frame[0], glm::dvec3(0, 1, 0));
  EXPECT_EQ(s.frame[1], glm::dvec3(-1, 0, 0));
}

TEST(Derive, HalfTurnAndGeneralAnglesTurnAboutTheCentre) {
  const auto half = derive_text("p --> R(z, pi){ I(a) }", {4, 2, 3});
  const Bounds b = world_bounds(half.terminals[0].scope);
  EXPECT_EQ(b.min, glm::dvec3(0, 0, 0));
  EXPECT_EQ(b.max, glm::dvec3(4, 2, 3));
  const auto tilt = derive_text("p --> R(x, 0.3){ I(a) }", {2, 2, 2});
  const Scope& s = tilt.terminals[0].scope;
  const glm::dvec3 centre = s.to_world(glm::dvec3(0.5));
  EXPECT_NEAR(centre.x, 1, kEps);
  EXPECT_NEAR(centre.y, 1, kEps);
  EXPECT_NEAR(centre.z, 1, kEps);
  EXPECT_NEAR(s.frame[1].z, std::sin(0.3), kEps);
}

TEST(Derive, TranslateAndScaleUseTheScopesOwnAxes) {
  const auto b = boxes(derive_text("p --> T(~0.5, 1, 0){ S(1, ~0.5, 2){ I(a) } }", {4, 4, 4}));
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b[0].min, glm::dvec3(2, 1, 0));
  EXPECT_EQ(b[0].max, glm::dvec3(3, 3, 2));
}

TEST(Derive, CompGivesZeroThicknessFaceScopes) {
  const auto d = derive_text("p --> comp(f){ front : I(f) | top : I(t) | right : I(r) }", {4, 2, 3});
  ASSERT_EQ(d.terminals.size(), 3u);
  const Scope& front = d.terminals[0].scope;
  EXPECT_EQ(front.size, glm::dvec3(4, 3, 0));
  EXPECT_EQ(front.frame[2], glm::dvec3(0, -1, 0));  // outward normal
  const Bounds top = world_bounds(d.terminals[1].scope);
  EXPECT_EQ(top.min, glm::dvec3(0, 0, 3));
  EXPECT_EQ(top.max, glm::dvec3(4, 2, 3));
  const Bounds right = world_bounds(d.terminals[2].scope);
  EXPECT_EQ(right.min, glm::dvec3(4, 0, 0));
  EXPECT_EQ(right.max, glm::dvec3(4, 2, 3));
}

TEST(Derive, ColourMakesAColouredRect) {
  const auto d = derive_text("p --> split(x){ ~1 : colour(1, 0.5, 0) | ~1 : colour(red) }", {2, 1, 1});
  ASSERT_EQ(d.terminals.size(), 2u);
  EXPECT_EQ(d.labels[d.terminals[0].label], "rect");
  EXPECT_TRUE(d.terminals[0].coloured);
  EXPECT_EQ(d.terminals[0].colour, (Rgb{1.0f, 0.5f, 0.0f}));
}

TEST(Derive, ParametersConditionsAndRecursion) {
  // The thesis's recursive repN (4.3.7) equals repeatN.
  const char* text =
      "p --> repN(x, 4)\n"
      "repN(axis, N) : N > 0 --> split(axis){ ~1 : I(rect) | ~(N - 1) : repN(axis, N - 1) }\n"
      "repN(axis, N) : N <= 0 --> nil\n";
  const auto b = boxes(derive_text(text, {8, 1, 1}));
  ASSERT_EQ(b.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(b[i].min.x, 2.0 * i, 1e-9);
}

TEST(Derive, ChoiceFrequenciesFollowPriorities) {
  const Grammar g = parse_grammar(
      "p --> I(a) : 0.5\n"
      "p --> I(b) : 0.3\n"
      "p --> I(c) : 0.2\n"
      "p --> I(never) : 0\n");
  std::map<std::string, int> counts;
  constexpr int kRuns = 10000;
  for (int seed = 0; seed < kRuns; ++seed) {
    DeriveOptions o;
    o.seed = static_cast<std::uint64_t>(seed);
    const auto d = derive(g, o);
    ASSERT_EQ(d.terminals.size(), 1u);
    ++counts[d.labels[d.terminals[0].label]];
  }
  EXPECT_NEAR(counts["a"] / double(kRuns), 0.5, 0.02);
  EXPECT_NEAR(counts["b"] / double(kRuns), 0.3, 0.02);
  EXPECT_NEAR(counts["c"] / double(kRuns), 0.2, 0.02);
  EXPECT_EQ(counts["never"], 0);
}

TEST(Derive, SameSeedSameResultDifferentSeedDifferentResult) {
  const Grammar g = parse_grammar("p --> split(x){ ~rand(1, 2) : I(a) | ~1 : I(b) }");
  DeriveOptions o;
  o.seed = 42;
  const auto a = derive(g, o);
  const auto b = derive(g, o);
  ASSERT_EQ(a.terminals.size(), 2u);
  EXPECT_EQ(a.terminals[0].scope, b.terminals[0].scope);
  o.seed = 43;
  EXPECT_NE(derive(g, o).terminals[0].scope, a.terminals[0].scope);
}

TEST(Derive, EditingOneBranchDoesNotReshuffleAnother) {
  // The right part's random width depends on its path, not on how many
  // draws the left part made.
  const auto a = derive_text("p --> split(x){ 1 : I(l) | 1 : S(rand(1, 2), 1, 1){ I(r) } }", {2, 1, 1}, 9);
  const auto b = derive_text(
      "p --> split(x){ 1 : S(rand(), rand(), rand()){ I(l) } | 1 : S(rand(1, 2), 1, 1){ I(r) } }", {2, 1, 1}, 9);
  EXPECT_EQ(a.terminals[1].scope.size, b.terminals[1].scope.size);
}

TEST(Derive, ConstantsAreDrawnOncePerDerivation) {
  const auto b = boxes(derive_text("w = rand(1, 2)\np --> split(x){ w : I(a) | w : I(b) | ~1 : nil }", {10, 1, 1}));
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].max.x - b[0].min.x, b[1].max.x - b[1].min.x);
}

TEST(Derive, RandomFunctionsStayInTheirRanges) {
  const Grammar g = parse_grammar(
      "p --> split(x){ randint(2, 4) : I(a) | tnormal(1, 5, 0.5, 1.5) : I(b) | choice(1, 3) : I(c) | ~1 : nil }");
  for (std::uint64_t seed = 0; seed < 500; ++seed) {
    DeriveOptions o;
    o.seed = seed;
    o.size = glm::dvec3(100, 1, 1);
    const auto b = boxes(derive(g, o));
    ASSERT_EQ(b.size(), 3u);
    const double w0 = b[0].max.x - b[0].min.x, w1 = b[1].max.x - b[1].min.x, w2 = b[2].max.x - b[2].min.x;
    EXPECT_TRUE(w0 == 2 || w0 == 3 || w0 == 4) << w0;
    EXPECT_GE(w1, 0.5);
    EXPECT_LE(w1, 1.5);
    EXPECT_TRUE(std::abs(w2 - 1) < 1e-12 || std::abs(w2 - 3) < 1e-12) << w2;
  }
}

TEST(Derive, CubeSkeletonGivesTwelveEdges) {
  // The context-sensitive-grammars thesis, 2.3.2: on the unit cube the
  // skeleton is 4 edges along each axis, 0.05 thick and 0.9 (x, y) or 1 (z) long.
  const auto files = test::bundled_grammars();
  const auto it = std::find_if(files.begin(), files.end(),
                               [](const std::string& f) { return f.ends_with("cube_skeleton.grm"); });
  ASSERT_NE(it, files.end());
  const Grammar g = read_grammar_file(*it);
  DeriveOptions o;
  o.size = glm::dvec3(1, 1, 1);
  const auto b = boxes(derive(g, o));
  ASSERT_EQ(b.size(), 12u);
  int along[3] = {0, 0, 0};
  for (const auto& box : b) {
    const glm::dvec3 s = box.max - box.min;
    int axis = -1;
    for (int k = 0; k < 3; ++k)
      if (s[k] > 0.5) axis = k;
    ASSERT_GE(axis, 0);
    ++along[axis];
    EXPECT_NEAR(s[axis], axis == 2 ? 1.0 : 0.9, 1e-12);
    for (int k = 0; k < 3; ++k)
      if (k != axis) {
        EXPECT_NEAR(s[k], 0.05, 1e-12);
      }
  }
  EXPECT_EQ(along[0], 4);
  EXPECT_EQ(along[1], 4);
  EXPECT_EQ(along[2], 4);
}

TEST(Derive, EveryBundledGrammarDerives) {
  const auto files = test::bundled_grammars();
  ASSERT_GE(files.size(), 6u);
  for (const auto& f : files) {
    SCOPED_TRACE(f);
    const Grammar g = read_grammar_file(f);
    for (std::uint64_t seed = 0; seed < 5; ++seed) {
      DeriveOptions o;
      o.seed = seed;
      const auto d = derive(g, o);
      EXPECT_FALSE(d.terminals.empty());
      EXPECT_TRUE(d.warnings.empty()) << d.warnings.front();
      for (const auto& t : d.terminals)
        for (int k = 0; k < 3; ++k) EXPECT_TRUE(std::isfinite(t.scope.size[k]) && t.scope.size[k] >= 0);
    }
  }
}

}  // namespace
}  // namespace vern
