// The tests' own child processes (support/child_process.hpp): a tool's
// peak memory is measured as its own, whatever the size of the test
// process that starts it.
#include "support/child_process.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "support/bad_input_helpers.hpp"

namespace vern::test {
namespace {

TEST(ChildProcess, APeakMeasuredIsTheToolsOwnNotTheTestsProcesss) {
  // 300 MB held and touched here: a child forked from this process was
  // measured at least that large (Linux counts the parent's memory at the
  // fork in the child's peak), which failed every memory bound when the
  // whole suite ran in one process.
  std::vector<char> held(300u << 20);
  std::memset(held.data(), 1, held.size());
  TempFolder dir;
  const MeasuredResult m = run_program_measured("check", {"--help"}, dir.path());
  EXPECT_EQ(m.result.exit_code, 0) << m.result.err;
  EXPECT_GT(m.peak_kib, 0);
  EXPECT_LT(m.peak_kib, 100 * 1024) << "peak memory in KiB";
  EXPECT_EQ(held[held.size() / 2], 1);  // held until here
}

TEST(ChildProcess, AMeasuredToolEndsAsTheToolEnded) {
  // Through the peak meter, a usage error is still exit code 2.
  TempFolder dir;
  const MeasuredResult m = run_program_measured("check", {}, dir.path());
  EXPECT_EQ(m.result.exit_code, 2) << m.result.err;
  EXPECT_NE(m.result.err.find("check"), std::string::npos) << m.result.err;
}

}  // namespace
}  // namespace vern::test
