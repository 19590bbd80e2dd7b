#include "inverse/sizes/support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace vern {
namespace {

// A support of `count` random pieces (points, ranges, whole-number ranges)
// between 0 and 100, built through the public constructors.
Support random_support(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> at(0, 100);
  std::uniform_real_distribution<double> width(0, 3);
  std::uniform_int_distribution<int> kind(0, 2);
  Support s;
  for (int k = 0; k < count; ++k) {
    const double lo = at(rng);
    switch (kind(rng)) {
      case 0: s = s.unite(Support::point(lo)); break;
      case 1: s = s.unite(Support::range(lo, lo + width(rng))); break;
      default: s = s.unite(Support::integers(lo, lo + 10 * width(rng))); break;
    }
  }
  return s;
}

bool sorted_and_disjoint(const Support& s) {
  for (std::size_t i = 0; i < s.intervals.size(); ++i) {
    if (s.intervals[i].first > s.intervals[i].second) return false;
    if (i > 0 && s.intervals[i].first <= s.intervals[i - 1].second) return false;
  }
  return true;
}

// The union holds exactly the values of either set, as sorted disjoint
// intervals, whichever order the two are given in.
TEST(Support, AUnionHoldsTheValuesOfEitherSetAsSortedDisjointIntervals) {
  std::mt19937 rng(20261206);
  std::uniform_real_distribution<double> probe(-1, 101);
  for (int trial = 0; trial < 300; ++trial) {
    const Support a = random_support(rng, 1 + trial % 40);
    const Support b = random_support(rng, 1 + trial % 7);
    const Support u = a.unite(b);
    ASSERT_TRUE(sorted_and_disjoint(u)) << u.describe();
    EXPECT_EQ(u, b.unite(a));
    std::vector<double> values;
    for (const Support* s : {&a, &b})
      for (const auto& [lo, hi] : s->intervals) values.insert(values.end(), {lo, hi, (lo + hi) / 2, lo - 1e-9, hi + 1e-9});
    for (int k = 0; k < 50; ++k) values.push_back(probe(rng));
    for (double v : values) EXPECT_EQ(u.contains(v), a.contains(v) || b.contains(v)) << v << " in " << u.describe();
  }
}

// Two large whole-number sets stay whole numbers; joined with a continuous
// set, a whole-number set widens to its intervals.
TEST(Support, WholeNumbersStayWholeOnlyWhenBothSetsAre) {
  const Support whole = Support::integers(0, 100).unite(Support::integers(200, 300));
  EXPECT_TRUE(whole.integer);
  EXPECT_TRUE(whole.contains(250));
  EXPECT_FALSE(whole.contains(50.5));
  EXPECT_FALSE(whole.contains(150));
  const Support widened = Support::integers(0, 100).unite(Support::range(200, 201));
  EXPECT_FALSE(widened.integer);
  EXPECT_TRUE(widened.contains(50.5));
  EXPECT_TRUE(widened.contains(200.5));
  EXPECT_FALSE(widened.contains(150));
}

// Past 256 intervals a support is its hull: supports prune and explain,
// they need not list thousands of lengths one by one.
TEST(Support, AUnionOfManyPointsBecomesTheirHull) {
  Support s;
  for (int k = 0; k < 257; ++k) s = s.unite(Support::point(2.0 * k));
  EXPECT_EQ(s, Support::range(0, 512));
  Support few;
  for (int k = 0; k < 200; ++k) few = few.unite(Support::point(2.0 * (199 - k)));
  ASSERT_EQ(few.intervals.size(), 200u);
  EXPECT_TRUE(few.contains(398));
  EXPECT_FALSE(few.contains(1));
}

}  // namespace
}  // namespace vern
