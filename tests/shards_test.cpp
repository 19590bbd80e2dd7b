// Slices of a run for generate --shard (forward/shards.hpp).
#include "forward/shards.hpp"

#include <gtest/gtest.h>

namespace vern {
namespace {

TEST(Shards, SlicesAreDisjointInOrderCoverTheRunAndDifferByOneAtMost) {
  for (std::uint32_t total : {0u, 1u, 7u, 10u, 1000u, 4'000'000'000u})
    for (std::uint32_t n : {1u, 2u, 3u, 7u, 16u}) {
      std::uint32_t next = 0, smallest = UINT32_MAX, largest = 0;
      for (std::uint32_t k = 1; k <= n; ++k) {
        const Slice s = shard_slice(total, {k, n});
        EXPECT_EQ(s.first, next) << total << " " << k << "/" << n;
        next = s.first + s.count;
        smallest = std::min(smallest, s.count);
        largest = std::max(largest, s.count);
      }
      EXPECT_EQ(next, total) << total << " in " << n;
      EXPECT_LE(largest - smallest, 1u) << total << " in " << n;
    }
}

TEST(Shards, OnlyKOfNWithKFromOneToNIsAShard) {
  ASSERT_TRUE(parse_shard("2/5"));
  EXPECT_EQ(parse_shard("2/5")->index, 2u);
  EXPECT_EQ(parse_shard("2/5")->count, 5u);
  EXPECT_TRUE(parse_shard("1/1"));
  for (const char* bad : {"", "2", "0/5", "6/5", "2/0", "-1/5", "2/5/1", "a/5", "2/ 5", " 2/5", "2.0/5", "99999999999/5"})
    EXPECT_FALSE(parse_shard(bad)) << bad;
}

}  // namespace
}  // namespace vern
