// The ordered-box algorithm: the thesis's interval example, gaps, flat
// parts, float noise, overlaps, unsplittable pinwheels, and a large random
// building.
#include "inverse/split/box_split.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <tuple>

#include "base/error.hpp"
#include "support/example_helpers.hpp"

namespace vern {
namespace {

using Kind = SplitTree::Kind;
using test::part;

// The boxes of all leaves below t, sorted.
void collect(const SplitTree& t, std::vector<std::uint32_t>& out) {
  if (t.kind == Kind::Leaf) out.push_back(t.box);
  for (const SplitTree& c : t.children) collect(c, out);
}
std::vector<std::uint32_t> leaves(const SplitTree& t) {
  std::vector<std::uint32_t> out;
  collect(t, out);
  std::sort(out.begin(), out.end());
  return out;
}

// The invariants every tree keeps: a split's children tile it exactly
// along its axis and span it on the other two; a leaf fills its container.
void check_tree(const SplitTree& t, const std::vector<LabelledBox>& boxes, double tolerance) {
  switch (t.kind) {
    case Kind::Leaf:
      ASSERT_LT(t.box, boxes.size());
      for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(t.min[i], boxes[t.box].min[i], tolerance);
        EXPECT_NEAR(t.max[i], boxes[t.box].max[i], tolerance);
      }
      EXPECT_TRUE(t.children.empty());
      break;
    case Kind::Empty: EXPECT_TRUE(t.children.empty()); break;
    case Kind::Unsplittable:
      for (const SplitTree& c : t.children) EXPECT_EQ(c.kind, Kind::Leaf);
      break;
    case Kind::Comp:  // each face's tree is in the face's own frame, not the boxes'
      EXPECT_GE(t.children.size(), 2u);
      EXPECT_EQ(t.children.size(), t.faces.size());
      for (const SplitTree& c : t.children) EXPECT_EQ(c.min, glm::dvec3(0.0));
      break;
    case Kind::Split: {
      ASSERT_GE(t.axis, 0);
      ASSERT_LE(t.axis, 2);
      ASSERT_GE(t.children.size(), 2u);
      double at = t.min[t.axis];
      for (const SplitTree& c : t.children) {
        EXPECT_EQ(c.min[t.axis], at);  // exactly: snapped coordinates
        EXPECT_GT(c.max[t.axis], c.min[t.axis]);  // no zero-length parts
        at = c.max[t.axis];
        for (int i = 0; i < 3; ++i) {
          if (i == t.axis) continue;
          EXPECT_EQ(c.min[i], t.min[i]);
          EXPECT_EQ(c.max[i], t.max[i]);
        }
        check_tree(c, boxes, tolerance);
      }
      EXPECT_EQ(at, t.max[t.axis]);
      break;
    }
  }
}

SplitTree split(const std::vector<LabelledBox>& boxes, double tolerance = 1e-9) {
  const SplitTree t = split_boxes(boxes, {tolerance}, "test.obj");
  check_tree(t, boxes, std::max(tolerance, 1e-12));
  return t;
}

std::string split_error(const std::vector<LabelledBox>& boxes, double tolerance = 1e-9) {
  try {
    split_boxes(boxes, {tolerance}, "test.obj");
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Input) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return {};
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Thesis 9.1.2: intervals (0,4) (1,5) (2,5) (5,9) (8,9) (11,14) split into
// {(0,4), (1,5), (2,5)}, {(5,9), (8,9)} and {(11,14)}. In 3-D each interval
// is a box along x in its own row along y, so the groups can be split
// further.
// The cut a container is, along which axis and into how many pieces.
testing::AssertionResult cut_along(const SplitTree& t, int axis, std::size_t pieces) {
  if (t.kind != Kind::Split) return testing::AssertionFailure() << "not a split";
  if (t.axis != axis || t.children.size() != pieces)
    return testing::AssertionFailure() << "cut along " << t.axis << " into " << t.children.size();
  return testing::AssertionSuccess();
}

// The first n of the thesis's intervals along x (9.1.2), each a box on
// its own row along y.
std::vector<LabelledBox> thesis_intervals(std::uint32_t n) {
  const double intervals[6][2] = {{0, 4}, {1, 5}, {2, 5}, {5, 9}, {8, 9}, {11, 14}};
  std::vector<LabelledBox> boxes;
  for (std::uint32_t i = 0; i < n; ++i) boxes.push_back(part("rect", {intervals[i][0], i, 0}, {intervals[i][1], i + 1, 1}, i));
  return boxes;
}

TEST(BoxSplit, ThesisIntervalsFallIntoThreeGroupsAndTheTouchingOnesStayOne) {
  // The thesis's intervals (9.1.2): the sweep along x finds three groups,
  // [0, 5], [5, 9] and [11, 14]. The first two touch, and empty space
  // separates them from the third: touching parts make one thing, so the
  // cut is made at the gap only, and [0, 9] is cut again on its own.
  const SplitTree t = split(thesis_intervals(6));
  ASSERT_EQ(t.kind, Kind::Split);
  EXPECT_EQ(t.axis, 0);
  ASSERT_EQ(t.children.size(), 3u);
  EXPECT_EQ(leaves(t.children[0]), (std::vector<std::uint32_t>{0, 1, 2, 3, 4}));
  EXPECT_EQ(t.children[0].max.x, 9.0);
  EXPECT_EQ(t.children[1].kind, Kind::Empty);  // nothing between 9 and 11
  EXPECT_EQ(t.children[1].min, glm::dvec3(9, 0, 0));
  EXPECT_EQ(t.children[1].max, glm::dvec3(11, 6, 1));
  EXPECT_EQ(leaves(t.children[2]), (std::vector<std::uint32_t>{5}));
  const SplitTreeStats s = split_tree_stats(t);
  EXPECT_EQ(s.leaves, 6u);
  EXPECT_EQ(s.unsplittable, 0u);
}

TEST(BoxSplit, TouchingGroupsWithoutAGapAreCutApart) {
  // The same groups without the third: no gap, so the cut at 5 is made.
  const SplitTree t = split(thesis_intervals(5));
  ASSERT_EQ(t.kind, Kind::Split);
  EXPECT_EQ(t.axis, 0);
  ASSERT_EQ(t.children.size(), 2u);
  EXPECT_EQ(leaves(t.children[0]), (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(leaves(t.children[1]), (std::vector<std::uint32_t>{3, 4}));
  EXPECT_EQ(t.children[0].max.x, 5.0);
}

TEST(BoxSplit, ABlockBetweenStreetsStaysABlockWhetherOrNotItsRowsLineUp) {
  // A column of a city along y: a block of two strips whose buildings line
  // up into two rows across it, a street, and a block whose strips do not
  // (and are cut at another x, so no cut along x crosses the column).
  // Both blocks are pieces of the column, each cut into its strips along x.
  const SplitTree t = split({part("rect", {0, 0, 0}, {2, 2, 3}, 0), part("rect", {0, 2, 0}, {2, 4, 4}, 1),
                             part("rect", {2, 0, 0}, {4, 2, 2}, 2), part("rect", {2, 2, 0}, {4, 4, 5}, 3),
                             part("rect", {0, 5, 0}, {1.5, 9, 3}, 4), part("rect", {1.5, 5, 0}, {4, 7, 2}, 5),
                             part("rect", {1.5, 7, 0}, {4, 9, 4}, 6)});
  ASSERT_TRUE(cut_along(t, 1, 3));
  EXPECT_EQ(t.children[1].kind, Kind::Empty);
  for (const std::size_t block : {0u, 2u}) {
    SCOPED_TRACE(block);
    ASSERT_TRUE(cut_along(t.children[block], 0, 2));
  }
  EXPECT_EQ(leaves(t.children[0].children[0]), (std::vector<std::uint32_t>{0, 1}));
}

TEST(BoxSplit, AYardAcrossComesBeforeCutsThatOnlyHappenToLineUp) {
  // A house's range (y 0 to 7) and a barn's (y 10 to 16) across a yard,
  // each a wall, two bays and a wall along x, their cuts lined up at 0.5,
  // 3 and 5.5 (another example's bays would not line up). The yard is cut
  // first, so each range is one piece in every example, cut on its own.
  std::vector<LabelledBox> boxes;
  for (const double y0 : {0.0, 10.0}) {
    const double y1 = y0 == 0 ? 7 : 16;
    boxes.push_back(part("wall", {0, y0, 0}, {0.5, y1, 6}));
    boxes.push_back(part("bay", {0.5, y0, 0}, {3, y1, 6}));
    boxes.push_back(part("bay", {3, y0, 0}, {5.5, y1, 6}));
    boxes.push_back(part("wall", {5.5, y0, 0}, {6, y1, 6}));
  }
  const SplitTree t = split(test::numbered(boxes));
  ASSERT_TRUE(cut_along(t, 1, 3));
  EXPECT_EQ(t.children[1].kind, Kind::Empty);
  for (const std::size_t range : {0u, 2u}) {
    SCOPED_TRACE(range);
    ASSERT_TRUE(cut_along(t.children[range], 0, 4));
  }
  EXPECT_EQ(leaves(t.children[2]), (std::vector<std::uint32_t>{4, 5, 6, 7}));
}

TEST(BoxSplit, AnLPlansFrontIsCutOffBeforeCutsThroughItsYard) {
  // An L: a front of four 3 m bays right across (y 0 to 6), a wing behind
  // it on the left (x 0 to 5, y 6 to 15) and empty space beside the wing.
  // Along x the front's bay boundaries at 6 and 9 are clean cuts too, the
  // yard behind them empty, but only because the bays fall beside the
  // wing's edge (another example's would not): the front's face, met by
  // parts right across, is cut first, and the front and the back are each
  // cut on their own.
  std::vector<LabelledBox> boxes;
  for (int bay = 0; bay < 4; ++bay) boxes.push_back(part("bay", {3.0 * bay, 0, 0}, {3.0 * bay + 3, 6, 8}));
  boxes.push_back(part("wing", {0, 6, 0}, {5, 15, 6}));
  const SplitTree t = split(test::numbered(boxes));
  ASSERT_TRUE(cut_along(t, 1, 2));
  ASSERT_TRUE(cut_along(t.children[0], 0, 4));
  EXPECT_EQ(leaves(t.children[0]), (std::vector<std::uint32_t>{0, 1, 2, 3}));
}

TEST(BoxSplit, FlatPartsRoundAnOpenBoxAreCutIntoItsFaces) {
  // A front of two panels, two side walls and a roof, all flat, meeting
  // at the corners: no straight cut separates them, but each lies on a
  // face of the box they bound: comp(f), each face split in its frame.
  const SplitTree t = split({part("wall", {0, 0, 0}, {4, 0, 4}, 0), part("door", {4, 0, 0}, {10, 0, 4}, 1),
                             part("side", {0, 0, 0}, {0, 6, 4}, 2), part("side", {10, 0, 0}, {10, 6, 4}, 3),
                             part("roof", {0, 0, 4}, {10, 6, 4}, 4)});
  ASSERT_EQ(t.kind, Kind::Comp);
  EXPECT_EQ(t.faces, (std::vector<Face>{Face::Front, Face::Left, Face::Right, Face::Top}));
  ASSERT_TRUE(cut_along(t.children[0], 0, 2));  // the front: wall | door along its x
  EXPECT_EQ(t.children[0].children[1].box, 1u);
  EXPECT_EQ(t.children[0].children[1].max, glm::dvec3(10, 4, 0));
  EXPECT_EQ(t.children[1].kind, Kind::Leaf);
  EXPECT_EQ(t.children[1].box, 2u);
  EXPECT_EQ(t.children[3].box, 4u);
}

TEST(BoxSplit, AMassWhoseStoreysLineUpRoundItsFacesIsOneMassOnItsPlinth) {
  // A tower on a solid plinth, cut into its faces: each side a spandrel
  // band under a glass band, at the same heights all round, and a flat
  // roof. Cuts along z run through all four sides at the band's top; the
  // bands are one mass's faces, each side's bands its own split.
  std::vector<LabelledBox> boxes{part("plinth", {0, 0, 0}, {10, 10, 2})};
  const glm::dvec3 lo[4] = {{0, 0, 0}, {0, 10, 0}, {0, 0, 0}, {10, 0, 0}};
  const glm::dvec3 hi[4] = {{10, 0, 0}, {10, 10, 0}, {0, 10, 0}, {10, 10, 0}};
  for (int s = 0; s < 4; ++s) {
    boxes.push_back(part("spandrel", lo[s] + glm::dvec3(0, 0, 2), hi[s] + glm::dvec3(0, 0, 3)));
    boxes.push_back(part("glass", lo[s] + glm::dvec3(0, 0, 3), hi[s] + glm::dvec3(0, 0, 8)));
  }
  boxes.push_back(part("roof", {0, 0, 8}, {10, 10, 8}));
  const SplitTree t = split(test::numbered(boxes));
  ASSERT_TRUE(cut_along(t, 2, 2));
  const SplitTree& mass = t.children[1];
  ASSERT_EQ(mass.kind, Kind::Comp);
  EXPECT_EQ(mass.faces, (std::vector<Face>{Face::Front, Face::Back, Face::Left, Face::Right, Face::Top}));
  EXPECT_TRUE(cut_along(mass.children[0], 1, 2));  // the front: spandrel under glass, along its y
}

TEST(BoxSplit, ASinglePartIsALeaf) {
  const SplitTree t = split({part("roof", {1, 2, 3}, {4, 6, 8})});
  EXPECT_EQ(t.kind, Kind::Leaf);
  EXPECT_EQ(t.box, 0u);
  EXPECT_EQ(t.min, glm::dvec3(1, 2, 3));
  EXPECT_EQ(t.max, glm::dvec3(4, 6, 8));
  EXPECT_EQ(split_boxes({}, {}).kind, Kind::Empty);
}

TEST(BoxSplit, GapsBecomeEmptyPartsOfTheRightSize) {
  // A tall box, a gap of 2, a low box: along x, then along y for the low one.
  const SplitTree t = split({part("a", {0, 0, 0}, {1, 2, 1}, 0), part("b", {3, 0, 0}, {4, 1, 1}, 1)});
  ASSERT_EQ(t.kind, Kind::Split);
  EXPECT_EQ(t.axis, 0);
  ASSERT_EQ(t.children.size(), 3u);
  EXPECT_EQ(t.children[0].kind, Kind::Leaf);
  EXPECT_EQ(t.children[1].kind, Kind::Empty);
  EXPECT_EQ(t.children[1].size(), glm::dvec3(2, 2, 1));
  const SplitTree& low = t.children[2];
  ASSERT_EQ(low.kind, Kind::Split);
  EXPECT_EQ(low.axis, 1);
  ASSERT_EQ(low.children.size(), 2u);
  EXPECT_EQ(low.children[0].kind, Kind::Leaf);
  EXPECT_EQ(low.children[0].box, 1u);
  EXPECT_EQ(low.children[1].kind, Kind::Empty);
  EXPECT_EQ(low.children[1].min, glm::dvec3(3, 1, 0));
  EXPECT_EQ(low.children[1].max, glm::dvec3(4, 2, 1));
}

TEST(BoxSplit, ARowOfBuildingsIsCutIntoBuildingsBeforeTheAirAboveIt) {
  // Two buildings side by side along x, 3 and 5 high, in a strip cut off
  // along y by a street: the strip is cut along x into the two buildings,
  // each with its own air, not along z under the taller one's top first.
  const SplitTree t = split({part("rect", {0, 0, 0}, {2, 2, 3}, 0), part("rect", {2, 0, 0}, {4, 2, 5}, 1),
                             part("rect", {0, 3, 0}, {4, 5, 6}, 2)});
  ASSERT_TRUE(cut_along(t, 1, 3));  // no cut along x crosses the whole plot
  const SplitTree& strip = t.children[0];
  ASSERT_TRUE(cut_along(strip, 0, 2));
  for (std::uint32_t b = 0; b < 2; ++b) {
    ASSERT_TRUE(cut_along(strip.children[b], 2, 2));
    EXPECT_EQ(strip.children[b].children[0].box, b);
    EXPECT_EQ(strip.children[b].children[1].kind, Kind::Empty);
  }
}

TEST(BoxSplit, AYardBeforeAWholeBuildingIsOneEmptyPart) {
  // A wing right across the plot's depth beside a house of two storeys
  // set back 4 m from the street: once the house is cut from the wing,
  // the yard every storey borders alike is cut off first, one empty part,
  // not one strip of it beside each storey.
  const SplitTree t = split({part("wing", {0, 0, 0}, {2, 10, 6}, 0), part("storey", {2, 4, 0}, {8, 10, 3}, 1),
                             part("storey", {2, 4, 3}, {8, 10, 6}, 2)});
  ASSERT_TRUE(cut_along(t, 0, 2));
  const SplitTree& house = t.children[1];
  ASSERT_TRUE(cut_along(house, 1, 2));
  EXPECT_EQ(house.children[0].kind, Kind::Empty);
  ASSERT_TRUE(cut_along(house.children[1], 2, 2));
  EXPECT_EQ(leaves(house.children[1]), (std::vector<std::uint32_t>{1, 2}));
}

TEST(BoxSplit, AYardBeforeABuildingWhoseTiersAreSetBackIsOneEmptyPart) {
  // The same house with a tier set back 1 m on every side above its
  // storeys: the tier does not border the yard, but the storeys' front
  // runs right across the house at the bottom, so the yard is still the
  // whole building's, one empty part (and the tier stays set in on its
  // storeys by 1 m, not by the yard and 1 m).
  const SplitTree t = split({part("wing", {0, 0, 0}, {2, 10, 9}, 0), part("storey", {2, 4, 0}, {8, 10, 3}, 1),
                             part("storey", {2, 4, 3}, {8, 10, 6}, 2), part("tier", {3, 5, 6}, {7, 9, 9}, 3)});
  ASSERT_TRUE(cut_along(t, 0, 2));
  const SplitTree& house = t.children[1];
  ASSERT_TRUE(cut_along(house, 1, 2));
  EXPECT_EQ(house.children[0].kind, Kind::Empty);
  EXPECT_EQ(leaves(house.children[1]), (std::vector<std::uint32_t>{1, 2, 3}));
}

TEST(BoxSplit, AMarginRoundAPartThatSpansARowIsCutBeforeTheRows) {
  // A portico before its wall: a pediment (x 2 to 8) over three columns
  // whose last stands short of the pediment's end. The margins left and
  // right of the pediment are the portico's, one empty part each, cut
  // before colonnade and pediment: cut the other way round, the colonnade
  // row would end where its last column does and only the pediment would
  // say where the colonnade ends (a variant's columns could not line up
  // with its pediment).
  const SplitTree t = split({part("wall", {0, 1, 0}, {10, 3, 4}, 0), part("pediment", {2, 0, 3}, {8, 1, 4}, 1),
                             part("column", {2, 0, 0}, {2.6, 1, 3}, 2), part("column", {4, 0, 0}, {4.6, 1, 3}, 3),
                             part("column", {6, 0, 0}, {6.6, 1, 3}, 4)});
  ASSERT_TRUE(cut_along(t, 1, 2));
  const SplitTree& portico = t.children[0];
  ASSERT_TRUE(cut_along(portico, 0, 3));
  EXPECT_EQ(portico.children[0].kind, Kind::Empty);
  EXPECT_EQ(portico.children[2].kind, Kind::Empty);
  ASSERT_TRUE(cut_along(portico.children[1], 2, 2));
  EXPECT_EQ(leaves(portico.children[1]), (std::vector<std::uint32_t>{1, 2, 3, 4}));
}

TEST(BoxSplit, AHouseBehindItsYardBetweenTwoWingsIsOnePiece) {
  // Two wings right across the plot's depth and, between them, a house of
  // two bays and two storeys set back 4 m: its bays are set back alike,
  // so the cut along x gives the wings and the house, not the wings and
  // each bay, and the house's yard is one empty part.
  std::vector<LabelledBox> boxes{part("wing", {0, 0, 0}, {2, 10, 6}, 0), part("wing", {8, 0, 0}, {10, 10, 6}, 1)};
  std::uint32_t id = 2;
  for (const double x : {2.0, 5.0})
    for (const double z : {0.0, 3.0}) boxes.push_back(part("storey", {x, 4, z}, {x + 3, 10, z + 3}, id++));
  const SplitTree t = split(boxes);
  ASSERT_TRUE(cut_along(t, 0, 3));
  const SplitTree& house = t.children[1];
  ASSERT_TRUE(cut_along(house, 1, 2));
  EXPECT_EQ(house.children[0].kind, Kind::Empty);
  EXPECT_EQ(leaves(house.children[1]), (std::vector<std::uint32_t>{2, 3, 4, 5}));
}

TEST(BoxSplit, ACourtyardIsItsFrontAndBackRangesAndItsSideRangesBetween) {
  // A 13 x 13 courtyard: ranges 3 deep in 3.25 m bays along the front and
  // back, and side ranges between them in 3.5 m bays along y. Both axes
  // cut through the yard (the x cuts between the front's bays past the
  // side ranges, the y cuts between the side ranges' bays, which line up
  // with each other), but only the y cuts at 3 and 10 run along faces
  // right across: the courtyard is cut there first, and its middle is
  // the two side ranges and the yard between them.
  std::vector<LabelledBox> boxes;
  std::uint32_t id = 0;
  for (const double y : {0.0, 10.0})
    for (int i = 0; i < 4; ++i) boxes.push_back(part("bay", {3.25 * i, y, 0}, {3.25 * (i + 1), y + 3, 4}, id++));
  for (const double x : {0.0, 10.0})
    for (int i = 0; i < 2; ++i) boxes.push_back(part("bay", {x, 3 + 3.5 * i, 0}, {x + 3, 3 + 3.5 * (i + 1), 4}, id++));
  const SplitTree t = split(boxes);
  ASSERT_TRUE(cut_along(t, 1, 3));
  EXPECT_EQ(leaves(t.children[0]), (std::vector<std::uint32_t>{0, 1, 2, 3}));
  const SplitTree& middle = t.children[1];
  ASSERT_TRUE(cut_along(middle, 0, 3));
  EXPECT_EQ(leaves(middle.children[0]), (std::vector<std::uint32_t>{8, 9}));
  EXPECT_EQ(middle.children[1].kind, Kind::Empty);
  EXPECT_EQ(leaves(middle.children[2]), (std::vector<std::uint32_t>{10, 11}));
}

TEST(BoxSplit, TiersOfTwoBandsNestUpToTheTopTier) {
  // Three tiers, each a wall (2 m) under an eaves band (1 m) of one
  // footprint, set in by 1 m on every side, the roof on the top tier's
  // footprint. Each tier's two bands are its lowest tier, the rest one
  // piece; the top two tiers narrow only once, inside the stack, and
  // still nest.
  std::vector<LabelledBox> boxes;
  std::uint32_t id = 0;
  for (int t = 0; t < 3; ++t) {
    const double in = t, z = 3.0 * t;
    boxes.push_back(part("rect", {in, in, z}, {12 - in, 12 - in, z + 2}, id++));
    boxes.push_back(part("eave", {in, in, z + 2}, {12 - in, 12 - in, z + 3}, id++));
  }
  boxes.push_back(part("roof", {2, 2, 9}, {10, 10, 11}, id++));
  const SplitTree t = split(boxes);
  ASSERT_TRUE(cut_along(t, 2, 3));
  EXPECT_EQ(t.children[0].box, 0u);
  EXPECT_EQ(t.children[1].box, 1u);
  // The rest: the air round it peeled along x, then y, then the next tier.
  const SplitTree* rest = &t.children[2];
  for (int level = 1; level <= 2; ++level) {
    ASSERT_TRUE(cut_along(*rest, 0, 3)) << "level " << level;
    ASSERT_TRUE(cut_along(rest->children[1], 1, 3)) << "level " << level;
    const SplitTree& tier = rest->children[1].children[1];
    ASSERT_TRUE(cut_along(tier, 2, 3)) << "level " << level;
    EXPECT_EQ(tier.children[0].box, 2u * static_cast<std::uint32_t>(level));
    rest = &tier.children[2];
  }
  EXPECT_EQ(rest->box, 6u);  // the roof, on the top tier's footprint
}

TEST(BoxSplit, ATerraceOfEqualHousesIsCutIntoHouses) {
  // Three houses 6 m wide, each a door bay (wall, door, wall) and a
  // window bay (wall, window, wall) under a roof band of a chimney and
  // its roof: the party walls run through the storey and the roof band,
  // which share no other boundary. The cuts at every party wall are the
  // houses', not bays and chimneys lining up by chance: houses first,
  // each its storey and roof band.
  std::vector<LabelledBox> boxes;
  std::uint32_t id = 0;
  for (int h = 0; h < 3; ++h) {
    const double x = 6.0 * h;
    for (const auto& [from, to, label] : std::vector<std::tuple<double, double, std::string>>{
             {0, 1, "wall"}, {1, 2, "door"}, {2, 3, "wall"}, {3, 3.8, "wall"}, {3.8, 5.2, "window"}, {5.2, 6, "wall"}})
      boxes.push_back(part(label, {x + from, 0, 0}, {x + to, 10, 6}, id++));
    boxes.push_back(part("chimney", {x, 0, 6}, {x + 0.8, 10, 9}, id++));
    boxes.push_back(part("roof", {x + 0.8, 0, 6}, {x + 6, 10, 9}, id++));
  }
  const SplitTree t = split(boxes);
  ASSERT_TRUE(cut_along(t, 0, 3));
  for (const SplitTree& house : t.children) EXPECT_TRUE(cut_along(house, 2, 2));
}

TEST(BoxSplit, TouchingBuildingsBesideAGapAreCutIntoBuildingsBeforeStoreys) {
  // A house, a gap, then two lodges of different widths touching, each a
  // wall band under a roof band of one height: the lodges are one block
  // beside the gap, and the block is its two lodges, each its wall and
  // roof, not a band of both walls under a band of both roofs (whose
  // party wall would then line up only by chance, band by band).
  const SplitTree t = split({part("house", {0, 0, 0}, {10, 8, 7}, 0), part("wall", {12, 0, 0}, {17, 8, 5}, 1),
                             part("roof", {12, 0, 5}, {17, 8, 7}, 2), part("wall", {17, 0, 0}, {23, 8, 5}, 3),
                             part("roof", {17, 0, 5}, {23, 8, 7}, 4)});
  ASSERT_TRUE(cut_along(t, 0, 3));  // the house, the gap, the block
  EXPECT_EQ(t.children[1].kind, Kind::Empty);
  const SplitTree& block = t.children[2];
  ASSERT_TRUE(cut_along(block, 0, 2));
  EXPECT_EQ(leaves(block.children[0]), (std::vector<std::uint32_t>{1, 2}));
  EXPECT_EQ(leaves(block.children[1]), (std::vector<std::uint32_t>{3, 4}));
}

TEST(BoxSplit, ATieredTowerIsCutAsTiersStandingOnTiers) {
  // Three tiers, each inset in the one below: cut at the lowest tier only,
  // then the air round the rest peeled (x, y), then the next tier, so each
  // tier is nested in the one it stands on (not three slabs of the whole
  // footprint, each with its own inset).
  const SplitTree t = split({part("rect", {0, 0, 0}, {10, 10, 3}, 0), part("rect", {1, 1, 3}, {9, 9, 6}, 1),
                             part("rect", {2, 2, 6}, {8, 8, 9}, 2)});
  ASSERT_TRUE(cut_along(t, 2, 2));
  EXPECT_EQ(t.children[0].box, 0u);
  const SplitTree& rest = t.children[1];
  ASSERT_TRUE(cut_along(rest, 0, 3));
  ASSERT_TRUE(cut_along(rest.children[1], 1, 3));
  const SplitTree& second = rest.children[1].children[1];
  ASSERT_TRUE(cut_along(second, 2, 2));
  EXPECT_EQ(second.children[0].box, 1u);
  EXPECT_EQ(leaves(second.children[1]), std::vector<std::uint32_t>{2});
}

TEST(BoxSplit, StoreysOfOneFootprintOnAWiderSlabStayOneStack) {
  // A house on its base slab: the storeys narrow once (onto the slab),
  // not again, so the stack is cut at every storey, as before.
  const SplitTree t = split({part("rect", {0, 0, 0}, {10, 10, 1}, 0), part("rect", {1, 1, 1}, {9, 9, 4}, 1),
                             part("rect", {1, 1, 4}, {9, 9, 7}, 2), part("rect", {1, 1, 7}, {9, 9, 10}, 3)});
  ASSERT_TRUE(cut_along(t, 2, 4));
}

TEST(BoxSplit, ABlockIsCutIntoPlotsBeforeSlicingItUnderATowersUpperStorey) {
  // In a strip cut off along y, a low building beside a tower whose upper
  // storey (on a smaller footprint) starts above the low building's roof:
  // a cut along z at 3 exists, but the strip is cut along x first.
  const SplitTree t = split({part("rect", {0, 0, 0}, {2, 2, 2}, 0), part("rect", {2, 0, 0}, {4, 2, 3}, 1),
                             part("rect", {2.5, 0.5, 3}, {3.5, 1.5, 6}, 2), part("rect", {0, 3, 0}, {4, 5, 6}, 3)});
  ASSERT_TRUE(cut_along(t, 1, 3));
  const SplitTree& strip = t.children[0];
  ASSERT_TRUE(cut_along(strip, 0, 2));
  const SplitTree& tower = strip.children[1];
  ASSERT_EQ(tower.kind, Kind::Split);
  EXPECT_EQ(tower.axis, 2);
  EXPECT_EQ(tower.children[0].box, 1u);
}

TEST(BoxSplit, APodiumRightAcrossIsCutOffBeforeAColumnOfItsBays) {
  // A podium of shop bays (a pier, a window, ...) under a tower set back
  // on every side: a cut along x after the first pier crosses nothing, but
  // it would make a column of one pier under air. The podium, a slab
  // right across, is cut off first, and the tower above on its own.
  std::vector<LabelledBox> boxes;
  for (int i = 0; i < 4; ++i) {
    boxes.push_back(part("rect", {5.0 * i, 0, 0}, {5.0 * i + 0.5, 10, 4.5}));
    boxes.push_back(part("window", {5.0 * i + 0.5, 0, 0}, {5.0 * i + 5, 10, 4.5}));
  }
  boxes.push_back(part("rect", {3, 3, 4.5}, {17, 7, 30}));
  const SplitTree t = split(test::numbered(boxes));
  ASSERT_TRUE(cut_along(t, 2, 2));
  EXPECT_EQ(leaves(t.children[0]).size(), 8u);
  // Where the bays below fill no slab, the plots come first, as before
  // (ABlockIsCutIntoPlotsBeforeSlicingItUnderATowersUpperStorey).
}

TEST(BoxSplit, HousesOfDifferentHeightsOverTheirShopsAreCutIntoHousesFirst) {
  // A terrace of three houses, each a shop 3.5 m high and two, four or
  // three storeys of windows between walls above it, under air up to the
  // tallest. The shops are a slab right across, as a podium is, but every
  // house holds storeys above it and the taller houses' storeys above a
  // lower one's top are of its own kinds: houses, cut apart first, not
  // storey bands across the terrace with air in them.
  std::vector<LabelledBox> boxes;
  const double widths[] = {6, 7.5, 5.5};
  const int storeys[] = {2, 4, 3};
  double x = 0;
  for (int h = 0; h < 3; ++h) {
    const double w = widths[h];
    boxes.push_back(part("shop", {x, 0, 0}, {x + w, 1, 3.5}));
    for (int s = 0; s < storeys[h]; ++s) {
      const double z = 3.5 + 3 * s;
      boxes.push_back(part("wall", {x, 0, z}, {x + 1, 1, z + 3}));
      boxes.push_back(part("window", {x + 1, 0, z}, {x + w - 1, 1, z + 3}));
      boxes.push_back(part("wall", {x + w - 1, 0, z}, {x + w, 1, z + 3}));
    }
    x += w;
  }
  const SplitTree t = split(test::numbered(boxes));
  ASSERT_TRUE(cut_along(t, 0, 3));
  // A tower over a podium of the same labels is still a podium: a column
  // of the podium has nothing above the slab
  // (APodiumRightAcrossIsCutOffBeforeAColumnOfItsBays).
}

TEST(BoxSplit, CutsThatOnlyHappenToLineUpThroughTheStoreysWait) {
  // A ground floor of a door (0..3) and window bays of 2.25 m, a roof band
  // of dormer tiles 3 m wide: both have a face at x = 3 and at x = 12, so
  // cuts along x there cross nothing, but they are few of either storey's
  // own faces. The storeys are cut apart first, each row on its own.
  std::vector<LabelledBox> boxes{part("door", {0, 0, 0}, {3, 1, 3})};
  for (int i = 0; i < 4; ++i) {
    const double x = 3 + 2.25 * i;
    boxes.push_back(part("rect", {x, 0, 0}, {x + 0.5, 1, 3}));
    boxes.push_back(part("window", {x + 0.5, 0, 0}, {x + 1.75, 1, 3}));
    boxes.push_back(part("rect", {x + 1.75, 0, 0}, {x + 2.25, 1, 3}));
  }
  for (int i = 0; i < 4; ++i) {
    const double x = 3.0 * i;
    boxes.push_back(part("roof", {x, 0, 3}, {x + 1, 1, 5}));
    boxes.push_back(part("window", {x + 1, 0, 3}, {x + 2, 1, 5}));
    boxes.push_back(part("roof", {x + 2, 0, 3}, {x + 3, 1, 5}));
  }
  const SplitTree t = split(test::numbered(boxes));
  ASSERT_TRUE(cut_along(t, 2, 2));
  ASSERT_TRUE(cut_along(t.children[0], 0, 13));
  ASSERT_TRUE(cut_along(t.children[1], 0, 12));
}

TEST(BoxSplit, EndWallsThroughEveryStoreyAreCutFirst) {
  // A terrace front: end walls full height, two storeys of bays and a roof
  // band between them. The cuts beside the end walls are all the roof
  // band's own faces: they are the building's, and come first.
  std::vector<LabelledBox> boxes{part("rect", {0, 0, 0}, {0.6, 1, 8}), part("rect", {9.6, 0, 0}, {10.2, 1, 8}),
                                 part("roof", {0.6, 0, 6}, {9.6, 1, 8})};
  for (int storey = 0; storey < 2; ++storey)
    for (int bay = 0; bay < 3; ++bay) {
      const double x = 0.6 + 3 * bay, z = 3.0 * storey;
      boxes.push_back(part("rect", {x, 0, z}, {x + 1, 1, z + 3}));
      boxes.push_back(part("window", {x + 1, 0, z}, {x + 3, 1, z + 3}));
    }
  const SplitTree t = split(test::numbered(boxes));
  ASSERT_TRUE(cut_along(t, 0, 3));
}

TEST(BoxSplit, BaysThatLineUpThroughStoreysUnderARoofWaitForTheStoreys) {
  // Piers full height at both ends; between them a ground floor and two
  // storeys of three aligned 4 m bays, and a roof within the middle bay
  // with air beside it. Cuts along x run beside the piers along faces from the
  // bottom to the top; those between the outer bays stop at the storeys'
  // top on both sides and run on through the air beside the roof. The
  // piers are cut off first, and the front between them into its storeys
  // (each then a row of bays), not into columns that each keep storey
  // heights of their own.
  std::vector<LabelledBox> boxes{part("pier", {0, 0, 0}, {0.6, 1, 14}), part("pier", {12.6, 0, 0}, {13.2, 1, 14}),
                                 part("roof", {5.2, 0, 10}, {8, 1, 14})};
  for (int storey = 0; storey < 3; ++storey)
    for (int bay = 0; bay < 3; ++bay) {
      const double x = 0.6 + 4 * bay, z = storey == 0 ? 0 : 1 + 3.0 * storey, top = 4 + 3.0 * storey;
      boxes.push_back(part("rect", {x, 0, z}, {x + 1, 1, top}));
      boxes.push_back(part(storey == 0 ? "shop" : "window", {x + 1, 0, z}, {x + 3, 1, top}));
      boxes.push_back(part("rect", {x + 3, 0, z}, {x + 4, 1, top}));
    }
  const SplitTree t = split(test::numbered(boxes));
  ASSERT_TRUE(cut_along(t, 0, 3));
  ASSERT_TRUE(cut_along(t.children[1], 2, 4));
  // A row of houses of different heights, one box each, keeps its houses:
  // no storey line runs through the lower ones.
  const SplitTree row = split(test::numbered({part("rect", {0, 0, 0}, {4, 1, 6}), part("rect", {4, 0, 0}, {8, 1, 9}),
                                              part("rect", {8, 0, 0}, {12, 1, 14})}));
  ASSERT_TRUE(cut_along(row, 0, 3));
}

TEST(BoxSplit, AnOnlyCutThatPeelsAirOffIsStillMade) {
  // A box under air along z, with nothing beside it: z is the only cut.
  const SplitTree t = split({part("rect", {0, 0, 0}, {2, 2, 1}, 0), part("rect", {0, 2, 0}, {2, 4, 3}, 1)});
  ASSERT_EQ(t.kind, Kind::Split);
  EXPECT_EQ(t.axis, 1);
  ASSERT_EQ(t.children[0].kind, Kind::Split);
  EXPECT_EQ(t.children[0].axis, 2);
  EXPECT_EQ(t.children[0].children[0].box, 0u);
  EXPECT_EQ(t.children[0].children[1].kind, Kind::Empty);
}

// Five boxes around a square, each pushing the next: no straight cut
// separates any of them.
std::vector<LabelledBox> pinwheel(glm::dvec3 at = glm::dvec3(0.0)) {
  return test::numbered({part("a", at + glm::dvec3(0, 0, 0), at + glm::dvec3(2, 1, 1)),
                         part("b", at + glm::dvec3(2, 0, 0), at + glm::dvec3(3, 2, 1)),
                         part("c", at + glm::dvec3(1, 2, 0), at + glm::dvec3(3, 3, 1)),
                         part("d", at + glm::dvec3(0, 1, 0), at + glm::dvec3(1, 3, 1)),
                         part("e", at + glm::dvec3(1, 1, 0), at + glm::dvec3(2, 2, 1))});
}

TEST(BoxSplit, APinwheelIsUnsplittableAndEnds) {
  const std::vector<LabelledBox> boxes = pinwheel();
  const SplitTree t = split(boxes);
  ASSERT_EQ(t.kind, Kind::Unsplittable);
  ASSERT_EQ(t.children.size(), 5u);
  for (std::uint32_t i = 0; i < 5; ++i) {
    EXPECT_EQ(t.children[i].box, i);
    EXPECT_EQ(t.children[i].min, boxes[i].min);
    EXPECT_EQ(t.children[i].max, boxes[i].max);
  }

  // Inside a building, the rest still splits around it.
  std::vector<LabelledBox> more = pinwheel();
  more.push_back(part("tower", {4, 0, 0}, {5, 3, 4}, 5));
  const SplitTree u = split(more);
  ASSERT_EQ(u.kind, Kind::Split);
  EXPECT_EQ(u.axis, 0);
  ASSERT_EQ(u.children.size(), 3u);
  const SplitTree& left = u.children[0];  // the pinwheel's column, split off its empty top
  ASSERT_EQ(left.kind, Kind::Split);
  EXPECT_EQ(left.axis, 2);
  EXPECT_EQ(left.children[0].kind, Kind::Unsplittable);
  EXPECT_EQ(left.children[1].kind, Kind::Empty);
  EXPECT_EQ(u.children[1].kind, Kind::Empty);
  EXPECT_EQ(u.children[2].kind, Kind::Leaf);
  EXPECT_EQ(split_tree_stats(u).unsplittable, 1u);
}

TEST(BoxSplit, OverlapsNameBothObjectsAndHowMuch) {
  const std::string e = split_error(test::numbered(
      {part("wall", {0, 0, 0}, {4, 1, 3}), part("window", {3, 0.5, 1}, {5, 1, 2}), part("roof", {0, 0, 3}, {4, 1, 4})}));
  EXPECT_TRUE(contains(e, "test.obj:1:1: error: objects 'wall.0' (line 1) and 'window.1' (line 2) overlap by "
                          "1 x 0.5 x 1 (along x, y, z)"))
      << e;
  EXPECT_TRUE(contains(e, "hint: inference needs non-overlapping parts; separate or merge these objects")) << e;
}

TEST(BoxSplit, DuplicatesAndCoplanarOrEmbeddedFlatPartsOverlap) {
  // Three copies of one box: three pairs.
  std::string e = split_error(test::numbered(
      {part("rect", {0, 0, 0}, {1, 1, 1}), part("rect", {0, 0, 0}, {1, 1, 1}), part("rect", {0, 0, 0}, {1, 1, 1})}));
  EXPECT_TRUE(contains(e, "objects 'rect.0' (line 1) and 'rect.1' (line 2) overlap by 1 x 1 x 1 (along x, y, z); "
                          "2 more pairs overlap"))
      << e;

  // Two facade panels in one plane.
  e = split_error(test::numbered({part("rect", {0, 0, 0}, {2, 0, 2}), part("window", {1, 0, 1}, {3, 0, 3})}));
  EXPECT_TRUE(contains(e, "overlap by 1 x 0 x 1")) << e;

  // A panel inside a wall.
  e = split_error(test::numbered({part("wall", {0, 0, 0}, {4, 1, 3}), part("window", {1, 0.5, 1}, {2, 0.5, 2})}));
  EXPECT_TRUE(contains(e, "'wall.0' (line 1) and 'window.1' (line 2) overlap")) << e;

  // Overlaps inside a splittable building are found too.
  std::vector<LabelledBox> boxes = pinwheel();
  boxes.push_back(part("tower", {4, 0, 0}, {5, 3, 4}, 5));
  boxes.push_back(part("tower", {4.5, 1, 1}, {5, 2, 2}, 6));
  e = split_error(boxes);
  EXPECT_TRUE(contains(e, "test.obj:6:1: error: objects 'tower.5' (line 6) and 'tower.6' (line 7) overlap by "
                          "0.5 x 1 x 1"))
      << e;
}

TEST(BoxSplit, TouchingPartsAndPanelsOnAFaceDoNotOverlap) {
  // A panel lying on a wall's face: allowed, but no cut can separate it.
  const SplitTree t = split(test::numbered({part("wall", {0, 0, 0}, {4, 1, 3}), part("panel", {1, 0, 1}, {2, 0, 2})}));
  EXPECT_EQ(t.kind, Kind::Unsplittable);
  // Boxes sharing faces, edges and corners split.
  const SplitTree u = split(test::numbered({part("a", {0, 0, 0}, {1, 1, 1}), part("b", {1, 0, 0}, {2, 1, 1}),
                                            part("c", {0, 1, 0}, {1, 2, 1}), part("d", {1, 1, 1}, {2, 2, 2})}));
  EXPECT_EQ(split_tree_stats(u).leaves, 4u);
  EXPECT_EQ(split_tree_stats(u).unsplittable, 0u);
}

// A grid of boxes sharing faces, each bound moved by up to 1e-9 as float
// export noise would: the default tolerance snaps them together.
TEST(BoxSplit, FloatNoiseAtSharedFacesSplitsCleanly) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> noise(-1e-9, 1e-9);
  std::vector<LabelledBox> boxes;
  const glm::dvec3 cell(2, 1.5, 3);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 2; ++k) {
        const glm::dvec3 lo = glm::dvec3(i, j, k) * cell;
        const glm::dvec3 hi = lo + cell;
        boxes.push_back(part(k == 1 ? "window" : "rect", lo + glm::dvec3(noise(rng), noise(rng), noise(rng)),
                             hi + glm::dvec3(noise(rng), noise(rng), noise(rng)),
                             static_cast<std::uint32_t>(boxes.size())));
      }
  const double tolerance = default_tolerance(test::example_of(boxes));
  const SplitTree t = split(boxes, tolerance);
  const SplitTreeStats s = split_tree_stats(t);
  EXPECT_EQ(s.leaves, 24u);
  EXPECT_EQ(s.empties, 0u);
  EXPECT_EQ(s.unsplittable, 0u);
  // Compared exactly, the same noise makes slivers of overlap.
  EXPECT_TRUE(contains(split_error(boxes, 0.0), "overlap by"));
}

TEST(BoxSplit, FacadesFlatOnOneAxisSplitOnTheOthers) {
  // The thesis's house with a garage as a 2-D facade: every part at y = 0.
  const double third = 10.0 / 3.0, two_thirds = 20.0 / 3.0;
  const std::vector<LabelledBox> boxes = test::numbered({part("rect", {0, 0, 0}, {two_thirds, 0, two_thirds}),
                                                         part("triangle", {0, 0, two_thirds}, {two_thirds, 0, 10}),
                                                         part("rect", {two_thirds, 0, 0}, {10, 0, third})});
  const SplitTree t = split(boxes);
  ASSERT_EQ(t.kind, Kind::Split);
  EXPECT_EQ(t.axis, 0);
  EXPECT_EQ(t.size().y, 0.0);
  ASSERT_EQ(t.children.size(), 2u);
  EXPECT_EQ(t.children[0].axis, 2);
  EXPECT_EQ(t.children[1].axis, 2);
  EXPECT_EQ(t.children[1].children[1].kind, Kind::Empty);
  const SplitTreeStats s = split_tree_stats(t);
  EXPECT_EQ(s.leaves, 3u);
  EXPECT_EQ(s.empties, 1u);
}

TEST(BoxSplit, AFlatPartCannotBeCutOutOfAThickerSpace) {
  // A panel at y = 0 beside a solid box 1 deep: cutting the panel out along
  // y would make a part of zero length, which derivation skips.
  const SplitTree t = split(test::numbered({part("panel", {0, 0, 0}, {2, 0, 2}), part("box", {3, 0, 0}, {5, 1, 2})}));
  ASSERT_EQ(t.kind, Kind::Split);
  ASSERT_EQ(t.children.size(), 3u);
  EXPECT_EQ(t.children[0].kind, Kind::Unsplittable);
  EXPECT_EQ(t.children[0].children.size(), 1u);
  EXPECT_EQ(t.children[2].kind, Kind::Leaf);
}

// Relabels a tree's leaves through a permutation of the boxes.
SplitTree renumbered(SplitTree t, const std::vector<std::uint32_t>& new_index) {
  if (t.kind == Kind::Leaf) t.box = new_index[t.box];
  for (SplitTree& c : t.children) c = renumbered(std::move(c), new_index);
  return t;
}

TEST(BoxSplit, TheTreeDoesNotDependOnTheOrderOfTheParts) {
  std::vector<LabelledBox> boxes = pinwheel();
  boxes.push_back(part("tower", {4, 0, 0}, {5, 3, 4}, 5));
  boxes.push_back(part("tower", {5, 0, 0}, {6, 3, 2}, 6));
  boxes.push_back(part("door", {7, 1, 0}, {8, 2, 1}, 7));
  const SplitTree t = split(boxes);
  EXPECT_EQ(split(boxes), t);

  std::vector<std::uint32_t> order(boxes.size());
  std::iota(order.begin(), order.end(), 0u);
  std::reverse(order.begin(), order.end());
  std::vector<LabelledBox> reversed;
  for (std::uint32_t i : order) reversed.push_back(boxes[i]);
  // Unsplittable children come in box order, which reversal changes.
  SplitTree r = renumbered(split(reversed), order);
  std::function<void(SplitTree&)> sort_groups = [&](SplitTree& x) {
    if (x.kind == Kind::Unsplittable) {
      std::sort(x.children.begin(), x.children.end(),
                [](const SplitTree& a, const SplitTree& b) { return a.box < b.box; });
    }
    for (SplitTree& c : x.children) sort_groups(c);
  };
  sort_groups(r);
  EXPECT_EQ(r, t);
}

// Cuts [lo, hi] into `count` boxes by random guillotine cuts; about one in
// ten boxes leaves some empty space beside it.
void guillotine(glm::dvec3 lo, glm::dvec3 hi, std::uint32_t count, std::mt19937_64& rng,
                std::vector<LabelledBox>& out) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  if (count == 1) {
    if (unit(rng) < 0.1) {
      const auto a = static_cast<glm::length_t>(rng() % 3);
      const double keep = 0.5 + 0.4 * unit(rng);
      if (rng() % 2 == 0) hi[a] = lo[a] + keep * (hi[a] - lo[a]);
      else lo[a] = hi[a] - keep * (hi[a] - lo[a]);
    }
    out.push_back(part(rng() % 2 == 0 ? "rect" : "window", lo, hi, static_cast<std::uint32_t>(out.size())));
    return;
  }
  // An axis in proportion to its length keeps the pieces near cubes.
  const glm::dvec3 size = hi - lo;
  double pick = unit(rng) * (size.x + size.y + size.z);
  glm::length_t a = 0;
  while (a < 2 && pick >= size[a]) pick -= size[a++];
  const auto k = static_cast<std::uint32_t>(1 + rng() % (count - 1));
  const double at = lo[a] + size[a] * static_cast<double>(k) / static_cast<double>(count);
  glm::dvec3 mid_hi = hi, mid_lo = lo;
  mid_hi[a] = at;
  mid_lo[a] = at;
  guillotine(lo, mid_hi, k, rng, out);
  guillotine(mid_lo, hi, count - k, rng, out);
}

// Not a timing test: the algorithm is O(n log n + n m), and a quadratic one
// would not finish 100,000 parts in a test's time.
TEST(BoxSplit, HundredThousandGuillotineBoxesSplitIntoAsManyLeaves) {
  constexpr std::uint32_t n = 100'000;
  std::mt19937_64 rng(2024);
  std::vector<LabelledBox> boxes;
  boxes.reserve(n);
  guillotine({0, 0, 0}, {1000, 800, 600}, n, rng, boxes);
  std::shuffle(boxes.begin(), boxes.end(), rng);
  ASSERT_EQ(boxes.size(), n);
  const double tolerance = default_tolerance(test::example_of(boxes));
  const SplitTree t = split_boxes(boxes, {tolerance});
  const SplitTreeStats s = split_tree_stats(t);
  EXPECT_EQ(s.leaves, n);
  EXPECT_EQ(s.unsplittable, 0u);
  EXPECT_GT(s.empties, 0u);
  // Each box in exactly one leaf that fits it (one assertion, not 100,000).
  std::vector<int> seen(n, 0);
  std::size_t misfits = 0;
  std::function<void(const SplitTree&)> visit = [&](const SplitTree& x) {
    if (x.kind == Kind::Leaf) {
      ++seen[x.box];
      const LabelledBox& b = boxes[x.box];
      for (int i = 0; i < 3; ++i) {
        if (std::abs(x.min[i] - b.min[i]) > tolerance || std::abs(x.max[i] - b.max[i]) > tolerance) ++misfits;
      }
    }
    for (const SplitTree& c : x.children) visit(c);
  };
  visit(t);
  EXPECT_EQ(misfits, 0u);
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<std::ptrdiff_t>(n));
}

