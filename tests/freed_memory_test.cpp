#include "base/freed_memory.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cstdlib>
#include <cstring>

namespace vern {
namespace {

// glibc's allocator only; AddressSanitizer brings its own, which maps
// large blocks afresh by design.
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)

long page_faults() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt;
}

// Writes every page of a block and reads it back, so that the compiler
// cannot leave the block out.
volatile long sum_of_pages = 0;
void touch(char* block, std::size_t size, char value) {
  std::memset(block, value, size);
  long sum = 0;
  for (std::size_t i = 0; i < size; i += 4096) sum += block[i];
  sum_of_pages = sum_of_pages + sum;
}

// Touches a 24 MB block, frees it, and touches one again: the second
// block's page faults.
long faults_of_a_block_asked_again() {
  constexpr std::size_t kSize = 24u << 20;
  char* first = static_cast<char*>(std::malloc(kSize));
  touch(first, kSize, 1);
  std::free(first);
  const long before = page_faults();
  char* again = static_cast<char*>(std::malloc(kSize));
  touch(again, kSize, 2);
  const long faults = page_faults() - before;
  std::free(again);
  return faults;
}

// Each case runs in a fresh process of its own (gtest re-runs the test
// binary for it), so that what other tests allocated does not count:
// the C library raises its own thresholds after frees.
class FreedMemory : public ::testing::Test {
 protected:
  void SetUp() override { GTEST_FLAG_SET(death_test_style, "threadsafe"); }
};

TEST_F(FreedMemory, ABlockFreedIsReusedWithoutAskingTheSystemAgain) {
  // 24 MB are 6,144 pages; reused, almost none of them faults again.
  EXPECT_EXIT(
      {
        keep_freed_memory();
        std::exit(faults_of_a_block_asked_again() < 100 ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

TEST_F(FreedMemory, WithoutItTheBlockIsGivenBackAndFaultsAgain) {
  // The C library's own settings: the block goes back when freed, and
  // all of its 6,144 pages fault again.
  EXPECT_EXIT(std::exit(faults_of_a_block_asked_again() > 3000 ? 0 : 1), ::testing::ExitedWithCode(0), "");
}
#endif

}  // namespace
}  // namespace vern
