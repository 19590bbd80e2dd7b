// Checking examples against grammars (inverse/check/check.hpp) and the supports
// of expressions it rests on (inverse/sizes/support.hpp).
//
// The bundled grammars derive examples with vern::derive; each must check
// as derivable, and each perturbed copy (a box moved, relabelled, deleted,
// added; the garage too tall) as not derivable, with a message naming a
// rule. All six bundled grammars are checked exactly: their random
// constants (the city's N and M) take few values and are tried one by one,
// and their continuous random arguments (the city's scalar and tower
// heights) are solved for from the split that uses them.
#include "inverse/check/check.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <tuple>
#include <utility>

#include "forward/derive.hpp"
#include "forward/evaluate.hpp"
#include "graph/parser.hpp"
#include "inverse/sizes/support.hpp"
#include "support/derive_helpers.hpp"

namespace vern {
namespace {

// ---- helpers ----

}  // namespace

// Readable supports in failure messages.
void PrintTo(const Support& s, std::ostream* os) { *os << s.describe(); }

namespace {

struct CheckedExample {
  std::vector<LabelledBox> boxes;
  glm::dvec3 size{0.0};
};

CheckedExample example_of(const Derivation& d) {
  CheckedExample e;
  e.size = d.start.size;
  for (const auto& t : d.terminals) {
    const Bounds b = world_bounds(t.scope);
    LabelledBox box;
    box.label = d.labels[t.label];
    box.min = b.min;
    box.max = b.max;
    e.boxes.push_back(box);
  }
  return e;
}

CheckedExample derive_example(const Grammar& g, std::uint64_t seed) {
  DeriveOptions o;
  o.seed = seed;
  return example_of(derive(g, o));
}

LabelledBox box(const std::string& label, glm::dvec3 lo, glm::dvec3 hi) {
  LabelledBox b;
  b.label = label;
  b.min = lo;
  b.max = hi;
  return b;
}

CheckResult check_text(const std::string& grammar, const std::vector<LabelledBox>& boxes, glm::dvec3 size) {
  return check_example(parse_grammar(grammar, "test.grm"), boxes, size, {});
}

std::string joined(const std::vector<std::string>& lines) {
  std::string t;
  for (const auto& l : lines) t += l + "\n";
  return t;
}

// Does the message say where: "at <a rule of g> (line:col), ..."?
bool names_a_rule(const Grammar& g, const std::string& message) {
  for (const auto& r : g.rules)
    if (message.find("at " + r.label + " (") != std::string::npos) return true;
  return false;
}

std::string stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

bool inside(const LabelledBox& b, glm::dvec3 size) {
  for (int k = 0; k < 3; ++k)
    if (b.min[k] < 0 || b.max[k] > size[k]) return false;
  return true;
}

// Moves box k by 0.3 m along the first axis and direction that keep it
// inside the scope.
bool move_box(CheckedExample& e, std::size_t k) {
  for (int axis : {0, 1, 2}) {
    for (double d : {0.3, -0.3}) {
      LabelledBox b = e.boxes[k];
      b.min[axis] += d;
      b.max[axis] += d;
      if (inside(b, e.size)) {
        e.boxes[k] = b;
        return true;
      }
    }
  }
  return false;
}

bool overlaps(const LabelledBox& a, const LabelledBox& b) {
  for (int k = 0; k < 3; ++k)
    if (a.max[k] <= b.min[k] || b.max[k] <= a.min[k]) return false;
  return true;
}

// Adds a small cube where no box is (searching a grid of the scope).
bool add_box_in_empty_space(CheckedExample& e) {
  const glm::dvec3 cube = e.size * 0.02;
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j)
      for (int k = 0; k < 9; ++k) {
        const glm::dvec3 centre = e.size * glm::dvec3((i + 0.5) / 9, (j + 0.5) / 9, (k + 0.5) / 9);
        const LabelledBox b = box("rect", centre - cube / 2.0, centre + cube / 2.0);
        if (std::none_of(e.boxes.begin(), e.boxes.end(), [&](const LabelledBox& o) { return overlaps(o, b); })) {
          e.boxes.push_back(b);
          return true;
        }
      }
  return false;
}

// ---- Support: interval arithmetic ----

Binding no_names(ExprKind, std::uint32_t) { return {false, {}, Support::everything()}; }

Support support_of(const std::string& expr) {
  // Parse "x --> split(x){ ~<expr> : nil }" and take the size expression.
  const Grammar g = parse_grammar("c = 1\np --> split(x){ ~(" + expr + ") : nil }");
  const auto& split = std::get<Split>(g.op(g.rules[0].body));
  return expression_support(split.parts[0].size.value, [](ExprKind kind, std::uint32_t) -> Binding {
    if (kind == ExprKind::Constant) return {true, Value(1.0), {}};
    return {false, {}, Support::everything()};
  });
}

TEST(CheckSupport, LiteralsAndDeterministicArithmeticArePoints) {
  EXPECT_EQ(support_of("3"), Support::point(3));
  // Computed with the same operations as derive(): bit-identical.
  EXPECT_EQ(support_of("10 / 51").lower(), 10.0 / 51.0);
  EXPECT_TRUE(support_of("10 / 51").is_point());
  EXPECT_EQ(support_of("max(2, c * 5) - 1"), Support::point(4));
}

TEST(CheckSupport, RandomFunctionsGiveTheirRanges) {
  EXPECT_EQ(support_of("rand(1, 2)"), Support::range(1, 2));
  EXPECT_EQ(support_of("rand"), Support::range(0, 1));
  EXPECT_EQ(support_of("randint(2, 5)"), Support::points({2, 3, 4, 5}));
  EXPECT_EQ(support_of("choice(1, 3, 7)"), Support::points({1, 3, 7}));
  EXPECT_EQ(support_of("tnormal(1, 2, 0.5, 3)"), Support::range(0.5, 3));
  EXPECT_EQ(support_of("normal(1, 2)"), Support::everything());
  EXPECT_EQ(support_of("normal(1, 0)"), Support::point(1));
}

TEST(CheckSupport, ArithmeticOfALiteralAndARandomValue) {
  EXPECT_EQ(support_of("rand/2 + 0.75"), Support::range(0.75, 1.25));
  EXPECT_EQ(support_of("rand(1, 2) * 2"), Support::range(2, 4));
  EXPECT_EQ(support_of("10 * randint(8, 10)"), Support::points({80, 90, 100}));
  EXPECT_EQ(support_of("randint(1, 4) * 2"), Support::points({2, 4, 6, 8}));
  EXPECT_NEAR(support_of("1 - rand(0.3, 0.7)").lower(), 0.3, 1e-15);
  EXPECT_NEAR(support_of("1 - rand(0.3, 0.7)").upper(), 0.7, 1e-15);
  EXPECT_EQ(support_of("-rand(1, 2)"), Support::range(-2, -1));
  // Each draw is independent: rand() - rand() spans [-1, 1].
  EXPECT_EQ(support_of("rand() - rand()"), Support::range(-1, 1));
  EXPECT_EQ(support_of("1 / rand(2, 4)"), Support::range(0.25, 0.5));
  EXPECT_EQ(support_of("floor(rand(0.5, 2.5))"), Support::points({0, 1, 2}));
}

TEST(CheckSupport, DivisionByARangeHoldingZeroIsUnbounded) {
  const Support s = support_of("1 / rand(0, 2)");
  EXPECT_DOUBLE_EQ(s.lower(), 0.5);
  EXPECT_TRUE(std::isinf(s.upper()));
  EXPECT_TRUE(Support::range(1, 2).contains(1.5));
  EXPECT_FALSE((Support::point(1) / Support::point(0)).contains(0));
}

TEST(CheckSupport, ComparisonsAndLogicGiveTruthValues) {
  EXPECT_EQ(support_of("rand(1, 2) > 3"), Support::point(0));
  EXPECT_EQ(support_of("rand(1, 2) < 3"), Support::point(1));
  EXPECT_EQ(support_of("rand() < 0.5"), Support::points({0, 1}));
  EXPECT_EQ(support_of("rand() < 0.5 && 0"), Support::point(0));
}

TEST(CheckSupport, IntegerSetsAndContainment) {
  const Support big = Support::integers(1, 1000);
  EXPECT_TRUE(big.integer);
  EXPECT_TRUE(big.contains(7));
  EXPECT_FALSE(big.contains(7.5));
  EXPECT_TRUE(big.contains(7.0000001, 1e-6));
  EXPECT_FALSE(big.values(64).has_value());
  EXPECT_EQ(Support::range(0, 1).intersect(Support::points({0.5, 2})), Support::point(0.5));
  EXPECT_EQ(Support::range(0, 1).unite(Support::range(2, 3)).describe(), "[0, 1] u [2, 3]");
}

TEST(CheckSupport, DeterministicFailuresAreEvaluationErrors) {
  const Grammar g = parse_grammar("p --> split(x){ ~(1 / 0) : nil }");
  const auto& split = std::get<Split>(g.op(g.rules[0].body));
  EXPECT_THROW(possible_values(split.parts[0].size.value, no_names), EvaluationError);
}

// ---- the matcher on small cases ----

TEST(CheckSplit, OneCommonScaleForRelativeParts) {
  const std::string g = "p --> split(x){ ~2 : I(A) | ~1 : I(B) }";
  const auto ok = check_text(g, {box("A", {0, 0, 0}, {6, 1, 1}), box("B", {6, 0, 0}, {9, 1, 1})}, {9, 1, 1});
  EXPECT_TRUE(ok.derivable) << ok.mismatch;
  const auto bad = check_text(g, {box("A", {0, 0, 0}, {5, 1, 1}), box("B", {5, 0, 0}, {9, 1, 1})}, {9, 1, 1});
  EXPECT_FALSE(bad.derivable);
  EXPECT_NE(bad.mismatch.find("at p (1:1), split(x) at 1:7"), std::string::npos) << bad.mismatch;
  EXPECT_NE(bad.mismatch.find("~2 : ~1"), std::string::npos) << bad.mismatch;
  EXPECT_NE(bad.mismatch.find("cuts at x = 0, 5, 9"), std::string::npos) << bad.mismatch;
}

// The mismatch named is the one of the attempt that got furthest, not
// the deepest: here a wing that matches on its second alternative (the
// first fails five splits down) comes before a house whose ground floor
// is too tall, and the house is what the grammar does not derive.
TEST(CheckSplit, NamesTheFailureFurthestAlongNotTheDeepest) {
  const std::string g =
      "p --> split(x){ 4 : w | ~1 : h }\n"
      "w --> split(y){ ~1 : split(z){ ~1 : split(y){ 1 : I(a) | ~1 : I(b) } } } : 1\n"
      "w --> split(y){ ~1 : I(c) | ~1 : I(c) } : 1\n"
      "h --> split(z){ 2 : I(g) | ~1 : I(s) }";
  const std::vector<LabelledBox> wing{box("c", {0, 0, 0}, {4, 1, 5}), box("c", {0, 1, 0}, {4, 2, 5})};
  auto with_ground = [&](double height) {
    std::vector<LabelledBox> boxes = wing;
    boxes.push_back(box("g", {4, 0, 0}, {10, 2, height}));
    boxes.push_back(box("s", {4, 0, height}, {10, 2, 5}));
    return check_text(g, boxes, {10, 2, 5});
  };
  const auto ok = with_ground(2);
  EXPECT_TRUE(ok.derivable) << ok.mismatch;
  const auto bad = with_ground(3);
  EXPECT_FALSE(bad.derivable);
  EXPECT_NE(bad.mismatch.find("at h (4:1), split(z)"), std::string::npos) << bad.mismatch;
  EXPECT_NE(bad.mismatch.find("cuts at z = 0, 3, 5"), std::string::npos) << bad.mismatch;
}

TEST(CheckSplit, AbsoluteSizesLeaveSpaceAtTheEndOrShrink) {
  // 2 + 3 on 10: the last 5 m are empty.
  const std::string g = "p --> split(x){ 2 : I(a) | 3 : I(b) }";
  EXPECT_TRUE(check_text(g, {box("a", {0, 0, 0}, {2, 1, 1}), box("b", {2, 0, 0}, {5, 1, 1})}, {10, 1, 1}).derivable);
  EXPECT_FALSE(check_text(g, {box("a", {0, 0, 0}, {2, 1, 1}), box("b", {2, 0, 0}, {6, 1, 1})}, {10, 1, 1}).derivable);
  // On 4 m they shrink to 1.6 and 2.4, and a relative part gets nothing.
  const std::string h = "p --> split(x){ 2 : I(a) | ~1 : I(c) | 3 : I(b) }";
  EXPECT_TRUE(check_text(h, {box("a", {0, 0, 0}, {1.6, 1, 1}), box("b", {1.6, 0, 0}, {4, 1, 1})}, {4, 1, 1}).derivable);
  EXPECT_FALSE(check_text(h, {box("a", {0, 0, 0}, {2, 1, 1}), box("b", {2, 0, 0}, {4, 1, 1})}, {4, 1, 1}).derivable);
}

TEST(CheckSplit, EmptyPartsMayEndAnywhereInEmptySpace) {
  // Two nils in a row: the boundary between them touches no box.
  const std::string g = "p --> split(x){ ~1 : I(a) | ~1 : nil | ~2 : nil | ~1 : I(b) }";
  EXPECT_TRUE(check_text(g, {box("a", {0, 0, 0}, {2, 1, 1}), box("b", {8, 0, 0}, {10, 1, 1})}, {10, 1, 1}).derivable);
  EXPECT_FALSE(check_text(g, {box("a", {0, 0, 0}, {2, 1, 1}), box("b", {7, 0, 0}, {10, 1, 1})}, {10, 1, 1}).derivable);
}

TEST(CheckSplit, RandomSizesAreReportedInTheWitness) {
  const std::string g = "p --> split(z){ ~(rand(0.75, 1.25)) : I(r) | ~2 : nil }";
  const auto r = check_text(g, {box("r", {0, 0, 0}, {1, 1, 3})}, {1, 1, 10});
  ASSERT_TRUE(r.derivable) << r.mismatch;
  // 3 : 7 = 0.857 : 2
  EXPECT_NE(joined(r.witness).find("part 1: 0.857143 (~rand(0.75, 1.25))"), std::string::npos) << joined(r.witness);
  EXPECT_FALSE(check_text(g, {box("r", {0, 0, 0}, {1, 1, 5})}, {1, 1, 10}).derivable);
}

TEST(CheckRepeat, TileCountsFollowDerive) {
  const std::string g = "p --> repeat(x, 1){ I(t) }";
  std::vector<LabelledBox> four;
  for (int i = 0; i < 4; ++i) four.push_back(box("t", {0.875 * i, 0, 0}, {0.875 * (i + 1), 1, 1}));
  EXPECT_TRUE(check_text(g, four, {3.5, 1, 1}).derivable);
  std::vector<LabelledBox> three;
  for (int i = 0; i < 3; ++i) three.push_back(box("t", {3.5 / 3 * i, 0, 0}, {3.5 / 3 * (i + 1), 1, 1}));
  const auto r = check_text(g, three, {3.5, 1, 1});
  EXPECT_FALSE(r.derivable);
  EXPECT_NE(r.mismatch.find("repeat(x)"), std::string::npos) << r.mismatch;
  // A random tile size allows every count it can give.
  EXPECT_TRUE(check_text("p --> repeat(x, rand(1, 2)){ I(t) }", three, {3.5, 1, 1}).derivable);
  EXPECT_TRUE(check_text("p --> repeatN(x, randint(2, 5)){ I(t) }", three, {3.5, 1, 1}).derivable);
  EXPECT_FALSE(check_text("p --> repeatN(x, randint(4, 5)){ I(t) }", three, {3.5, 1, 1}).derivable);
}

TEST(CheckOperations, TransformsFacesAndTurnsAgreeWithDerive) {
  const char* grammars[] = {
      "p --> S(~0.5, ~1, 2){ T(1, 0, ~0.5){ I(r) } }",
      "p --> R(z, 0.3){ I(r) }",
      "p --> R(z, pi/2){ split(x){ ~1 : I(a) | ~3 : I(b) } }",
      "p --> comp(f){ top : I(t) | front : I(f) | left : split(x){ ~1 : I(a) | ~1 : nil } }",
      "p --> colour(red)",
      "p --> q(randint(1, 3))\nq(n) : n > 1 --> split(y){ ~1 : I(a) | ~(n-1) : q(n-1) }\nq(n) : n <= 1 --> I(b)",
  };
  for (const char* text : grammars) {
    const Grammar g = parse_grammar(text, "test.grm");
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      DeriveOptions o;
      o.seed = seed;
      o.size = glm::dvec3(4, 6, 3);
      const CheckedExample e = example_of(derive(g, o));
      const auto r = check_example(g, e.boxes, e.size, {});
      EXPECT_TRUE(r.derivable) << text << "\n" << r.mismatch;
    }
  }
}

