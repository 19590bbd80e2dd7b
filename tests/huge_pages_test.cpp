#include "base/huge_pages.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "base/freed_memory.hpp"
#include "base/parallel_for.hpp"

#if defined(__linux__)
#include <sys/resource.h>
#endif

namespace vern {
namespace {

// Page faults per thread are counted on Linux only.
#if defined(__linux__)

// Whether the system gives huge pages to memory that asks for them.
bool transparent_huge_pages() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  std::getline(in, modes);
  return modes.find("[always]") != std::string::npos || modes.find("[madvise]") != std::string::npos;
}

long thread_page_faults() {
  rusage u{};
  getrusage(RUSAGE_THREAD, &u);
  return u.ru_minflt;
}

// 16 MB in blocks of 4 KB, each written: 4,096 pages. The faults this
// thread took for them.
volatile long sum_of_blocks = 0;
long faults_of_small_blocks() {
  constexpr std::size_t kBlocks = 4096, kSize = 4096;
  std::vector<char*> blocks(kBlocks);
  const long before = thread_page_faults();
  for (char*& b : blocks) {
    b = static_cast<char*>(std::malloc(kSize));
    std::memset(b, 1, kSize);
  }
  const long faults = thread_page_faults() - before;
  long sum = 0;
  for (char* b : blocks) {
    sum += b[kSize - 1];
    std::free(b);
  }
  sum_of_blocks = sum_of_blocks + sum;
  return faults;
}

// The faults of the small blocks in a thread parallel_for starts.
long faults_in_a_worker() {
  long faults[2] = {0, 0};
  parallel_for(2, 2, [&](std::size_t i) { faults[i] = faults_of_small_blocks(); });
  return std::max(faults[0], faults[1]);
}

// Each case runs in a fresh process (a gtest death test): the choice is
// the whole process's, and other tests' allocations would count. It says
// its counts, which gtest shows when a case fails.
int faults_within(long most, long least) {
  const long here = faults_of_small_blocks(), worker = faults_in_a_worker();
  std::fprintf(stderr, "faults: %ld on this thread, %ld on a worker\n", here, worker);
  return here >= least && here <= most && worker >= least && worker <= most ? 0 : 1;
}

class HugePages : public ::testing::Test {
 protected:
  void SetUp() override {
    // glibc's allocator only (a sanitizer brings its own).
    if (!huge_pages_built()) GTEST_SKIP() << "this build does not ask for huge pages";
    if (!transparent_huge_pages()) GTEST_SKIP() << "this system gives no transparent huge pages";
    GTEST_FLAG_SET(death_test_style, "threadsafe");
  }
};

TEST_F(HugePages, TheHeapOfThisThreadAndOfWorkersTakesAFaultPerHugePage) {
  // 16 MB are 8 huge pages. The reserve's first huge page begins at a
  // 2 MB boundary: up to 2 MB before it (512 pages) are ordinary pages.
  EXPECT_EXIT(
      {
        keep_freed_memory();
        use_huge_pages();
        std::exit(faults_within(700, 0));
      },
      ::testing::ExitedWithCode(0), "");
}

TEST_F(HugePages, WithoutThemEveryPageFaults) {
  // Not asked for: each of the 4,096 pages faults, on this thread and on
  // a worker's.
  EXPECT_EXIT(
      {
        keep_freed_memory();
        std::exit(faults_within(1'000'000, 3000));
      },
      ::testing::ExitedWithCode(0), "");
}
#endif

}  // namespace
}  // namespace vern