// A street of towers, each of storeys 3 to 4 m high: the storeys of
// different towers meet the air at heights a few centimetres apart, though
// every part is metres thick. At a tolerance of 0.3 m neighbouring heights
// used to chain into one rank tens of metres long, every storey in it flat
// and overlapping the next. Clusters never span more than the tolerance,
// so the street splits into its storeys.
TEST(BoxSplit, CoordinatesCloserThanTheToleranceNeverChainIntoOneRank) {
  std::mt19937_64 rng(1206);
  std::uniform_real_distribution<double> storey(3, 4);
  std::vector<LabelledBox> boxes;
  for (std::uint32_t t = 0; t < 200; ++t) {
    double z = 0;
    for (int k = 0; k < 30; ++k) {
      const double h = storey(rng);
      boxes.push_back(part("rect", {10.0 * t, 0, z}, {10.0 * t + 10, 12, z + h}, static_cast<std::uint32_t>(boxes.size())));
      z += h;
    }
  }
  const double tolerance = 0.3;
  // The case is real: neighbouring heights chain over tens of metres.
  std::vector<double> zs;
  for (const LabelledBox& b : boxes) zs.insert(zs.end(), {b.min.z, b.max.z});
  std::sort(zs.begin(), zs.end());
  double longest_chain = 0, chain_start = zs.front();
  for (std::size_t i = 1; i < zs.size(); ++i) {
    if (zs[i] - zs[i - 1] > tolerance) chain_start = zs[i];
    longest_chain = std::max(longest_chain, zs[i] - chain_start);
  }
  ASSERT_GT(longest_chain, 30.0);
  const SplitTree t = split(boxes, tolerance);
  const SplitTreeStats s = split_tree_stats(t);
  EXPECT_EQ(s.leaves, boxes.size());
  EXPECT_EQ(s.unsplittable, 0u);
}