TEST(CheckSplit, PartsMayEndInEmptySpaceAboveTheirBoxes) {
  // The plot's part q ends at z = 5, above both of its boxes: no box face
  // marks that boundary, only the sizes inside q do.
  const std::string g =
      "p --> split(z){ ~1 : q | ~1 : nil }\n"
      "q --> split(x){ ~1 : split(z){ ~1 : I(a) | ~1 : nil } | ~1 : split(z){ ~3 : I(b) | ~1 : nil } }";
  const auto ok = check_text(g, {box("a", {0, 0, 0}, {2, 1, 2.5}), box("b", {2, 0, 0}, {4, 1, 3.75})}, {4, 1, 10});
  EXPECT_TRUE(ok.derivable) << ok.mismatch;
  // b at 4 would need q to end at 16/3 while a needs 5.
  EXPECT_FALSE(check_text(g, {box("a", {0, 0, 0}, {2, 1, 2.5}), box("b", {2, 0, 0}, {4, 1, 4})}, {4, 1, 10}).derivable);
  // The same with a random height, and with tiles along the open axis.
  const std::string h =
      "p --> split(z){ ~rand(0.5, 2) : q | ~1 : nil }\n"
      "q --> repeatN(z, 2){ split(z){ ~1 : I(a) | ~1 : nil } }";
  EXPECT_TRUE(check_text(h, {box("a", {0, 0, 0}, {1, 1, 1}), box("a", {0, 0, 2}, {1, 1, 3})}, {1, 1, 8}).derivable);
  EXPECT_FALSE(
      check_text(h, {box("a", {0, 0, 0}, {1, 1, 1}), box("a", {0, 0, 2.5}, {1, 1, 3.5})}, {1, 1, 8}).derivable);
}

