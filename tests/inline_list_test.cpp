#include "base/inline_list.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>

#include "inverse/sizes/support.hpp"

namespace vern {
namespace {

template <typename List>
bool held_in_place(const List& list) {
  const auto* at = reinterpret_cast<const char*>(list.begin());
  const auto* self = reinterpret_cast<const char*>(&list);
  return at >= self && at < self + sizeof(List);
}

TEST(InlineList, UpToNElementsAreHeldInPlaceAndMoreGoToTheHeapInOrder) {
  InlineList<int, 2> list;
  EXPECT_TRUE(list.empty());
  list.push_back(1);
  list.emplace_back(2);
  ASSERT_EQ(list.size(), 2u);
  EXPECT_TRUE(held_in_place(list));
  list.push_back(3);
  ASSERT_EQ(list.size(), 3u);
  EXPECT_FALSE(held_in_place(list));
  EXPECT_EQ(list[0], 1);
  EXPECT_EQ(list[1], 2);
  EXPECT_EQ(list.back(), 3);
  EXPECT_EQ(std::vector<int>(list.begin(), list.end()), (std::vector<int>{1, 2, 3}));
  list.clear();
  EXPECT_TRUE(list.empty());
  list.push_back(7);
  EXPECT_TRUE(held_in_place(list));
  EXPECT_EQ(list.front(), 7);
}

TEST(InlineList, CopiesAreEqualValuesOfTheirOwn) {
  using Pairs = InlineList<std::pair<double, double>, 1>;
  Pairs one{{1, 2}};
  Pairs copy = one;
  EXPECT_TRUE(held_in_place(copy));
  EXPECT_EQ(copy, one);
  copy.back().second = 3;
  EXPECT_EQ(one.back().second, 2);
  EXPECT_FALSE(copy == one);

  Pairs two{{2, 1}, {0, 0}};
  Pairs sorted = two;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, (Pairs{{0, 0}, {2, 1}}));
  EXPECT_EQ(two, (Pairs{{2, 1}, {0, 0}}));
  EXPECT_FALSE(two == (Pairs{{2, 1}}));
}

// The supports a check builds most (a range, a point, one clamped or
// added to another) keep their single interval in place.
TEST(InlineList, SupportsOfOneIntervalHoldItInPlace) {
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