// The same shape: kinds, axes and boxes equal, extents within tolerance.
void expect_same_shape(const SplitTree& a, const SplitTree& b, double tolerance, std::size_t& differences) {
  if (a.kind != b.kind || a.axis != b.axis || a.box != b.box || a.children.size() != b.children.size()) {
    ++differences;
    return;
  }
  for (int i = 0; i < 3; ++i)
    if (std::abs(a.min[i] - b.min[i]) > tolerance || std::abs(a.max[i] - b.max[i]) > tolerance) ++differences;
  for (std::size_t i = 0; i < a.children.size(); ++i) expect_same_shape(a.children[i], b.children[i], tolerance, differences);
}

// Thousands of parts (the sort takes its radix path) whose every bound an
// exporter moved by float noise: snapping gives the tree of the exact
// parts, though no coordinate is shared exactly any more.
TEST(BoxSplit, NoiseOnEveryBoundOfALargeBuildingChangesNothing) {
  std::mt19937_64 rng(99);
  std::vector<LabelledBox> exact;
  guillotine({0, 0, 0}, {400, 300, 200}, 20'000, rng, exact);
  std::vector<LabelledBox> noisy = exact;
  std::uniform_real_distribution<double> noise(-2e-9, 2e-9);
  for (LabelledBox& b : noisy) {
    for (int a = 0; a < 3; ++a) {
      b.min[a] += noise(rng);
      b.max[a] += noise(rng);
    }
  }
  const double tolerance = default_tolerance(test::example_of(exact));
  const SplitTree t = split_boxes(exact, {tolerance});
  const SplitTree u = split_boxes(noisy, {tolerance});
  EXPECT_EQ(split_tree_stats(u).leaves, exact.size());
  std::size_t differences = 0;
  expect_same_shape(t, u, 1e-8, differences);
  EXPECT_EQ(differences, 0u);
}

}  // namespace
}  // namespace vern