TEST(CheckOperations, RandomConstantsAreTriedOrSolvedFor) {
  // Few values: tried one by one; continuous: solved from the first split.
  for (const char* text : {"w = randint(1, 3)\np --> split(x){ w : I(a) | ~1 : I(b) }",
                           "w = rand(0.5, 2.5)\np --> split(x){ w : I(a) | ~1 : I(b) | w : I(a) }"}) {
    const Grammar g = parse_grammar(text, "test.grm");
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      DeriveOptions o;
      o.seed = seed;
      o.size = glm::dvec3(8, 1, 1);
      const CheckedExample e = example_of(derive(g, o));
      const auto r = check_example(g, e.boxes, e.size, {});
      EXPECT_TRUE(r.derivable) << text << "\n" << r.mismatch;
    }
  }
  // A width outside rand(0.5, 2.5), and two widths that differ, are not derivable.
  const std::string g = "w = rand(0.5, 2.5)\np --> split(x){ w : I(a) | ~1 : I(b) | w : I(a) }";
  EXPECT_FALSE(
      check_text(g, {box("a", {0, 0, 0}, {3, 1, 1}), box("b", {3, 0, 0}, {5, 1, 1}), box("a", {5, 0, 0}, {8, 1, 1})},
                 {8, 1, 1})
          .derivable);
  EXPECT_FALSE(
      check_text(g, {box("a", {0, 0, 0}, {1, 1, 1}), box("b", {1, 0, 0}, {6, 1, 1}), box("a", {6, 0, 0}, {8, 1, 1})},
                 {8, 1, 1})
          .derivable);
}

