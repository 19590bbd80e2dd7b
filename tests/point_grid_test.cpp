#include "inverse/load/point_grid.hpp"

#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace vern {
namespace {

std::vector<glm::dvec3> random_points(std::size_t n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  std::vector<glm::dvec3> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back({u(rng), u(rng), u(rng)});
  return out;
}

TEST(PointGrid, FindsAPointWithinTheToleranceOnEveryAxis) {
  const std::vector<glm::dvec3> corners = {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}, {2, 3, 4}};
  const PointGrid grid(corners, 0.01);
  EXPECT_TRUE(grid.near({2.009, 2.991, 4.0}));
  EXPECT_FALSE(grid.near({2.011, 3.0, 4.0}));   // beyond on x
  EXPECT_FALSE(grid.near({1.0, 1.5, 2.0}));     // between the corners
  EXPECT_TRUE(grid.covers({{0, 0, 0.005}, {0.005, 3, 0}}));
  EXPECT_FALSE(grid.covers({{0, 0, 0}, {1, 1, 1}}));
}

bool brute_near(const std::vector<glm::dvec3>& points, glm::dvec3 q, double tol) {
  for (const glm::dvec3& p : points) {
    const glm::dvec3 d = glm::abs(p - q);
    if (d.x <= tol && d.y <= tol && d.z <= tol) return true;
  }
  return false;
}

TEST(PointGrid, AnswersAsReadingEveryPointForFewAndManyPoints) {
  // A few points are read in turn, many are binned: either way the answer
  // is the one of reading every point.
  const double tol = 0.05;
  for (const std::size_t n : {std::size_t{12}, std::size_t{500}}) {
    const std::vector<glm::dvec3> points = random_points(n, static_cast<std::uint32_t>(n));
    const PointGrid grid(points, tol);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> jitter(-0.08, 0.08);
    int near = 0, far = 0;
    for (const glm::dvec3& p : points) {
      for (int k = 0; k < 20; ++k) {
        const glm::dvec3 q = p + glm::dvec3{jitter(rng), jitter(rng), jitter(rng)};
        const bool expected = brute_near(points, q, tol);
        (expected ? near : far) += 1;
        EXPECT_EQ(grid.near(q), expected) << n << " points";
      }
    }
    EXPECT_GT(near, 0);
    EXPECT_GT(far, 0);
    EXPECT_TRUE(grid.covers(points));
  }
}

TEST(PointGrid, AnEmptySetHoldsNothing) {
  const PointGrid grid({}, 0.1);
  EXPECT_FALSE(grid.near({0, 0, 0}));
  EXPECT_TRUE(grid.covers({}));
}

}  // namespace
}  // namespace vern
