// From split trees to operation graphs, and the round trip that matters:
// deriving the graph inferred from an example gives back the example.
#include "inverse/split/split_graph.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <map>
#include <set>

#include "base/error.hpp"
#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "io/obj_writer.hpp"
#include "support/derive_helpers.hpp"
#include "support/example_helpers.hpp"
#include "support/run_command.hpp"

namespace vern {
namespace {

using test::part;

// A grammar whose one rule derives the example's graph.
Grammar grammar_of(const Example& ex, NodeId* root = nullptr) {
  Grammar g;
  const NodeId r = example_graph(g, ex, {default_tolerance(ex)});
  Rule rule;
  rule.label = "example";
  rule.body = r;
  g.rules.push_back(rule);
  if (root != nullptr) *root = r;
  return g;
}

// Derives the example's grammar on a scope of the example's size at the
// origin and compares with the example's parts moved to the origin, within
// a quarter of the tolerance the graph was built with (lengths that differ
// by float noise are one length, which moves a cut by at most that).
::testing::AssertionResult round_trips(const Example& ex) {
  const Grammar g = grammar_of(ex);
  DeriveOptions o;
  o.size = example_size(ex);
  const Derivation d = derive(g, o);
  const double eps = default_tolerance(ex) / 4;
  return test::same_boxes(test::translated(ex.boxes, -ex.min), test::derived_parts(d), eps);
}

double literal(const Size& s) { return s.value.literal().value_or(-1.0); }

TEST(SplitGraph, PartsBecomeASplitWithRelativeSizes) {
  Grammar g;
  const Example ex = test::example_of(
      test::numbered({part("wall", {0, 0, 0}, {1, 1, 1}), part("window", {1, 0, 0}, {3, 1, 1})}));
  const NodeId root = example_graph(g, ex, {1e-9});
  const auto* split = std::get_if<Split>(&g.op(root));
  ASSERT_NE(split, nullptr);
  EXPECT_EQ(split->axis, Expr::axis(Axis::X));
  ASSERT_EQ(split->parts.size(), 2u);
  EXPECT_TRUE(split->parts[0].size.relative);
  EXPECT_EQ(literal(split->parts[0].size), 1.0);
  EXPECT_EQ(literal(split->parts[1].size), 2.0);
  const auto* wall = std::get_if<Primitive>(&g.op(split->parts[0].child));
  const auto* window = std::get_if<Primitive>(&g.op(split->parts[1].child));
  ASSERT_TRUE(wall != nullptr && window != nullptr);
  EXPECT_EQ(g.label(wall->label), "wall");
  EXPECT_EQ(g.label(window->label), "window");
}

TEST(SplitGraph, GapsAreNilAndASinglePartIsItsPrimitive) {
  Grammar g;
  const NodeId root = example_graph(
      g, test::example_of(test::numbered({part("a", {0, 0, 0}, {1, 1, 1}), part("b", {3, 0, 0}, {4, 1, 1})})), {1e-9});
  const auto& split = std::get<Split>(g.op(root));
  ASSERT_EQ(split.parts.size(), 3u);
  EXPECT_TRUE(std::holds_alternative<Nil>(g.op(split.parts[1].child)));
  EXPECT_EQ(literal(split.parts[1].size), 2.0);

  Grammar one;
  const NodeId leaf = example_graph(one, test::example_of({part("roof", {2, 2, 2}, {3, 4, 5})}), {1e-9});
  EXPECT_TRUE(std::holds_alternative<Primitive>(one.op(leaf)));
}

TEST(SplitGraph, EqualSubtreesShareOneNode) {
  // Four equal columns of a rect under a window.
  std::vector<LabelledBox> boxes;
  for (int i = 0; i < 4; ++i) {
    boxes.push_back(part("rect", {i, 0, 0}, {i + 1, 1, 2}));
    boxes.push_back(part("window", {i, 0, 2}, {i + 1, 1, 3}));
  }
  NodeId root = 0;
  const Grammar g = grammar_of(test::example_of(test::numbered(boxes)), &root);
  const auto& split = std::get<Split>(g.op(root));
  ASSERT_EQ(split.parts.size(), 4u);
  for (const SplitPart& p : split.parts) EXPECT_EQ(p.child, split.parts[0].child);
  EXPECT_EQ(g.node_count(), 4u);  // I(rect), I(window), one column, the row
}

// Five boxes around a square, each pushing the next: no straight cut
// separates any of them (as in box_split_test).
std::vector<vern::LabelledBox> pinwheel(glm::dvec3 at = glm::dvec3(0.0)) {
  return {part("a", at + glm::dvec3(0, 0, 0), at + glm::dvec3(2, 1, 1)),
          part("b", at + glm::dvec3(2, 0, 0), at + glm::dvec3(3, 2, 1)),
          part("c", at + glm::dvec3(1, 2, 0), at + glm::dvec3(3, 3, 1)),
          part("d", at + glm::dvec3(0, 1, 0), at + glm::dvec3(1, 3, 1)),
          part("e", at + glm::dvec3(1, 1, 0), at + glm::dvec3(2, 2, 1))};
}

// The operation as written, on one line.
std::string one_line(const Grammar& g, NodeId root) { return write_operation(g, root, {}, {.width = 100000}); }

// How many nodes of each kind the graph below root holds, each once.
std::map<std::string, int> operations_below(const Grammar& g, NodeId root) {
  std::map<std::string, int> count;
  std::set<NodeId> seen;
  std::function<void(NodeId)> visit = [&](NodeId id) {
    if (!seen.insert(id).second) return;
    ++count[operation_name(g.op(id))];
    for (NodeId c : node_children(g.op(id))) visit(c);
  };
  visit(root);
  return count;
}

TEST(SplitGraph, APinwheelIsPlacedWithSAtItsCornersAndWarned) {
  const Example ex = test::example_of(test::numbered(pinwheel()), "pinwheel.obj");
  Grammar g;
  std::vector<std::string> warnings;
  const NodeId root = example_graph(g, ex, {default_tolerance(ex)}, {}, &warnings);
  // Cut along x at the min corners 0, 1, 2: a and d, then e and c, then b.
  // Two parts reach past their piece, twice its length (S(~2, ...)); b
  // falls short of its piece, the rest empty; d and e fill theirs.
  const std::string text = one_line(g, root);
  EXPECT_EQ(text,
            "split(x){ ~1 : split(y){ ~1 : S(~2, ~1, ~1){ I(a) } | ~2 : I(d) } | "
            "~1 : split(y){ ~1 : nil | ~1 : I(e) | ~1 : S(~2, ~1, ~1){ I(c) } } | ~1 : split(y){ ~2 : I(b) | ~1 : nil } }")
      << text;
  EXPECT_TRUE(round_trips(ex));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0],
            "pinwheel.obj:1:1: warning: no straight cut separates these 5 parts (e.g. a pinwheel): they are placed "
            "with S(...) at their corners: 'a.0' (line 1), 'b.1' (line 2), 'c.2' (line 3), 'd.3' (line 4), "
            "'e.4' (line 5)\n  hint: a placed group is copied as it is, never varied; split one of these parts in "
            "two so that a cut can pass between them");