TEST(CheckOperations, ContinuousRandomArgumentsAreSolvedFor) {
  const std::string g = "p --> b(rand(0.2, 0.8))\nb(h) --> split(z){ ~h : I(r) | ~(1-h) : nil }";
  const auto r = check_text(g, {box("r", {0, 0, 0}, {1, 1, 4})}, {1, 1, 10});
  ASSERT_TRUE(r.derivable) << r.mismatch;
  EXPECT_NE(joined(r.witness).find("h = 0.4 (rand(0.2, 0.8)"), std::string::npos) << joined(r.witness);
  EXPECT_FALSE(check_text(g, {box("r", {0, 0, 0}, {1, 1, 9})}, {1, 1, 10}).derivable);
}

TEST(CheckOperations, SizeIsReadFromTheScopeBeingMatched) {
  // Tiers of 3 m, as many as the plot's height holds: two on a plot 6 m
  // high, so two tiers of 2 m and one of 2 m are not its buildings.
  const std::string g =
      "p --> t(round(size(z) / 3))\nt(n) : n > 0 --> split(z){ 3 : I(r) | ~1 : t(n - 1) }\nt(n) : n <= 0 --> nil";
  const auto r = check_text(g, {box("r", {0, 0, 0}, {1, 1, 3}), box("r", {0, 0, 3}, {1, 1, 6})}, {1, 1, 6});
  ASSERT_TRUE(r.derivable) << r.mismatch;
  EXPECT_FALSE(check_text(g,
                          {box("r", {0, 0, 0}, {1, 1, 2}), box("r", {0, 0, 2}, {1, 1, 4}), box("r", {0, 0, 4}, {1, 1, 6})},
                          {1, 1, 6})
                   .derivable);
  // In a split's sizes too: a quarter of whatever scope it splits.
  const std::string quarter = "p --> split(x){ ~1 : q | ~1 : q }\nq --> split(x){ size(x) / 4 : I(a) | ~1 : nil }";
  EXPECT_TRUE(check_text(quarter, {box("a", {0, 0, 0}, {1, 1, 1}), box("a", {4, 0, 0}, {5, 1, 1})}, {8, 1, 1}).derivable);
  EXPECT_FALSE(check_text(quarter, {box("a", {0, 0, 0}, {2, 1, 1}), box("a", {4, 0, 0}, {6, 1, 1})}, {8, 1, 1}).derivable);
}

