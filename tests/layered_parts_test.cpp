// Overlapping parts resolved into what is visible of each
// (inverse/load/layered_parts.hpp): containers cut around what they hold, a
// stack order for parts painted over one another, errors that say which.
#include "inverse/load/layered_parts.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "base/error.hpp"
#include "inverse/split/box_split.hpp"

namespace vern {
namespace {

LabelledBox part(const std::string& label, glm::dvec3 min, glm::dvec3 max, std::uint32_t line) {
  LabelledBox b;
  b.label = label;
  b.object = label;
  b.min = min;
  b.max = max;
  b.line = line;
  return b;
}

Example example_of(std::vector<LabelledBox> boxes) {
  Example e;
  e.source = "facade.obj";
  e.boxes = std::move(boxes);
  update_bounds(e);
  return e;
}

double volume(const LabelledBox& b) {
  const glm::dvec3 s = b.max - b.min;
  return s.x * s.y * s.z;
}

// Every part of the result apart from every other: split_boxes refuses
// overlaps, so it must cut them all out.
void expect_apart(const Example& e) { EXPECT_NO_THROW(split_boxes(e.boxes, BoxSplitOptions{1e-9}, e.source)); }

std::vector<LabelledBox> labelled(const Example& e, const std::string& label) {
  std::vector<LabelledBox> out;
  for (const LabelledBox& b : e.boxes)
    if (b.label == label) out.push_back(b);
  return out;
}

TEST(LayeredParts, AWallKeepsBandsAndPiersAroundTheWindowsSetIntoIt) {
  const Example e = example_of({part("wall", {0, 0, 0}, {10, 0.3, 3}, 1), part("window", {2, 0, 1}, {3, 0.3, 2}, 2),
                                part("window", {6, 0, 1}, {7, 0.3, 2}, 3)});
  const Example v = visible_parts(e, Layering{{}, 1e-9});
  expect_apart(v);
  // The wall: the band below the windows, three piers between and beside
  // them, the band above; in file order, the windows as they were.
  ASSERT_EQ(v.boxes.size(), 7u);
  const std::vector<std::pair<glm::dvec3, glm::dvec3>> wall = {
      {{0, 0, 0}, {10, 0.3, 1}}, {{0, 0, 1}, {2, 0.3, 2}}, {{3, 0, 1}, {6, 0.3, 2}}, {{7, 0, 1}, {10, 0.3, 2}},
      {{0, 0, 2}, {10, 0.3, 3}}};
  for (std::size_t i = 0; i < wall.size(); ++i) {
    EXPECT_EQ(v.boxes[i].label, "wall");
    EXPECT_EQ(v.boxes[i].line, 1u);
    EXPECT_EQ(v.boxes[i].min, wall[i].first) << i;
    EXPECT_EQ(v.boxes[i].max, wall[i].second) << i;
  }
  EXPECT_EQ(v.boxes[5].min, e.boxes[1].min);
  EXPECT_EQ(v.boxes[6].max, e.boxes[2].max);
}

// A deep wall with windows set into its face, and the same wall turned a
// quarter (its face along y): after the bands, each is cut first along
// its row of windows, not its depth, so the turned wall's pieces are the
// wall's turned. Cut x before y whichever way the wall faced, the turned
// wall was a slab at its face and one behind, and no layout matched.
TEST(LayeredParts, AWallAndTheSameWallTurnedAQuarterKeepPiecesAlike) {
  const std::vector<LabelledBox> wall = {part("wall", {0, 0, 0}, {10, 5, 3}, 1),
                                         part("window", {2, 0, 1}, {3, 0.2, 2}, 2),
                                         part("window", {6, 0, 1}, {7, 0.2, 2}, 3)};
  std::vector<LabelledBox> turned = wall;
  for (LabelledBox& b : turned) {  // (x, y) -> (-y, x)
    const glm::dvec3 lo = b.min, hi = b.max;
    b.min = {-hi.y, lo.x, lo.z};
    b.max = {-lo.y, hi.x, hi.z};
  }
  const Example v = visible_parts(example_of(wall), Layering{{}, 1e-9});
  const Example t = visible_parts(example_of(turned), Layering{{}, 1e-9});
  ASSERT_EQ(v.boxes.size(), t.boxes.size());
  for (std::size_t i = 0; i < v.boxes.size(); ++i) {
    EXPECT_EQ(t.boxes[i].min, glm::dvec3(-v.boxes[i].max.y, v.boxes[i].min.x, v.boxes[i].min.z)) << i;
    EXPECT_EQ(t.boxes[i].max, glm::dvec3(-v.boxes[i].min.y, v.boxes[i].max.x, v.boxes[i].max.z)) << i;
  }
}

TEST(LayeredParts, NoOverlapsNoChange) {
  const Example e = example_of({part("wall", {0, 0, 0}, {2, 1, 3}, 1), part("door", {2, 0, 0}, {3, 1, 2}, 2)});
  const Example v = visible_parts(e, Layering{{}, 1e-9});
  ASSERT_EQ(v.boxes.size(), 2u);
  EXPECT_EQ(v.boxes[0].max, e.boxes[0].max);
  EXPECT_EQ(v.boxes[1].min, e.boxes[1].min);
}

// A sill painted over a window's lower edge, as the CMP annotations have
// it: the stack says which keeps what.
TEST(LayeredParts, TheStackSaysWhichOfTwoOverlappingPartsKeepsWhatIsVisible) {
  const Example e =
      example_of({part("window", {0, 0, 1}, {2, 0.2, 3}, 1), part("sill", {-0.1, 0, 0.8}, {2.1, 0.2, 1.2}, 2)});
  Example v = visible_parts(e, Layering{{"window", "sill"}, 1e-9});
  expect_apart(v);
  ASSERT_EQ(v.boxes.size(), 2u);
  EXPECT_EQ(v.boxes[0].min, glm::dvec3(0, 0, 1.2));  // the window above the sill
  EXPECT_EQ(v.boxes[0].max, glm::dvec3(2, 0.2, 3));
  EXPECT_EQ(v.boxes[1].min, e.boxes[1].min);

  v = visible_parts(e, Layering{{"sill", "window"}, 1e-9});
  expect_apart(v);
  const auto sill = labelled(v, "sill");
  ASSERT_EQ(sill.size(), 3u);  // below the window, and its two ends beside it
  EXPECT_EQ(sill[0].min, glm::dvec3(-0.1, 0, 0.8));
  EXPECT_EQ(sill[0].max, glm::dvec3(2.1, 0.2, 1));
  EXPECT_EQ(sill[1].max, glm::dvec3(0, 0.2, 1.2));
  EXPECT_EQ(sill[2].min, glm::dvec3(2, 0, 1));
  EXPECT_EQ(labelled(v, "window")[0].min, e.boxes[0].min);
}

TEST(LayeredParts, OverlapsNoOrderSaysAreAnErrorNamingBothPartsAndTheStack) {
  const Example e = example_of({part("window", {0, 0, 1}, {2, 0.2, 3}, 4), part("sill", {-0.1, 0, 0.8}, {2.1, 0.2, 1.2}, 9),
                                part("window", {3, 0, 1}, {5, 0.2, 3}, 14),
                                part("sill", {2.9, 0, 0.8}, {5.1, 0.2, 1.2}, 19)});
  try {
    visible_parts(e, Layering{{"window"}, 1e-9});  // sill unlisted: no order
    FAIL() << "no error";
  } catch (const Error& err) {
    const std::string m = err.what();
    EXPECT_EQ(err.kind(), ErrorKind::Input);
    EXPECT_EQ(m.rfind("facade.obj:4:1: error: objects 'window' (line 4) and 'sill' (line 9) overlap by 2 x 0.2 x 0.2 "
                      "(along x, y, z), and neither lies inside the other; 1 more such pair",
                      0),
              0u)
        << m;
    EXPECT_NE(m.find("hint: say which is painted over which, bottom to top: --stack window,sill"), std::string::npos)
        << m;
  }
}

// Two blinds of one facade annotated a little over one another: listed in
// the stack, the later in the file is painted over the earlier; unlisted,
// nothing orders them.
TEST(LayeredParts, PartsOfOneListedLabelArePaintedInFileOrder) {
  const Example e = example_of({part("blind", {0, 0, 0}, {2, 0.2, 1}, 1), part("blind", {0, 0, 0.9}, {2, 0.2, 2}, 2)});
  const Example v = visible_parts(e, Layering{{"wall", "blind"}, 1e-9});
  expect_apart(v);
  ASSERT_EQ(v.boxes.size(), 2u);
  EXPECT_EQ(v.boxes[0].max, glm::dvec3(2, 0.2, 0.9));
  EXPECT_EQ(v.boxes[1].min, e.boxes[1].min);
  try {
    visible_parts(e, Layering{{"wall"}, 1e-9});
    FAIL() << "no error";
  } catch (const Error& err) {
    EXPECT_NE(std::string(err.what()).find("or list their label in --stack"), std::string::npos) << err.what();
  }
}

// A label stacked over the parts it holds hides them; the label's mesh
// stays with its first part still there.
TEST(LayeredParts, APartWhollyCoveredIsGoneAndItsLabelsMeshMovesOn) {
  LabelledBox first = part("window", {1, 0, 1}, {2, 0.3, 2}, 2), second = part("window", {4, 0, 1}, {5, 0.3, 2}, 3);
  first.mesh = 1;
  LabelledBox shutter = part("shutter", {0.9, 0, 0.9}, {2.1, 0.3, 2.1}, 4);
  shutter.mesh = 2;
  Example e = example_of({part("wall", {0, 0, 0}, {6, 0.3, 3}, 1), first, second, shutter});
  e.boxes[0].mesh = 0;
  e.meshes.resize(3);
  const Example v = visible_parts(e, Layering{{"wall", "window", "shutter"}, 1e-9});
  expect_apart(v);
  const auto windows = labelled(v, "window");
  ASSERT_EQ(windows.size(), 1u);
  EXPECT_EQ(windows[0].line, 3u);
  EXPECT_EQ(windows[0].mesh, 1u);
  EXPECT_EQ(labelled(v, "wall")[0].mesh, 0u);
  EXPECT_EQ(labelled(v, "wall")[1].mesh, Mesh::kNone);
  EXPECT_EQ(labelled(v, "shutter")[0].mesh, 2u);
  // What is left of the wall, the window and the shutter fill the wall.
  double total = 0;
  for (const LabelledBox& b : v.boxes) total += volume(b);
  EXPECT_NEAR(total, volume(e.boxes[0]), 1e-9);
}

// Four panels in a pinwheel round a square in a wall: no straight cut
// through the wall misses them all, so the wall is tiled by their grid.
TEST(LayeredParts, PartsInAPinwheelLeaveTheWallTiledByTheirGrid) {
  const Example e = example_of({part("wall", {0, 0, 0}, {5, 0.2, 5}, 1), part("panel", {1, 0, 1}, {3, 0.2, 2}, 2),
                                part("panel", {3, 0, 1}, {4, 0.2, 3}, 3), part("panel", {2, 0, 3}, {4, 0.2, 4}, 4),
                                part("panel", {1, 0, 2}, {2, 0.2, 4}, 5)});
  const Example v = visible_parts(e, Layering{{}, 1e-9});
  expect_apart(v);
  double wall = 0;
  for (const LabelledBox& b : labelled(v, "wall")) wall += volume(b);
  EXPECT_NEAR(wall, 0.2 * (25 - 8), 1e-9);  // the centre square [2, 3] x [2, 3] is wall too
  EXPECT_EQ(labelled(v, "panel").size(), 4u);
}

// By the stack the top label is painted over the bottom one; by lying
// inside, the middle one over the top one and the bottom one over the
// middle one: a circle, which no painting follows.
TEST(LayeredParts, PartsPaintedOverOneAnotherInACircleAreAnError) {
  const Example e = example_of({part("top", {0, 0, 0}, {10, 1, 10}, 1), part("mid", {1, 0, 1}, {9, 1, 9}, 2),
                                part("low", {2, 0, 2}, {8, 1, 8}, 3)});
  try {
    visible_parts(e, Layering{{"low", "top"}, 1e-9});
    FAIL() << "no error";
  } catch (const Error& err) {
    EXPECT_NE(std::string(err.what()).find("painted over one another in a circle"), std::string::npos) << err.what();
  }
}

}  // namespace
}  // namespace vern