  // Anywhere, in any order of the parts, and with float noise within the
  // tolerance: the boxes come back.
  std::vector<vern::LabelledBox> moved = pinwheel({-4.5, 7, 2});
  std::reverse(moved.begin(), moved.end());
  moved[1].max.x += 1e-9;
  moved[3].min.y -= 1e-9;
  EXPECT_TRUE(round_trips(test::example_of(test::numbered(moved))));
}

TEST(SplitGraph, OnlyThePinwheelInsideABuildingIsPlaced) {
  // A pinwheel on the ground floor of a block, beside a tower and under a
  // roof slab: the rest still splits.
  std::vector<vern::LabelledBox> boxes = pinwheel();
  boxes.push_back(part("tower", {3, 0, 0}, {5, 3, 4}));
  boxes.push_back(part("rect", {0, 0, 1}, {3, 3, 2}));
  boxes.push_back(part("roof", {0, 0, 2}, {3, 3, 3}));
  const Example ex = test::example_of(test::numbered(boxes), "block.obj");
  Grammar g;
  std::vector<std::string> warnings;
  const NodeId root = example_graph(g, ex, {default_tolerance(ex)}, {}, &warnings);
  const auto& outer = std::get<Split>(g.op(root));
  EXPECT_EQ(outer.axis, Expr::axis(Axis::X));
  ASSERT_EQ(outer.parts.size(), 2u);
  EXPECT_TRUE(std::holds_alternative<Primitive>(g.op(outer.parts[1].child)));  // the tower
  const auto& storeys = std::get<Split>(g.op(outer.parts[0].child));
  EXPECT_EQ(storeys.axis, Expr::axis(Axis::Z));
  ASSERT_EQ(storeys.parts.size(), 4u);  // the pinwheel, rect, roof, and the air beside the tower's top
  EXPECT_TRUE(std::holds_alternative<Nil>(g.op(storeys.parts[3].child)));
  // Only the ground floor holds placements: a and c (b falls short of its
  // piece and is cut out of it).
  EXPECT_EQ(operations_below(g, storeys.parts[0].child)["S"], 2);
  EXPECT_EQ(operations_below(g, root)["S"], 2);
  EXPECT_TRUE(round_trips(ex));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("block.obj:1:1: warning: no straight cut separates these 5 parts"), std::string::npos)
      << warnings[0];
}