TEST(CheckOperations, WhatCannotBeCheckedIsSaid) {
  const auto r = check_text("p --> T(rand(0, 1), 0, 0){ I(r) }", {box("r", {0.5, 0, 0}, {1.5, 1, 1})}, {1, 1, 1});
  EXPECT_FALSE(r.derivable);
  EXPECT_NE(r.mismatch.find("cannot check: a T offset is random"), std::string::npos) << r.mismatch;
}

TEST(CheckOperations, ChoicesAreTriedInOrderAndReported) {
  const std::string g = "p --> I(a) : 0.5\np --> I(b) : 0.5\n";
  const auto r = check_text(g, {box("b", {0, 0, 0}, {1, 1, 1})}, {1, 1, 1});
  ASSERT_TRUE(r.derivable) << r.mismatch;
  EXPECT_NE(joined(r.witness).find("p: alternative 2 of 2 (I(b) at 2:7)"), std::string::npos) << joined(r.witness);
  // A priority of 0 never wins.
  EXPECT_FALSE(check_text("p --> I(a) : 0\np --> I(b) : 1\n", {box("a", {0, 0, 0}, {1, 1, 1})}, {1, 1, 1}).derivable);
}

// The fewest matching steps (CheckOptions::max_steps) with which the
// example still checks, or 0 when it does not check at all.
std::uint64_t fewest_steps(const Grammar& g, const std::vector<LabelledBox>& boxes, glm::dvec3 size, bool learned) {
  CheckOptions o;
  o.learned_order = learned;
  auto derivable = [&](std::uint64_t steps) {
    o.max_steps = steps;
    try {
      return check_example(g, boxes, size, o).derivable;
    } catch (const Error&) {
      return false;
    }
  };
  std::uint64_t lo = 0, hi = 100'000;
  if (!derivable(hi)) return 0;
  while (hi - lo > 1) {
    const std::uint64_t mid = (lo + hi) / 2;
    (derivable(mid) ? hi : lo) = mid;
  }
  return hi;
}

TEST(CheckOperations, ALearnedOrderTriesFirstTheAlternativeThatMatchedMost) {
  // Twenty cells, each a plain box: the first alternative, a stack, is
  // tried and fails at every cell in the written order.
  const Grammar g = parse_grammar(
      "p --> repeat(x, 1){ cell }\n"
      "cell --> split(z){ ~1 : I(a) | ~1 : split(z){ ~1 : I(a) | ~1 : I(a) } } : 1\n"
      "cell --> I(a) : 1\n",
      "test.grm");
  std::vector<LabelledBox> boxes;
  for (int i = 0; i < 20; ++i) boxes.push_back(box("a", {i, 0, 0}, {i + 1, 1, 1}));
  const glm::dvec3 size{20, 1, 1};
  const std::uint64_t written = fewest_steps(g, boxes, size, false);
  const std::uint64_t learned = fewest_steps(g, boxes, size, true);
  ASSERT_GT(written, 0u);
  ASSERT_GT(learned, 0u);
  // Once the second alternative has matched, it is tried first.
  EXPECT_LT(learned, written);
  EXPECT_LE(learned * 3, written * 2) << "written " << written << ", learned " << learned;
  // The written order stays what a witness reports.
  CheckOptions o;
  const CheckResult r = check_example(g, boxes, size, o);
  ASSERT_TRUE(r.derivable) << r.mismatch;
  EXPECT_NE(joined(r.witness).find("alternative 2 of 2"), std::string::npos) << joined(r.witness);
}

TEST(CheckOperations, AnAnswerOnlyCheckKeepsNoRecordAndGivesTheSameAnswer) {
  const Grammar g = read_grammar_file(VERN_SOURCE_DIR "/data/grammars/modern_houses.grm");
  CheckOptions full, answer;
  answer.answer_only = true;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    CheckedExample e = derive_example(g, seed);
    const CheckResult r = check_example(g, e.boxes, e.size, full);
    const CheckResult a = check_example(g, e.boxes, e.size, answer);
    ASSERT_TRUE(r.derivable) << r.mismatch;
    EXPECT_FALSE(r.parts.empty());
    EXPECT_TRUE(a.derivable) << a.mismatch;
    EXPECT_TRUE(a.parts.empty());
    EXPECT_TRUE(a.steps.empty());
    EXPECT_TRUE(a.witness.empty());
    // A box moved: no derivation either way.
    ASSERT_TRUE(move_box(e, e.boxes.size() / 2));
    EXPECT_EQ(check_example(g, e.boxes, e.size, answer).derivable, check_example(g, e.boxes, e.size, full).derivable);
  }
}

TEST(CheckOperations, TheStepLimitIsAnError) {
  const Grammar g = read_grammar_file(VERN_SOURCE_DIR "/data/grammars/garage.grm");
  const CheckedExample e = derive_example(g, 1);
  CheckOptions o;
  o.max_steps = 3;
  try {
    check_example(g, e.boxes, e.size, o);
    FAIL() << "expected a Limit error";
  } catch (const Error& err) {
    EXPECT_EQ(err.kind(), ErrorKind::Limit);
    EXPECT_NE(std::string(err.what()).find("max_steps"), std::string::npos);
  }
}

// ---- limits: what derive() refuses, check refuses at the same place ----

// The error check_text's grammar ("test.grm") gives, with its kind.
std::pair<ErrorKind, std::string> refusal(const std::string& grammar, const std::vector<LabelledBox>& boxes,
                                          glm::dvec3 size, std::uint64_t max_steps = 10'000'000) {
  CheckOptions o;
  o.max_steps = max_steps;
  try {
    const CheckResult r = check_example(parse_grammar(grammar, "test.grm"), boxes, size, o);
    return {ErrorKind::Internal, "no error; " + (r.derivable ? std::string("derivable") : r.mismatch)};
  } catch (const Error& e) {
    return {e.kind(), e.what()};
  }
}

