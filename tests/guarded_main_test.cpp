// What reaches the user when a command's run throws: each kind of failure
// as its exit code and a message naming where (apps/support/guarded_main).
#include "support/guarded_main.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace vern {
namespace {

// A file-system call on a user's path that took no error code: the path's
// fault (a link that leads to itself), reported as an I/O error naming it,
// not as a bug.
int throws_a_filesystem_error(int, char**) {
  throw std::filesystem::filesystem_error(
      "status", std::filesystem::path("prims/loop.obj"),
      std::make_error_code(std::errc::too_many_symbolic_link_levels));
}

TEST(GuardedMainDeathTest, AFileSystemErrorIsAnIoErrorNamingThePath) {
  char name[] = "generate";
  char* argv[] = {name, nullptr};
  EXPECT_EXIT(std::exit(guarded_main("generate", throws_a_filesystem_error, 1, argv)), ::testing::ExitedWithCode(5),
              "prims/loop.obj: error: cannot read or write: Too many levels of symbolic links\n  hint: ");
}

}  // namespace
}  // namespace vern
