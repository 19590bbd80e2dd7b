// parallel_for: every index once, and the error of the lowest failing
// index whatever the thread count.
#include "base/parallel_for.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

namespace vern {
namespace {

TEST(ParallelFor, RunsEveryIndexOnceAndReportsProgress) {
  for (const unsigned threads : {1u, 2u, 8u}) {
    std::vector<std::atomic<int>> runs(1000);
    std::size_t last = 0;
    parallel_for(
        runs.size(), threads, [&](std::size_t i) { ++runs[i]; }, [&](std::size_t done) { last = std::max(last, done); });
    for (const auto& r : runs) EXPECT_EQ(r.load(), 1);
    EXPECT_EQ(last, runs.size());
  }
}

TEST(ParallelFor, TheLowestFailingIndexIsReported) {
  for (const unsigned threads : {1u, 2u, 4u}) {
    try {
      parallel_for(200, threads, [](std::size_t i) {
        if (i == 37 || i == 150) throw std::runtime_error("item " + std::to_string(i));
      });
      FAIL() << "no error";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "item 37") << threads << " threads";
    }
  }
}

TEST(ParallelFor, AnEmptyRangeRunsNothing) {
  bool called = false;
  parallel_for(0, 4, [&](std::size_t) { called = true; });
  EXPECT_FALSE(called);
}

}  // namespace
}  // namespace vern