const std::vector<LabelledBox> kTwoTiles = {box("t", {0, 0, 0}, {1, 1, 1}), box("t", {1, 0, 0}, {2, 1, 1})};

TEST(CheckLimits, ATileSizeNeverAboveZeroIsAnInputError) {
  auto [kind, what] = refusal("p --> repeat(x, 0){ I(t) }", kTwoTiles, {2, 1, 1});
  EXPECT_EQ(kind, ErrorKind::Input) << what;
  EXPECT_EQ(what.rfind("test.grm:1:17: error: the tile size of repeat is 0", 0), 0u) << what;
  EXPECT_NE(what.find("\n  rule chain: p\n  hint: "), std::string::npos) << what;
  std::tie(kind, what) = refusal("p --> repeat(x, rand(-2, -1)){ I(t) }", kTwoTiles, {2, 1, 1});
  EXPECT_EQ(kind, ErrorKind::Input) << what;
  EXPECT_EQ(what.rfind("test.grm:1:17: error: the tile size of repeat, rand(-2, -1), is never > 0", 0), 0u) << what;
}

TEST(CheckLimits, MoreTilesThanMatchingStepsAreRefusedAtTheRepeat) {
  // Each tile is matched once: a repeat of more tiles than the steps
  // allowed cannot be checked, and is refused before any tile is laid out.
  for (const char* g : {"p --> repeat(x, 1e-12){ I(t) }", "p --> repeat(x, 1e-19){ I(t) }",
                        "p --> repeat(x, 1e-320){ I(t) }", "p --> repeat(x, rand(1e-13, 1e-12)){ I(t) }"}) {
    const auto [kind, what] = refusal(g, kTwoTiles, {2, 1, 1});
    EXPECT_EQ(kind, ErrorKind::Limit) << g << "\n" << what;
    EXPECT_EQ(what.rfind("test.grm:1:7: error: repeat would make ", 0), 0u) << what;
    EXPECT_NE(what.find("more than check's limit of 10000000 matching steps"), std::string::npos) << what;
    EXPECT_NE(what.find("--max-steps"), std::string::npos) << what;
  }
  for (const char* g : {"p --> repeatN(x, 1e12){ I(t) }", "p --> repeatN(x, 1e19){ I(t) }",
                        "p --> repeatN(x, rand(1e19, 1.0000000000000002e19)){ I(t) }"}) {
    const auto [kind, what] = refusal(g, kTwoTiles, {2, 1, 1});
    EXPECT_EQ(kind, ErrorKind::Limit) << g << "\n" << what;
    EXPECT_EQ(what.rfind("test.grm:1:18: error: repeatN asks for 1e+", 0), 0u) << what;
  }
  // The limit is the step limit, whatever it is set to.
  const auto [kind, what] = refusal("p --> S(1, 1, 1){ repeatN(x, 150){ I(t) } }", kTwoTiles, {2, 1, 1}, 100);
  EXPECT_EQ(kind, ErrorKind::Limit) << what;
  EXPECT_EQ(what.rfind("test.grm:1:30: error: repeatN asks for 150 tiles, more than check's limit of 100", 0), 0u)
      << what;
  EXPECT_NE(what.find("\n  rule chain: p\n"), std::string::npos) << what;
}

TEST(CheckLimits, CountsWithinTheLimitAreTriedFirst) {
  // Tile sizes down to 0.0019 m give up to 1053 tiles on 2 m, past a limit
  // of 1000 steps; the two tiles of the example come first and match.
  const auto [kind, what] = refusal("p --> repeat(x, rand(0.0019, 1)){ I(t) }", kTwoTiles, {2, 1, 1}, 1000);
  EXPECT_EQ(kind, ErrorKind::Internal);
  EXPECT_EQ(what, "no error; derivable");
}

