// The benchmarks' synthetic workloads (bench/workload.hpp): random
// guillotine layouts that inference splits back into exactly their boxes,
// written as OBJ that reads back bit for bit, and random grammars that
// parse and derive. All seeded: the same options, the same output.
#include "workload.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <sstream>

#include "base/error.hpp"
#include "forward/derive.hpp"
#include "graph/parser.hpp"
#include "inverse/split/box_split.hpp"
#include "io/obj_reader.hpp"

namespace vern {
namespace {

LayoutOptions layout_options(std::size_t boxes, std::uint64_t seed = 1) {
  LayoutOptions o;
  o.boxes = boxes;
  o.seed = seed;
  return o;
}

TEST(Workload, ALayoutHasExactlyTheBoxesAskedForAndTheSeedDecidesThem) {
  for (std::size_t n : {1u, 2u, 7u, 1000u}) {
    EXPECT_EQ(random_layout(layout_options(n)).size(), n);
  }
  const auto a = random_layout(layout_options(500, 3));
  const auto b = random_layout(layout_options(500, 3));
  const auto c = random_layout(layout_options(500, 4));
  ASSERT_EQ(a.size(), b.size());
  bool all_same = true, any_other = false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    all_same = all_same && a[i].min == b[i].min && a[i].max == b[i].max && a[i].object == b[i].object;
    any_other = any_other || a[i].min != c[i].min || a[i].max != c[i].max;
  }
  EXPECT_TRUE(all_same);
  EXPECT_TRUE(any_other);
}

// The guillotine layout is what ordered-box splitting undoes: every box a
// leaf of its own, nothing unsplittable, and the boxes on a millimetre grid.
TEST(Workload, BoxSplittingRecoversEveryBoxOfALayout) {
  LayoutOptions o = layout_options(20'000, 9);
  o.gaps = 0.3;
  const auto boxes = random_layout(o);
  std::size_t off_grid = 0;
  for (const LabelledBox& b : boxes) {
    for (int a = 0; a < 3; ++a) {
      EXPECT_LT(b.min[a], b.max[a]);
      for (double v : {b.min[a], b.max[a]}) off_grid += std::abs(v * 1000 - std::round(v * 1000)) > 1e-6 ? 1 : 0;
    }
  }
  EXPECT_EQ(off_grid, 0u);
  const SplitTreeStats s = split_tree_stats(split_boxes(boxes, {1e-4}));
  EXPECT_EQ(s.leaves, boxes.size());
  EXPECT_EQ(s.unsplittable, 0u);
  EXPECT_GT(s.empties, 0u);  // the gaps
}

TEST(Workload, ShallowLayoutsCutTheirLastLevelIntoRows) {
  LayoutOptions o = layout_options(1000);
  o.depth = 2;
  o.gaps = 0;
  const SplitTreeStats s = split_tree_stats(split_boxes(random_layout(o), {1e-4}));
  EXPECT_EQ(s.leaves, 1000u);
  EXPECT_LE(s.depth, 3u);  // the root, one level of cuts, the rows' boxes
  o.depth = 1;
  o.boxes = 10'000'000;  // a row of ten million in 9.4 km: thinner than a millimetre
  try {
    random_layout(o);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Usage);
    EXPECT_NE(std::string(e.what()).find("raise --depth"), std::string::npos) << e.what();
  }
}

TEST(Workload, LayoutOptionsOutOfRangeAreUsageErrors) {
  for (auto change : {+[](LayoutOptions& o) { o.boxes = 0; }, +[](LayoutOptions& o) { o.depth = 0; },
                      +[](LayoutOptions& o) { o.branching = 1; }, +[](LayoutOptions& o) { o.gaps = 1.5; }}) {
    LayoutOptions o = layout_options(10);
    change(o);
    EXPECT_THROW(random_layout(o), Error);
  }
}

// Each box an object of 8 vertices and 6 quads; the names and coordinates
// read back exactly.
TEST(Workload, LayoutObjReadsBackAsTheSameBoxes) {
  const auto boxes = random_layout(layout_options(300, 5));
  std::istringstream in(layout_obj(boxes));
  const std::vector<ObjObject> objects = read_obj(in, "layout.obj");
  ASSERT_EQ(objects.size(), boxes.size());
  std::set<std::string> labels;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    EXPECT_EQ(objects[i].name, boxes[i].object);
    EXPECT_EQ(objects[i].mesh.positions.size(), 8u);
    EXPECT_EQ(objects[i].mesh.face_sizes, std::vector<std::uint32_t>(6, 4));
    EXPECT_EQ(objects[i].mesh.min_corner(), boxes[i].min);
    EXPECT_EQ(objects[i].mesh.max_corner(), boxes[i].max);
    labels.insert(boxes[i].label);
  }
  EXPECT_GT(labels.size(), 4u);
}

TEST(Workload, RandomGrammarsParseDeriveAndRepeat) {
  GrammarOptions o;
  o.rules = 200;
  o.seed = 11;
  const std::string text = random_grammar(o);
  EXPECT_EQ(random_grammar(o), text);
  o.seed = 12;
  EXPECT_NE(random_grammar(o), text);
  const Grammar g = parse_grammar(text, "random.grm");
  std::set<std::string> labels;
  for (const Rule& r : g.rules) labels.insert(r.label);
  EXPECT_EQ(labels.size(), 200u);
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    DeriveOptions d;
    d.seed = seed;
    EXPECT_GT(derive(g, d).terminals.size(), 200u) << "seed " << seed;  // at least one part per rule
  }
}

TEST(Workload, RandomGrammarsOnVariedPlotsDrawTheirPlots) {
  // The same grammar but for @scope: plots within 30 % of 40 x 30 x 60 m.
  GrammarOptions o;
  o.rules = 8;
  o.seed = 3;
  const std::string fixed = random_grammar(o);
  o.varied_plots = true;
  const Grammar g = parse_grammar(random_grammar(o), "random.grm");
  EXPECT_EQ(parse_grammar(fixed, "random.grm").rules.size(), g.rules.size());
  std::set<double> widths;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    DeriveOptions d;
    d.seed = seed;
    const Derivation v = derive(g, d);
    EXPECT_GE(v.start.size.x, 28.0);
    EXPECT_LE(v.start.size.x, 52.0);
    EXPECT_GE(v.start.size.z, 42.0);
    EXPECT_LE(v.start.size.z, 78.0);
    widths.insert(v.start.size.x);
  }
  EXPECT_EQ(widths.size(), 8u);
}

}  // namespace
}  // namespace vern
