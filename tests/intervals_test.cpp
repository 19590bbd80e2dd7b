#include "inverse/intervals.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "inverse/support.hpp"

namespace vern {
namespace {

bool held_in_place(const Intervals& list) {
  const auto* at = reinterpret_cast<const char*>(list.begin());
  const auto* self = reinterpret_cast<const char*>(&list);
  return at >= self && at < self + sizeof(Intervals);
}

TEST(Intervals, OneIntervalIsHeldInPlaceAndMoreGoToTheHeapInOrder) {
  Intervals list;
  EXPECT_TRUE(list.empty());
  list.emplace_back(1, 2);
  ASSERT_EQ(list.size(), 1u);
  EXPECT_TRUE(held_in_place(list));
  EXPECT_EQ(list.front(), (Intervals::value_type{1, 2}));
  list.emplace_back(3, 4);
  list.emplace_back(5, 6);
  ASSERT_EQ(list.size(), 3u);
  EXPECT_FALSE(held_in_place(list));
  EXPECT_EQ(list[0], (Intervals::value_type{1, 2}));
  EXPECT_EQ(list[1], (Intervals::value_type{3, 4}));
  EXPECT_EQ(list.back(), (Intervals::value_type{5, 6}));
  list.clear();
  EXPECT_TRUE(list.empty());
  list.emplace_back(7, 8);
  EXPECT_TRUE(held_in_place(list));
  EXPECT_EQ(list.back(), (Intervals::value_type{7, 8}));
}

TEST(Intervals, CopiesAreEqualValuesOfTheirOwn) {
  Intervals one{{1, 2}};
  Intervals copy = one;
  EXPECT_TRUE(held_in_place(copy));
  EXPECT_EQ(copy, one);
  copy.back().second = 3;
  EXPECT_EQ(one.back().second, 2);
  EXPECT_FALSE(copy == one);

  Intervals two{{2, 1}, {0, 0}};
  Intervals moved = two;
  std::sort(moved.begin(), moved.end());
  EXPECT_EQ(moved, (Intervals{{0, 0}, {2, 1}}));
  EXPECT_EQ(two, (Intervals{{2, 1}, {0, 0}}));
  EXPECT_FALSE(two == (Intervals{{2, 1}}));
}

// The supports a check builds most (a range, a point, one clamped or
// added to another) keep their single interval in place.
TEST(Intervals, SupportsOfOneIntervalStayInPlace) {
  const Support a = Support::range(2, 5);
  const Support b = Support::point(1);
  for (const Support& s : {a, b, a + b, a.clamp(3, 10), a.unite(Support::range(4, 6)), a - b}) {
    ASSERT_EQ(s.intervals.size(), 1u) << s.describe();
    EXPECT_TRUE(held_in_place(s.intervals)) << s.describe();
  }
  const Support gap = a.unite(Support::range(7, 8));
  EXPECT_EQ(gap.intervals, (Intervals{{2, 5}, {7, 8}}));
  EXPECT_EQ(gap.describe(), "[2, 5] u [7, 8]");
}

}  // namespace
}  // namespace vern