TEST(CheckLimits, ManyTilesWithinTheLimitTakeNoMemoryPerTile) {
  // 2e12 tiles, allowed by a limit raised to 1e15 steps: the boxes cross
  // the tiles' boundaries, which is found from the boxes alone.
  const auto [kind, what] = refusal("p --> repeat(x, 1e-12){ I(t) }", kTwoTiles, {2, 1, 1}, 1'000'000'000'000'000);
  EXPECT_EQ(kind, ErrorKind::Internal) << what;
  EXPECT_NE(what.find("boxes cross the tile boundaries of 2e+12 tiles"), std::string::npos) << what;
}

// A rule chain names the rules a check is inside, with their arguments as
// far as the example has pinned them down. The place of the count is its
// expression's operator, the '*', as in generate's message.
TEST(CheckLimits, TheRuleChainNamesTheCallsAndTheirArguments) {
  const auto [kind, what] = refusal(
      "p --> q(2, rand(1, 5))\nq(a, b) --> r(a * 2)\nr(n) --> repeatN(x, 1e12 * n){ I(t) }", kTwoTiles, {2, 1, 1});
  EXPECT_EQ(kind, ErrorKind::Limit) << what;
  EXPECT_EQ(what.rfind("test.grm:3:26: error: repeatN asks for 4e+12 tiles", 0), 0u) << what;
  EXPECT_NE(what.find("\n  rule chain: p > q(2, ?) > r(4)\n"), std::string::npos) << what;
}

// ---- placements: contents that leave their part's slice ----

// A pinwheel as inference writes it (placements.hpp): cuts at the parts'
// min corners, S(...) for the three parts that reach past their piece.
const char* kPinwheel =
    "pinwheel --> split(x){\n"
    "    ~1 : split(y){ ~1 : S(2, 1, 1){ I(a) } | ~2 : I(d) } |\n"
    "    ~1 : split(y){ ~1 : nil | ~1 : I(e) | ~1 : S(2, 1, 1){ I(c) } } |\n"
    "    ~1 : S(1, 2, 1){ I(b) } }\n";

std::vector<LabelledBox> pinwheel_boxes(glm::dvec3 at = glm::dvec3(0.0)) {
  return {box("a", at + glm::dvec3(0, 0, 0), at + glm::dvec3(2, 1, 1)),
          box("b", at + glm::dvec3(2, 0, 0), at + glm::dvec3(3, 2, 1)),
          box("c", at + glm::dvec3(1, 2, 0), at + glm::dvec3(3, 3, 1)),
          box("d", at + glm::dvec3(0, 1, 0), at + glm::dvec3(1, 3, 1)),
          box("e", at + glm::dvec3(1, 1, 0), at + glm::dvec3(2, 2, 1))};
}

TEST(CheckPlacements, APinwheelOfPlacementsIsDerivedAndCompared) {
  // No cut of the example's boxes lies at x = 1 or 2, where the split
  // puts its boundaries: the split alone cannot be followed, but nothing
  // below it is random, so it is derived and compared.
  const auto r = check_text(kPinwheel, pinwheel_boxes(), {3, 3, 1});
  EXPECT_TRUE(r.derivable) << r.mismatch;

  // A part moved, or one missing: not derivable, and the message says
  // which box differs.
  std::vector<LabelledBox> moved = pinwheel_boxes();
  moved[2].min.x += 0.25;
  const auto m = check_text(kPinwheel, moved, {3, 3, 1});
  EXPECT_FALSE(m.derivable);
  EXPECT_NE(m.mismatch.find("split(x) at 1:14 on x 0..3, y 0..3, z 0..1: derived here (nothing below is random), "
                            "it gives 'c' (x 1..3, y 2..3, z 0..1), which the example does not have"),
            std::string::npos)
      << m.mismatch;
  std::vector<LabelledBox> four = pinwheel_boxes();
  four.pop_back();
  const auto f = check_text(kPinwheel, four, {3, 3, 1});
  EXPECT_FALSE(f.derivable);
  EXPECT_NE(f.mismatch.find("more than 4 terminals"), std::string::npos) << f.mismatch;
}

TEST(CheckPlacements, APinwheelInsideABuildingAndAmongAlternatives) {
  // Only the pinwheel is derived; the block around it, and the choice
  // between two ways to place it, are matched as before.
  const std::string block = "block --> split(x){ ~3 : split(z){ ~1 : wheel | ~2 : I(rect) } | ~2 : I(tower) }\n";
  const std::string first = "wheel --> pinwheel : 1\n";
  const std::string second = "wheel --> split(y){ ~1 : pinwheel | ~1 : nil } : 1\n";
  const std::string g = block + first + second + kPinwheel;
  std::vector<LabelledBox> boxes = pinwheel_boxes();
  boxes.push_back(box("rect", {0, 0, 1}, {3, 3, 3}));
  boxes.push_back(box("tower", {3, 0, 0}, {5, 3, 3}));
  const auto r = check_text(g, boxes, {5, 3, 3});
  ASSERT_TRUE(r.derivable) << r.mismatch;
  EXPECT_NE(joined(r.witness).find("wheel: alternative 1 of 2"), std::string::npos) << joined(r.witness);

  // The other alternative, on a larger block: what derive() makes with it
  // (the placed parts keep their sizes, the others stretch).
  const Grammar only_second = parse_grammar(block + second + kPinwheel, "test.grm");
  DeriveOptions o;
  o.size = glm::dvec3(10, 12, 3);
  const CheckedExample e = example_of(derive(only_second, o));
  ASSERT_EQ(e.boxes.size(), 7u);
  const auto other = check_example(parse_grammar(g, "test.grm"), e.boxes, e.size, {});
  ASSERT_TRUE(other.derivable) << other.mismatch;
  EXPECT_NE(joined(other.witness).find("wheel: alternative 2 of 2"), std::string::npos) << joined(other.witness);
  // ... and the first alternative alone does not derive it.
  EXPECT_FALSE(check_example(parse_grammar(block + first + kPinwheel, "test.grm"), e.boxes, e.size, {}).derivable);
}

TEST(CheckPlacements, RandomPlacementsAreStillNotChecked) {
  // Below a random size nothing is derived: the matcher's answer stands.
  const auto r = check_text("p --> split(x){ ~1 : S(rand(1, 2), 1, 1){ I(a) } | ~1 : I(b) }",
                            {box("a", {0, 0, 0}, {1.5, 1, 1}), box("b", {1, 0, 0}, {2, 1, 1})}, {2, 1, 1});
  EXPECT_FALSE(r.derivable);
  EXPECT_EQ(r.mismatch.find("derived here"), std::string::npos) << r.mismatch;
}

// ---- the bundled grammars ----

class CheckBundled : public ::testing::TestWithParam<std::string> {};

TEST_P(CheckBundled, DerivedExamplesAreDerivable) {
  const Grammar g = read_grammar_file(GetParam());
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const CheckedExample e = derive_example(g, seed);
    const auto r = check_example(g, e.boxes, e.size, {});
    EXPECT_TRUE(r.derivable) << "seed " << seed << ": " << r.mismatch;
    EXPECT_FALSE(r.witness.empty());
  }
}

