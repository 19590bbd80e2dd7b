// Buildings standing at an angle about z read in their own frame
// (inverse/load/building_angle.hpp).
#include "inverse/load/building_angle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/example_helpers.hpp"

namespace vern {
namespace {

constexpr double kDegree = std::numbers::pi / 180;

// Boxes given along the axes, turned by `angle` about (3, -2) with their
// vertex positions, as a file of the turned building holds them.
Example turned_boxes(const std::vector<LabelledBox>& boxes, double angle) {
  Example e;
  e.source = "turned.obj";
  const double c = std::cos(angle), s = std::sin(angle);
  for (const LabelledBox& b : boxes) {
    std::vector<glm::dvec3> at;
    glm::dvec3 lo(1e300), hi(-1e300);
    for (int k = 0; k < 8; ++k) {
      const glm::dvec3 p(k & 1 ? b.max.x : b.min.x, k & 2 ? b.max.y : b.min.y, k & 4 ? b.max.z : b.min.z);
      at.push_back({3 + c * p.x - s * p.y, -2 + s * p.x + c * p.y, p.z});
      lo = glm::min(lo, at.back());
      hi = glm::max(hi, at.back());
    }
    LabelledBox t = b;
    t.min = lo;
    t.max = hi;
    e.boxes.push_back(t);
    e.positions.add(at, lo, hi);
  }
  update_bounds(e);
  return e;
}

std::vector<LabelledBox> house() {
  using test::part;
  return {part("wall", {0, 0, 0}, {7.2, 5, 3}, 0), part("roof", {0, 0, 3}, {7.2, 5, 4.5}, 1),
          part("window", {0.7, 0, 1}, {1.7, 0.2, 2.2}, 2), part("window", {3.1, 0, 1}, {4.1, 0.2, 2.2}, 3)};
}

TEST(BuildingAngle, AHouseTurned30DegreesIsReadInItsOwnFrame) {
  const Example e = turned_boxes(house(), 30 * kDegree);
  const std::optional<double> angle = building_angle(e, 1e-6);
  ASSERT_TRUE(angle);
  EXPECT_NEAR(*angle, 30 * kDegree, 1e-9);
  const Example back = turned_back(e, *angle);
  ASSERT_EQ(back.boxes.size(), 4u);
  // Each part as modelled, the building moved as a whole.
  const glm::dvec3 shift = back.boxes[0].min - house()[0].min;
  for (std::size_t b = 0; b < 4; ++b) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(back.boxes[b].min[k] - shift[k], house()[b].min[k], 1e-9) << b;
      EXPECT_NEAR(back.boxes[b].max[k] - shift[k], house()[b].max[k], 1e-9) << b;
    }
  }
  EXPECT_NEAR(back.max.x - back.min.x, 7.2, 1e-9);
  EXPECT_NEAR(back.max.y - back.min.y, 5, 1e-9);
}

TEST(BuildingAngle, TheAngleIsTakenModuloAQuarterTurn) {
  EXPECT_NEAR(*building_angle(turned_boxes(house(), 60 * kDegree), 1e-6), 60 * kDegree, 1e-9);
  EXPECT_NEAR(*building_angle(turned_boxes(house(), -20 * kDegree), 1e-6), 70 * kDegree, 1e-9);
  EXPECT_NEAR(*building_angle(turned_boxes(house(), 120 * kDegree), 1e-6), 30 * kDegree, 1e-9);
  EXPECT_NEAR(*building_angle(turned_boxes(house(), 1 * kDegree), 1e-6), 1 * kDegree, 1e-9);
}

TEST(BuildingAngle, HousesAlongTheAxesOrTurnedAQuarterAreNotTurned) {
  EXPECT_FALSE(building_angle(turned_boxes(house(), 0), 1e-6));
  EXPECT_FALSE(building_angle(turned_boxes(house(), 90 * kDegree), 1e-6));
  // Within the tolerance of square: float noise, not a turn.
  EXPECT_FALSE(building_angle(turned_boxes(house(), 1e-9), 1e-6));
  // An example without vertex positions has no angle to read.
  EXPECT_FALSE(building_angle(test::example_of(house()), 1e-6));
}

TEST(BuildingAngle, PartsStandingAtDifferentAnglesAreNoTurnedBuilding) {
  Example e = turned_boxes(house(), 30 * kDegree);
  const Example other = turned_boxes({test::part("shed", {10, 0, 0}, {12, 2, 2}, 4)}, 40 * kDegree);
  std::vector<glm::dvec3> at;
  other.positions.get(0, other.boxes[0].min, other.boxes[0].max, at);
  e.boxes.push_back(other.boxes[0]);
  e.positions.add(at, other.boxes[0].min, other.boxes[0].max);
  update_bounds(e);
  EXPECT_FALSE(building_angle(e, 1e-6));
}

TEST(BuildingAngle, APartOfAnotherOutlineFollowsTheSquareOnes) {
  // A round tower (an octagon from above) beside a turned house.
  Example e = turned_boxes(house(), 30 * kDegree);
  std::vector<glm::dvec3> at;
  glm::dvec3 lo(1e300), hi(-1e300);
  for (int k = 0; k < 8; ++k)
    for (const double z : {0.0, 6.0}) {
      const double a = k * std::numbers::pi / 4 + 0.1;
      at.push_back({20 + 2 * std::cos(a), 2 * std::sin(a), z});
      lo = glm::min(lo, at.back());
      hi = glm::max(hi, at.back());
    }
  LabelledBox tower = test::part("tower", lo, hi, 4);
  e.boxes.push_back(tower);
  e.positions.add(at, lo, hi);
  update_bounds(e);
  const std::optional<double> angle = building_angle(e, 1e-6);
  ASSERT_TRUE(angle);
  EXPECT_NEAR(*angle, 30 * kDegree, 1e-9);
}

}  // namespace
}  // namespace vern