TEST(SplitGraph, APanelInsideAThickerSpaceIsPlacedToo) {
  // A panel at y = 0 beside a box 1 deep: no cut makes it a part of zero
  // thickness, so it is resized instead, to none of its piece's.
  const Example flat = test::example_of(
      test::numbered({part("panel", {0, 0, 0}, {2, 0, 2}), part("box", {3, 0, 0}, {5, 1, 2})}), "flat.obj");
  Grammar g;
  std::vector<std::string> warnings;
  const NodeId root = example_graph(g, flat, {default_tolerance(flat)}, {}, &warnings);
  EXPECT_EQ(one_line(g, root), "split(x){ ~2 : S(~1, ~0, ~1){ I(panel) } | ~1 : nil | ~2 : I(box) }");
  EXPECT_TRUE(round_trips(flat));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("flat.obj:1:1: warning: part 'panel.0' (line 1) is flat and lies inside a thicker "
                             "empty space, which no straight cut can cut it out of: it is placed with S(...)"),
            std::string::npos)
      << warnings[0];
}

TEST(SplitGraph, TurnedPartsKeepTheirTurnInsideTheirPlacement) {
  const Example ex = test::example_of(test::numbered(pinwheel()));
  std::vector<Orientation> turns(5);
  turns[0] = {QuarterTurn{Axis::Z, 1}};  // a
  Grammar g;
  const SplitTree tree = split_boxes(ex.boxes, {default_tolerance(ex)});
  const NodeId root = split_graph(g, tree, ex.boxes, ex.source, turns, {default_tolerance(ex)});
  EXPECT_NE(one_line(g, root).find("S(~2, ~1, ~1){ R(z, pi / 2){ I(a) } }"), std::string::npos)
      << one_line(g, root);
}

TEST(SplitGraph, PartsThatShareAMinCornerAreStillAnError) {
  // Two panels meeting at a corner, one of them standing inside the
  // group (a third panel behind reaches past it): neither cuts, nor
  // corners, nor faces (comp_faces.hpp) separate them.
  const Example ex = test::example_of(test::numbered({part("wall", {0, 0, 0}, {1, 0, 1}),
                                                      part("side", {0, 0, 0}, {0, 1, 1}),
                                                      part("back", {-1, 1, 0}, {1, 1, 1})}),
                                      "corner.obj");
  Grammar g;
  try {
    example_graph(g, ex, {default_tolerance(ex)});
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Input);
    EXPECT_NE(std::string(e.what()).find("corner.obj:1:1: error: these 3 parts cannot be separated by straight cuts "
                                         "(e.g. a pinwheel): 'wall.0' (line 1), 'side.1' (line 2), 'back.2' (line 3)"),
              std::string::npos)
        << e.what();
  }
}