TEST_P(CheckBundled, PerturbedExamplesAreNot) {
  const Grammar g = read_grammar_file(GetParam());
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const CheckedExample original = derive_example(g, seed);
    ASSERT_FALSE(original.boxes.empty());
    auto expect_rejected = [&](const CheckedExample& e, const char* what) {
      const auto r = check_example(g, e.boxes, e.size, {});
      EXPECT_FALSE(r.derivable) << what << ", seed " << seed;
      EXPECT_TRUE(names_a_rule(g, r.mismatch)) << what << ", seed " << seed << ": " << r.mismatch;
    };
    CheckedExample moved = original;
    ASSERT_TRUE(move_box(moved, 0));
    expect_rejected(moved, "a box moved by 0.3 m");

    CheckedExample relabelled = original;
    relabelled.boxes[relabelled.boxes.size() / 2].label = "bogus";
    expect_rejected(relabelled, "a box relabelled");

    CheckedExample deleted = original;
    deleted.boxes.erase(deleted.boxes.begin());
    expect_rejected(deleted, "a box deleted");

    // A grammar without nil (terrace) fills its scope: nowhere to add a box.
    CheckedExample added = original;
    const bool has_nil = [&] {
      for (NodeId id = 0; id < g.node_count(); ++id)
        if (std::holds_alternative<Nil>(g.op(id))) return true;
      return false;
    }();
    if (!has_nil) continue;
    ASSERT_TRUE(add_box_in_empty_space(added));
    expect_rejected(added, "a box added in empty space");
  }
}

INSTANTIATE_TEST_SUITE_P(CheckGrammars, CheckBundled, ::testing::ValuesIn(test::bundled_grammars()),
                         [](const auto& p) { return stem(p.param); });

TEST(CheckGarage, AGarageTallerThanTheGrammarAllowsIsRejected) {
  for (const char* name : {"garage", "garage_machine"}) {
    const Grammar g = read_grammar_file(std::string(VERN_SOURCE_DIR "/data/grammars/") + name + ".grm");
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      CheckedExample e = derive_example(g, seed);
      // The garage is the rect that does not reach the top third.
      auto garage = std::find_if(e.boxes.begin(), e.boxes.end(),
                                 [&](const LabelledBox& b) { return b.label == "rect" && b.max.z < e.size.z / 2; });
      ASSERT_NE(garage, e.boxes.end());
      garage->max.z = e.size.z * 0.6;  // the grammar allows 0.27 to 0.38 of the height
      const auto r = check_example(g, e.boxes, e.size, {});
      EXPECT_FALSE(r.derivable);
      EXPECT_NE(r.mismatch.find("at garage"), std::string::npos) << r.mismatch;
      EXPECT_NE(r.mismatch.find("split(z)"), std::string::npos) << r.mismatch;
    }
  }
}

TEST(CheckGarage, TheWitnessNamesTheAlternativeAndTheGarageHeight) {
  const Grammar g = read_grammar_file(VERN_SOURCE_DIR "/data/grammars/garage_machine.grm");
  const CheckedExample e = derive_example(g, 1);
  const auto r = check_example(g, e.boxes, e.size, {});
  ASSERT_TRUE(r.derivable) << r.mismatch;
  const std::string w = joined(r.witness);
  EXPECT_NE(w.find("plot: alternative "), std::string::npos) << w;
  EXPECT_NE(w.find("garage, split(z) at 26:12, part 1: "), std::string::npos) << w;
}

TEST(CheckBundledAcross, AnExampleOfOneGrammarDoesNotFitAnother) {
  const auto files = test::bundled_grammars();
  for (const auto& a : files) {
    const CheckedExample e = derive_example(read_grammar_file(a), 1);
    for (const auto& b : files) {
      if (a == b) continue;
      const auto r = check_example(read_grammar_file(b), e.boxes, e.size, {});
      EXPECT_FALSE(r.derivable) << stem(a) << " checked against " << stem(b);
      EXPECT_FALSE(r.mismatch.empty());
    }
  }
}

}  // namespace
}  // namespace vern

namespace vern {
namespace {

// The lengths a derivation gave its random parts, lined up by place: the
// same rule run at two places is two places, one place in two examples is
// one (joint_sizes.hpp reads sizes that vary together this way).
TEST(CheckMatchedParts, EachRandomPartIsMeasuredAtItsOwnPlace) {
  const Grammar g = parse_grammar(R"(
@scope 12, 8, 10
b --> split(x){ ~1 : col | ~1 : col }
col --> split(z){ ~rand(1, 9) : I(rect) | ~rand(1, 9) : nil }
)");
  std::vector<std::vector<MatchedPart>> seen;
  for (std::uint64_t seed : {1, 2}) {
    const CheckedExample e = derive_example(g, seed);
    const CheckResult r = check_example(g, e.boxes, e.size);
    ASSERT_TRUE(r.derivable) << r.mismatch;
    ASSERT_EQ(r.parts.size(), 4u);  // two parts in each of two columns
    for (const MatchedPart& m : r.parts) EXPECT_EQ(m.split, g.rules[1].body);
    // Each column's two parts fill its 10 m; the rect is as tall as its box.
    for (std::size_t column = 0; column < 2; ++column) {
      const MatchedPart& rect = r.parts[2 * column];
      const MatchedPart& air = r.parts[2 * column + 1];
      EXPECT_EQ(rect.path, air.path);
      EXPECT_EQ(rect.part, 0u);
      EXPECT_EQ(air.part, 1u);
      EXPECT_NEAR(rect.length + air.length, 10.0, 1e-6);
      const double x = 6.0 * static_cast<double>(column);
      const auto top =
          std::ranges::find_if(e.boxes, [&](const LabelledBox& b) { return std::abs(b.min.x - x) < 1e-6; });
      ASSERT_NE(top, e.boxes.end());
      EXPECT_NEAR(rect.length, top->max.z, 1e-6);
    }
    EXPECT_NE(r.parts[0].path, r.parts[2].path);
    seen.push_back(r.parts);
  }
  EXPECT_EQ(seen[0][0].path, seen[1][0].path);
  EXPECT_EQ(seen[0][2].path, seen[1][2].path);
  EXPECT_NE(seen[0][0].length, seen[1][0].length);
}

}  // namespace
}  // namespace vern
