// Coordinates that measure one place made one (inverse/load/snapped_coordinates.hpp):
// rows and columns annotated a pixel apart line up, places further apart
// than the noise level stay apart, and no coordinate moves by more than it.
#include "inverse/load/snapped_coordinates.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>

#include "support/example_helpers.hpp"

namespace vern {
namespace {

using test::example_of;
using test::part;

// The distinct values of the bounds on one axis.
std::set<double> places(const Example& e, int axis) {
  std::set<double> out;
  for (const LabelledBox& b : e.boxes) {
    out.insert(b.min[axis]);
    out.insert(b.max[axis]);
  }
  return out;
}

TEST(SnappedCoordinates, ARowAnnotatedAPixelApartLinesUpWhereMostPartsPutIt) {
  // A facade and a row of three windows whose sills and heads wander by a
  // centimetre; the facade's edges are where the facade put them.
  const Example e = example_of({part("facade", {0, 0, 0}, {10, 0.2, 6}, 0),
                                part("window", {1, 0, 1.00}, {2, 0.2, 2.49}, 1),
                                part("window", {4, 0, 1.01}, {5, 0.2, 2.50}, 2),
                                part("window", {7, 0, 0.99}, {8, 0.2, 2.51}, 3)});
  const Example s = snapped_coordinates(e, 0.03);
  EXPECT_EQ(places(s, 2), (std::set<double>{0, 1.00, 2.50, 6}));
  for (std::size_t b = 1; b < 4; ++b) {
    EXPECT_EQ(s.boxes[b].min.z, 1.00);
    EXPECT_EQ(s.boxes[b].max.z, 2.50);
  }
  EXPECT_EQ(s.boxes[0].max, glm::dvec3(10, 0.2, 6));
  EXPECT_EQ(s.snapped, 0.03);
  EXPECT_NEAR(largest_move(e, s), 0.01, 1e-12);
  // Without noise to settle, nothing moves.
  EXPECT_EQ(largest_move(e, snapped_coordinates(e, 1e-6)), 0);
}

TEST(SnappedCoordinates, PlacesFurtherApartThanTheLevelStayApart) {
  // Three window edges 0.04 m apart at a level of 0.05 m: not one place
  // (the outer two are 0.08 m apart), and the two places they become lie
  // more than the level apart, leaving no sliver between them.
  const Example e = example_of({part("window", {1.00, 0, 0}, {2, 0.2, 1}, 0),
                                part("window", {1.04, 0, 2}, {2, 0.2, 3}, 1),
                                part("window", {1.08, 0, 4}, {2, 0.2, 5}, 2)});
  const Example s = snapped_coordinates(e, 0.05);
  const std::set<double> x = places(s, 0);
  ASSERT_EQ(x.size(), 3u);  // two places for the three edges, and 2
  EXPECT_GT(*std::next(x.begin()) - *x.begin(), 0.05);
  EXPECT_LE(largest_move(e, s), 0.05);
}

// Random rows of random boxes, coordinates a fraction of the level apart:
// no bound moves by more than the level, no box turns inside out, bounds
// that were equal stay equal, and bounds further apart than the level
// never become one.
TEST(SnappedCoordinates, NoBoundMovesByMoreThanTheLevelAndNoneFurtherApartBecomeOne) {
  std::mt19937_64 rng(61207);
  std::uniform_real_distribution<double> at(0, 3), length(0.001, 0.5);
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<LabelledBox> boxes;
    for (std::uint32_t k = 0; k < 60; ++k) {
      const glm::dvec3 lo(at(rng), at(rng), at(rng));
      boxes.push_back(part("p", lo, lo + glm::dvec3(length(rng), length(rng), length(rng)), k));
    }
    const Example e = example_of(boxes);
    const double level = 0.02;
    const Example s = snapped_coordinates(e, level);
    EXPECT_LE(largest_move(e, s), level);
    for (std::size_t a = 0; a < boxes.size(); ++a) {
      for (int axis = 0; axis < 3; ++axis) {
        ASSERT_LE(s.boxes[a].min[axis], s.boxes[a].max[axis]);
        for (std::size_t b = 0; b < boxes.size(); ++b) {
          const double raw = e.boxes[a].min[axis], other = e.boxes[b].max[axis];
          const double now = s.boxes[a].min[axis], other_now = s.boxes[b].max[axis];
          if (raw == other) {
            EXPECT_EQ(now, other_now);
          }
          if (std::abs(raw - other) > level) {
            EXPECT_NE(now, other_now) << raw << " " << other;
          }
        }
      }
    }
  }
}

TEST(SnappedCoordinates, PartsPositionsMoveWithTheirBounds) {
  Example e = example_of({part("window", {1, 0, 1.01}, {2, 0.2, 2.5}, 0), part("window", {4, 0, 1.0}, {5, 0.2, 2.5}, 1)});
  for (const LabelledBox& b : e.boxes) {
    const std::vector<glm::dvec3> corners = {b.min, b.max, {b.min.x, b.max.y, b.min.z}};
    e.positions.add(corners, b.min, b.max);
  }
  const Example s = snapped_coordinates(e, 0.03);
  std::vector<glm::dvec3> at;
  s.positions.get(0, s.boxes[0].min, s.boxes[0].max, at);
  ASSERT_EQ(at.size(), 3u);
  EXPECT_EQ(at[0], s.boxes[0].min);
  EXPECT_EQ(at[1], s.boxes[0].max);
  EXPECT_EQ(at[0].z, 1.0);
}

}  // namespace
}  // namespace vern
