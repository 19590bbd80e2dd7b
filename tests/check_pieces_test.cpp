// The small pieces check is built from (check.hpp lists them), each on its
// own: where boxes may be cut along an axis (check_cuts.hpp), the scales a
// placement leaves possible (check_scale.hpp) and the trail of bindings of
// unknown random values (check_bindings.hpp). check_test.cpp tests them
// together, through check_example.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "inverse/check/check_bindings.hpp"
#include "inverse/check/check_cuts.hpp"
#include "inverse/check/check_scale.hpp"

namespace vern::check_detail {
namespace {

LabelledBox box(const char* label, double x0, double x1) {
  LabelledBox b;
  b.label = label;
  b.min = {x0, 0, 0};
  b.max = {x1, 1, 1};
  return b;
}

// ---- cuts ----

// The cuts of all the boxes along the scope's x, which runs as am says.
Cuts cuts(const std::vector<LabelledBox>& boxes, double length, AxisMap am = AxisMap{0, 1, 0}) {
  BoxList all;
  for (std::uint32_t k = 0; k < boxes.size(); ++k) all.push_back(k);
  return make_cuts(boxes, all, am, length, 1e-6, 1e-6);
}

TEST(CheckCuts, AreTheFacesNoBoxCrosses) {
  // A wall, a door over 2..5 and a window inside the door's span: no cut
  // at the window's faces, which the door crosses.
  const std::vector<LabelledBox> boxes = {box("wall", 0, 2), box("door", 2, 5), box("window", 3, 4)};
  const Cuts c = cuts(boxes, 6);
  EXPECT_EQ(c.at, (std::vector<double>{0, 2, 5, 6}));
  ASSERT_EQ(c.segments(), 3u);
  EXPECT_EQ(c.boxes(0, 1), (BoxList{0}));
  EXPECT_EQ(c.boxes(1, 2), (BoxList{1, 2}));
  EXPECT_TRUE(c.boxes(2, 3).empty());
  EXPECT_EQ(c.between(0, 3), 3u);
  EXPECT_EQ(c.boxes(1, 3), (BoxList{1, 2}));
  EXPECT_TRUE(c.outside.empty());
}

TEST(CheckCuts, SnapFacesWithinTheTolerance) {
  // 2 and 2.0000004 are one cut; a face within the tolerance of the
  // scope's end is the end.
  const std::vector<LabelledBox> boxes = {box("a", 0, 2), box("b", 2.0000004, 5.9999996)};
  const Cuts c = cuts(boxes, 6);
  EXPECT_EQ(c.at, (std::vector<double>{0, 2, 6}));
}

// Snapped to a noise level of 0.05 (Example::snapped), faces apart are
// cuts apart however close (a window edge 0.03 from a wall's), while faces
// within the level of the scope's ends are the ends: the grammar placed
// the scope, within the level.
TEST(CheckCuts, FacesApartAreCutsApartWithACutToleranceAndTheEndsTakeTheLevel) {
  BoxList all{0, 1, 2};
  const std::vector<LabelledBox> boxes = {box("wall", -0.02, 0.97), box("window", 0.97, 1.0), box("wall", 1.0, 6.04)};
  const Cuts c = make_cuts(boxes, all, AxisMap{0, 1, 0}, 6, 0.05, 1e-6);
  EXPECT_EQ(c.at, (std::vector<double>{0, 0.97, 1.0, 6}));
  EXPECT_TRUE(c.outside.empty());
  // With one tolerance for both, the window's faces are one cut: it is
  // flat there, as thin as nothing.
  EXPECT_EQ(make_cuts(boxes, all, AxisMap{0, 1, 0}, 6, 0.05, 0.05).at, (std::vector<double>{0, 0.97, 0.97, 6}));
}

TEST(CheckCuts, GiveAFlatBoxAZeroLengthSegment) {
  // A panel of no thickness at 2: the cut appears twice, the panel
  // between the copies, so a part boundary there can give it to either side.
  const std::vector<LabelledBox> boxes = {box("a", 0, 2), box("panel", 2, 2), box("b", 2, 4)};
  const Cuts c = cuts(boxes, 4);
  EXPECT_EQ(c.at, (std::vector<double>{0, 2, 2, 4}));
  ASSERT_EQ(c.segments(), 3u);
  EXPECT_EQ(c.boxes(1, 2), (BoxList{1}));
}

TEST(CheckCuts, FollowATurnedAxisAndCollectBoxesOutside) {
  // The scope's x runs along world -x from 6: local t = 6 - w.
  const std::vector<LabelledBox> boxes = {box("a", 0, 2), box("b", 7, 8)};
  const Cuts c = cuts(boxes, 6, AxisMap{0, -1, 6});
  EXPECT_EQ(c.at, (std::vector<double>{0, 4, 6}));
  EXPECT_EQ(c.outside, (BoxList{1}));
}

TEST(CheckCuts, MapAQuarterTurnedScopeOnly) {
  Scope s;
  s.origin = {1, 2, 3};
  s.frame = glm::dmat3(glm::dvec3(0, 1, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, 1));
  const auto x = axis_map(s, Axis::X), y = axis_map(s, Axis::Y);
  ASSERT_TRUE(x && y);
  EXPECT_EQ(x->world, 1);
  EXPECT_EQ(x->sign, 1);
  EXPECT_EQ(y->world, 0);
  EXPECT_EQ(y->sign, -1);
  EXPECT_EQ(y->local(0.5), 0.5);  // -(0.5 - 1)
  const double c = std::sqrt(0.5);
  s.frame = glm::dmat3(glm::dvec3(c, c, 0), glm::dvec3(-c, c, 0), glm::dvec3(0, 0, 1));
  EXPECT_FALSE(axis_map(s, Axis::X));
  EXPECT_TRUE(axis_map(s, Axis::Z));
}

TEST(CheckCuts, SpellTheirWorldPositions) {
  const std::vector<LabelledBox> boxes = {box("a", 0, 2.5)};
  const Cuts c = cuts(boxes, 6);
  EXPECT_EQ(cuts_text(c, AxisMap{0, 1, 0}), "x = 0, 2.5, 6");
}

// ---- scale ----

TEST(CheckScale, NarrowsToTheScalesEveryPartAllows) {
  ScaleState sc;
  sc.limit(0.5, 4);
  sc.limit(1, 10);
  EXPECT_TRUE(sc.ok());
  EXPECT_EQ(sc.set(), Support::range(1, 4));
  // A set of two intervals is kept exactly, not as its hull.
  sc.limit(Support::range(0, 2).unite(Support::range(3, 5)));
  EXPECT_EQ(sc.set(), Support::range(1, 2).unite(Support::range(3, 4)));
  sc.limit(2.5, 2.8);
  EXPECT_FALSE(sc.ok());
}

TEST(CheckScale, CountsMissesAsAPenaltyNotAVerdict) {
  ScaleState sc;
  sc.require(-1);  // a length within its size: no miss
  EXPECT_TRUE(sc.ok());
  sc.require(0.25);
  sc.require(0.5);
  EXPECT_FALSE(sc.ok());
  EXPECT_EQ(sc.penalty, 0.75);
}

TEST(CheckScale, MeasuresTheDistanceToASupport) {
  const Support s = Support::range(1, 2).unite(Support::range(4, 5));
  EXPECT_EQ(distance_to(s, 1.5), 0);
  EXPECT_EQ(distance_to(s, 3.5), 0.5);
  EXPECT_EQ(distance_to(s, 7), 2);
  EXPECT_TRUE(std::isinf(distance_to(Support{}, 1)));
}

TEST(CheckScale, FindsTheScalesWhereLowerLinesStayBelowUpperOnes) {
  // A length at least 3 and at most k (a relative part of share 1).
  const std::vector<Line> lowers = {{0, 3}}, uppers = {{1, 0}};
  const auto [lo, hi] = feasible_scales(lowers, uppers, 0, 5, 0);
  EXPECT_EQ(lo, 3);
  EXPECT_EQ(hi, 5);
  EXPECT_EQ(least_excess(lowers, uppers, 0, 5), -2);  // at k = 5, 2 to spare
  // With k at most 2, the best is 1 metre short.
  const auto [lo2, hi2] = feasible_scales(lowers, uppers, 0, 2, 0);
  EXPECT_GT(lo2, hi2);
  EXPECT_EQ(least_excess(lowers, uppers, 0, 2), 1);
}

// ---- bindings ----

TEST(CheckBindings, UndoTakesBackBindingsToAMark) {
  Bindings b({}, {});
  const int u = b.add({Support::range(0, 1), std::nullopt, "s1", {}});
  b.enter({0, {Slot{Value(), u}}});
  EXPECT_FALSE(b.binding(ExprKind::Param, 0).known);
  const std::size_t mark = b.trail_size();
  b.bind(u, 0.25);
  EXPECT_TRUE(b.binding(ExprKind::Param, 0).known);
  EXPECT_EQ(b.binding(ExprKind::Param, 0).value.number(), 0.25);
  b.undo(mark);
  EXPECT_FALSE(b.binding(ExprKind::Param, 0).known);
  EXPECT_EQ(b.binding(ExprKind::Param, 0).support, Support::range(0, 1));
}

TEST(CheckBindings, DroppedUnknownsLeaveTheTrail) {
  Bindings b({Slot{Value(2.0), -1}}, {});
  const int kept = b.add({Support::range(0, 1), std::nullopt, "a", {}});
  const int dropped = b.add({Support::range(0, 1), std::nullopt, "b", {}});
  b.bind(kept, 0.5);
  b.bind(dropped, 0.5);
  b.drop_unknowns(1);
  EXPECT_EQ(b.unknown_count(), 1u);
  EXPECT_EQ(b.trail_size(), 1u);
  b.undo(0);
  EXPECT_FALSE(b.unknown(kept).value);
  EXPECT_EQ(b.binding(ExprKind::Constant, 0).value.number(), 2.0);
}

}  // namespace
}  // namespace vern::check_detail
