// Groups of parts that no straight cut separates (a pinwheel), end to end:
// infer places them with S(...) at their corners (inverse/split/placements.hpp)
// and warns, the grammar derives the examples exactly, check accepts them,
// and merging several such examples keeps every one derivable.
#include "inverse/split/placements.hpp"

#include <gtest/gtest.h>

#include "forward/derive.hpp"
#include "forward/layout_faults.hpp"
#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "inverse/check/check.hpp"
#include "inverse/infer.hpp"
#include "support/example_helpers.hpp"

namespace vern {
namespace {

using test::part;

// Five boxes around a square, each pushing the next, `scale` times the
// unit pinwheel, from `at`.
std::vector<vern::LabelledBox> pinwheel(double scale = 1, glm::dvec3 at = glm::dvec3(0.0)) {
  auto p = [&](const char* label, glm::dvec3 lo, glm::dvec3 hi) {
    return part(label, at + scale * lo, at + scale * hi);
  };
  return {p("a", {0, 0, 0}, {2, 1, 1}), p("b", {2, 0, 0}, {3, 2, 1}), p("c", {1, 2, 0}, {3, 3, 1}),
          p("d", {0, 1, 0}, {1, 3, 1}), p("e", {1, 1, 0}, {2, 2, 1})};
}

// The grammar as written and read back, as a user gets it.
Grammar reread(const Inference& inferred) { return parse_grammar(write_grammar(inferred.grammar), "inferred.grm"); }

// check, as `check` runs it: the example moved to the origin.
CheckResult check_one(const Grammar& g, const Example& e) {
  return check_example(g, test::translated(e.boxes, -e.min), example_size(e));
}

// Derives g on the example's own plot and compares with its parts.
::testing::AssertionResult derives(const Grammar& g, const Example& e, double tolerance) {
  DeriveOptions o;
  o.size = example_size(e);
  return test::same_boxes(test::translated(e.boxes, -e.min), test::derived_parts(derive(g, o)), tolerance);
}

TEST(Placements, OnePinwheelComesBackExactlyAndChecks) {
  const Example ex = test::example_of(test::numbered(pinwheel(1, {10, -3, 0.5})), "pinwheel.obj");
  const Inference inferred = infer({ex}, {});
  const Grammar g = reread(inferred);
  EXPECT_EQ(write_grammar(inferred.grammar),
            "@scope 3, 3, 1\n"
            "\n"
            "building --> split(x){\n"
            "    ~1 : split(y){ ~1 : S(~2, ~1, ~1){ I(a) } | ~2 : I(d) } |\n"
            "    ~1 : split(y){ ~1 : nil | ~1 : I(e) | ~1 : S(~2, ~1, ~1){ I(c) } } |\n"
            "    ~1 : split(y){ ~2 : I(b) | ~1 : nil } }\n");
  EXPECT_TRUE(derives(g, ex, 2 * inferred.tolerance));
  const CheckResult r = check_one(g, ex);
  EXPECT_TRUE(r.derivable) << r.mismatch;
  ASSERT_EQ(inferred.warnings.size(), 1u);
  EXPECT_EQ(inferred.warnings[0],
            "pinwheel.obj:1:1: warning: no straight cut separates these 5 parts (e.g. a pinwheel): they are placed "
            "with S(...) at their corners: 'a.0' (line 1), 'b.1' (line 2), 'c.2' (line 3), 'd.3' (line 4), "
            "'e.4' (line 5)\n  hint: a placed group is copied as it is, never varied; split one of these parts in "
            "two so that a cut can pass between them");
}

TEST(Placements, NoisyCornersAreSnappedAndTheNumbersStayShort) {
  // Every coordinate off by up to 3e-8 (within the default tolerance of
  // 1e-6 x 3 m): the cuts and S sizes are written as the round numbers.
  std::vector<vern::LabelledBox> boxes = pinwheel();
  const double noise[] = {3e-8, -2e-8, 1e-8, -3e-8, 2e-8};
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    boxes[i].min += glm::dvec3(noise[i], -noise[i], 0);
    boxes[i].max += glm::dvec3(-noise[(i + 1) % 5], noise[(i + 2) % 5], 0);
  }
  const Example ex = test::example_of(test::numbered(boxes));
  const Inference inferred = infer({ex}, {});
  const std::string text = write_grammar(inferred.grammar);
  EXPECT_NE(text.find("~1 : split(y){ ~1 : S(~2, ~1, ~1){ I(a) } | ~2 : I(d) } |"), std::string::npos) << text;
  EXPECT_NE(text.find("~1 : split(y){ ~2 : I(b) | ~1 : nil } }"), std::string::npos) << text;
  EXPECT_TRUE(derives(reread(inferred), ex, 2 * inferred.tolerance));
  EXPECT_TRUE(check_one(reread(inferred), ex).derivable);
}

TEST(Placements, OnlyThePinwheelOfABuildingIsPlaced) {
  // A terrace: a row of three houses, the middle one with a pinwheel of
  // rooms on its ground floor; storeys and roofs above all three.
  std::vector<vern::LabelledBox> boxes;
  for (int house = 0; house < 3; ++house) {
    const double x = 3.0 * house;
    if (house == 1) {
      for (const auto& b : pinwheel(1, {x, 0, 0})) boxes.push_back(b);
    } else {
      boxes.push_back(part("rect", {x, 0, 0}, {x + 3, 3, 1}));
    }
    boxes.push_back(part("rect", {x, 0, 1}, {x + 3, 3, 2}));
    boxes.push_back(part("roof", {x, 0, 2}, {x + 3, 3, 3}));
  }
  const Example ex = test::example_of(test::numbered(boxes), "terrace.obj");
  const Inference inferred = infer({ex}, {});
  const std::string text = write_grammar(inferred.grammar);
  // Two S placements, both in the middle house's ground floor (the two
  // rooms that reach past their pieces; the third placed room falls short
  // of its piece, the rest empty); the rest is cuts.
  std::size_t placements = 0;
  for (std::size_t at = text.find("S("); at != std::string::npos; at = text.find("S(", at + 1)) ++placements;
  EXPECT_EQ(placements, 2u) << text;
  EXPECT_NE(text.find("rectRoofZ --> split(z){ ~2 : repeatN(z, 2){ I(rect) } | ~1 : I(roof) }"), std::string::npos)
      << text;
  const Grammar g = reread(inferred);
  EXPECT_TRUE(derives(g, ex, 2 * inferred.tolerance));
  const CheckResult r = check_one(g, ex);
  EXPECT_TRUE(r.derivable) << r.mismatch;
  ASSERT_EQ(inferred.warnings.size(), 1u);
  EXPECT_NE(inferred.warnings[0].find("terrace.obj:4:1: warning: no straight cut separates these 5 parts"),
            std::string::npos)
      << inferred.warnings[0];
}

TEST(Placements, PinwheelsOfDifferentSizesAreOneStructureThatScalesWithoutOverlaps) {
  // Two buildings: a pinwheel of unit rooms under a slab, and one of rooms
  // one and a half times as large.
  std::vector<Example> examples;
  for (const double scale : {1.0, 1.5}) {
    std::vector<vern::LabelledBox> boxes = pinwheel(scale);
    boxes.push_back(part("rect", {0, 0, scale}, {3 * scale, 3 * scale, scale + 1}));
    examples.push_back(test::example_of(test::numbered(boxes), "pinwheel" + std::to_string(examples.size()) + ".obj"));
  }
  const Inference inferred = infer(examples, {});
  const Grammar g = reread(inferred);
  EXPECT_EQ(inferred.warnings.size(), 2u);
  for (const Example& e : examples) {
    SCOPED_TRACE(e.source);
    const CheckResult r = check_one(g, e);
    EXPECT_TRUE(r.derivable) << r.mismatch << "\n" << write_grammar(inferred.grammar);
  }
  // The placements are shares of their piece, so the two pinwheels are
  // one structure (one alternative, the slab 1 m in both), and on a plot of
  // any size the rooms scale together: no two overlap.
  const std::string text = write_grammar(inferred.grammar);
  EXPECT_FALSE(std::holds_alternative<Choose>(g.op(g.rules[g.start_rule].body))) << text;
  EXPECT_EQ(text.find("S(~2, ~1, ~1){ I(a) }"), text.rfind("S(~2, ~1, ~1){ I(a) }")) << text;
  EXPECT_NE(text.find("1 : I(rect) }"), std::string::npos) << text;
  for (const glm::dvec3 plot : {glm::dvec3(2, 2, 2), glm::dvec3(6, 4, 3), glm::dvec3(9, 9, 2.5)}) {
    DeriveOptions o;
    o.size = plot;
    const LayoutFaults faults = find_faults(derive(g, o));
    EXPECT_TRUE(faults.valid()) << faults.first << "\n" << text;
  }
  // New buildings derive, each with all five parts of one pinwheel.
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    DeriveOptions o;
    o.seed = seed;
    const Derivation d = derive(g, o);
    EXPECT_EQ(d.terminals.size(), 6u) << "seed " << seed;
  }
}

}  // namespace
}  // namespace vern
