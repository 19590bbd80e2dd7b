// From split trees to operation graphs, and the round trip that matters:
// deriving the graph inferred from an example gives back the example.
#include "inverse/split_graph.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "forward/obj_writer.hpp"
#include "graph/error.hpp"
#include "graph/parser.hpp"
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
// origin and compares with the example's parts moved to the origin.
::testing::AssertionResult round_trips(const Example& ex) {
  const Grammar g = grammar_of(ex);
  DeriveOptions o;
  o.size = example_size(ex);
  const Derivation d = derive(g, o);
  const glm::dvec3 size = example_size(ex);
  const double eps = 1e-9 * std::max({size.x, size.y, size.z});
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

TEST(SplitGraph, UnsplittableGroupsAreNamedInTheError) {
  const Example ex = test::example_of(
      test::numbered({part("a", {0, 0, 0}, {2, 1, 1}), part("b", {2, 0, 0}, {3, 2, 1}), part("c", {1, 2, 0}, {3, 3, 1}),
                      part("d", {0, 1, 0}, {1, 3, 1}), part("e", {1, 1, 0}, {2, 2, 1})}),
      "pinwheel.obj");
  Grammar g;
  try {
    example_graph(g, ex, {default_tolerance(ex)});
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Input);
    const std::string m = e.what();
    EXPECT_NE(m.find("pinwheel.obj:1:1: error: these 5 parts cannot be separated by straight cuts (e.g. a pinwheel): "
                     "'a.0' (line 1), 'b.1' (line 2), 'c.2' (line 3), 'd.3' (line 4), 'e.4' (line 5)"),
              std::string::npos)
        << m;
  }

  const Example flat = test::example_of(
      test::numbered({part("panel", {0, 0, 0}, {2, 0, 2}), part("box", {3, 0, 0}, {5, 1, 2})}), "flat.obj");
  try {
    example_graph(g, flat, {default_tolerance(flat)});
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("flat.obj:1:1: error: part 'panel.0' (line 1) is flat"), std::string::npos)
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
