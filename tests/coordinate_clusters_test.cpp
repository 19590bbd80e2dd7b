#include "inverse/load/coordinate_clusters.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace vern {
namespace {

using Starts = std::vector<std::uint32_t>;

TEST(CoordinateClusters, NeighboursWithinTheToleranceAreOneAndGapsBeyondItSeparate) {
  EXPECT_EQ(cluster_starts(std::vector<double>{}, 0.1), Starts{});
  EXPECT_EQ(cluster_starts(std::vector<double>{3}, 0.1), (Starts{0}));
  EXPECT_EQ(cluster_starts(std::vector<double>{0, 0.05, 1, 1, 1.02, 2}, 0.1), (Starts{0, 2, 5}));
}

// Three window edges a few centimetres apart at a tolerance of 0.05 m:
// each lies within the tolerance of the next, but joined they would span
// 0.07 m; the closer pair is one coordinate, the third stays apart.
TEST(CoordinateClusters, AChainLongerThanTheToleranceIsCutWhereItsGapsAreWidest) {
  EXPECT_EQ(cluster_starts(std::vector<double>{1.0, 1.03, 1.07}, 0.05), (Starts{0, 2}));
  EXPECT_EQ(cluster_starts(std::vector<double>{1.0, 1.04, 1.07}, 0.05), (Starts{0, 1}));
  // Equal gaps are joined left to right.
  EXPECT_EQ(cluster_starts(std::vector<double>{0, 1, 2, 3}, 1.5), (Starts{0, 2}));
}

// Random coordinates a fraction of the tolerance apart, many repeated:
// every cluster spans at most the tolerance, equal coordinates are never
// parted, and clusters are as coarse as that allows: two neighbouring
// clusters together always span more than the tolerance.
TEST(CoordinateClusters, ClustersNeverSpanMoreThanTheToleranceNorPartEqualCoordinates) {
  std::mt19937_64 rng(61206);
  for (int trial = 0; trial < 50; ++trial) {
    std::uniform_real_distribution<double> at(0, 10 + trial);
    std::vector<double> v;
    for (int k = 0; k < 400; ++k) {
      v.push_back(at(rng));
      if (k % 3 == 0) v.push_back(v.back());
    }
    std::sort(v.begin(), v.end());
    const double tolerance = 0.2;
    const Starts s = cluster_starts(v, tolerance);
    ASSERT_FALSE(s.empty());
    EXPECT_EQ(s.front(), 0u);
    ASSERT_TRUE(std::is_sorted(s.begin(), s.end()));
    for (std::size_t c = 0; c < s.size(); ++c) {
      const std::uint32_t from = s[c], to = c + 1 < s.size() ? s[c + 1] : static_cast<std::uint32_t>(v.size());
      ASSERT_LT(from, to);
      EXPECT_LE(v[to - 1] - v[from], tolerance);
      if (from > 0) {
        EXPECT_LT(v[from - 1], v[from]) << "equal coordinates parted at " << from;
      }
      if (c + 1 < s.size()) {
        const std::uint32_t end = c + 2 < s.size() ? s[c + 2] : static_cast<std::uint32_t>(v.size());
        EXPECT_GT(v[end - 1] - v[from], tolerance) << "two clusters that fit together at " << from;
      }
    }
  }
}

}  // namespace
}  // namespace vern