// Every bundled grammar, several seeds: derive, infer the example's graph,
// derive that, compare. (Rotations turn meshes, not boxes: R(z, k pi/2)
// keeps a terminal's box.)
TEST(SplitGraph, DerivedBuildingsRoundTripThroughTheirInferredGraphs) {
  const std::vector<std::pair<std::string, int>> grammars = {
      {"garage.grm", 6},        {"garage_machine.grm", 6}, {"cube_skeleton.grm", 1},
      {"better_roofs.grm", 6},  {"modern_houses.grm", 6},  {"skyscraper_city.grm", 2}};
  for (const auto& [name, seeds] : grammars) {
    const Grammar g = read_grammar_file(VERN_SOURCE_DIR "/data/grammars/" + name);
    for (int seed = 1; seed <= seeds; ++seed) {
      SCOPED_TRACE(name + " seed " + std::to_string(seed));
      DeriveOptions o;
      o.seed = static_cast<std::uint64_t>(seed);
      const Derivation d = derive(g, o);
      ASSERT_FALSE(d.terminals.empty());
      const Example ex = test::example_of(test::derived_parts(d), name);
      EXPECT_TRUE(round_trips(ex));
    }
  }
}

TEST(SplitGraph, PartsEqualButForFloatNoiseAreOneNode) {
  // Six columns whose widths a derivation summed in different orders
  // (1e-15 apart) or a modelling tool wrote in single precision (1e-7
  // apart): one length, one column node, so the row can become a repeat.
  std::vector<LabelledBox> boxes;
  double x = 0;
  for (int i = 0; i < 6; ++i) {
    const double w = 3.4112803 + (i % 2 ? 1e-15 : -2e-7);
    boxes.push_back(part("sill", {x, 0, 0}, {x + w, 1, 1}));
    boxes.push_back(part("pier", {x, 0, 1}, {x + 0.7, 1, 4}));
    boxes.push_back(part("bay", {x + 0.7, 0, 1}, {x + w, 1, 4}));
    x += w;
  }
  const Example ex = test::example_of(test::numbered(boxes));
  Grammar g;
  const NodeId root = example_graph(g, ex, {default_tolerance(ex)});
  const auto* row = std::get_if<Split>(&g.op(root));
  ASSERT_NE(row, nullptr);
  ASSERT_EQ(row->parts.size(), 6u);
  for (const SplitPart& p : row->parts) {
    EXPECT_EQ(p.child, row->parts[0].child);
    EXPECT_EQ(literal(p.size), literal(row->parts[0].size));
  }
  EXPECT_TRUE(round_trips(ex));
}

TEST(SplitGraph, AFacadeFlatOnOneAxisRoundTrips) {
  // The thesis's example files are 2-D: every part at y = 0.
  const Derivation d = test::derive_text(
      "plot --> split(x){~2 : house | ~1 : garage}\n"
      "house --> split(z){~2 : I(rect) | ~1 : I(triangle)}\n"
      "garage --> split(z){~1 : I(rect) | ~2 : nil}\n",
      {10, 0, 10});
  const Example ex = test::example_of(test::derived_parts(d));
  EXPECT_EQ(example_size(ex).y, 0.0);
  EXPECT_TRUE(round_trips(ex));
}

TEST(SplitGraph, AnExampleFileRoundTrips) {
  const Grammar g = read_grammar_file(VERN_SOURCE_DIR "/data/grammars/modern_houses.grm");
  DeriveOptions o;
  o.seed = 3;
  const Derivation d = derive(g, o);
  Scene scene;
  scene.labels = d.labels;
  scene.variants.push_back({"house", glm::dvec3(-7, 3, 0.5), d.terminals});
  test::TempFolder dir;
  write_obj(scene, PrimitiveLibrary::builtin(), dir / "house.obj");
  const Example ex = load_example(dir / "house.obj");
  ASSERT_EQ(ex.boxes.size(), d.terminals.size());
  EXPECT_TRUE(round_trips(ex));
}

}  // namespace
}  // namespace vern
