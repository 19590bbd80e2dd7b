// check's refusals as a user meets them: a grammar check cannot follow
// stops with the grammar's file:line:col, the rule chain, the example it
// was checking and a hint; memory stays bounded whatever the grammar asks.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/bad_input_helpers.hpp"
#include "support/run_command.hpp"

namespace vern {
namespace {

using test::TempFolder;

const std::filesystem::path kCorpus = VERN_SOURCE_DIR "/tests/bad_inputs";

void copy_inputs(const TempFolder& dir, const std::string& grammar) {
  std::filesystem::copy_file(kCorpus / "grammar" / grammar, dir / grammar);
  std::filesystem::copy_file(kCorpus / "obj/two_parts.obj", dir / "two_parts.obj");
}

TEST(CheckCli, ARefusedRepeatNamesItsPlaceTheChainAndTheExample) {
  TempFolder dir;
  copy_inputs(dir, "repeat_tiny_tile.grm");
  const auto r = test::run_program("check", {"repeat_tiny_tile.grm", "two_parts.obj"}, dir.path());
  EXPECT_EQ(r.exit_code, 4) << r.err;
  EXPECT_EQ(r.out, "");
  // The grammar's place comes first, as generate's errors do; the example
  // is named on a line of its own.
  EXPECT_EQ(r.err.rfind("repeat_tiny_tile.grm:1:7: error: repeat would make ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("\n  rule chain: p\n  example: two_parts.obj\n  hint: raise the limit with --max-steps"),
            std::string::npos)
      << r.err;
}

TEST(CheckCli, ARaisedStepLimitChecksBillionsOfTilesInLittleMemory) {
  // 2e12 tiles: within a limit of 1e15 steps, so checked, and found not
  // to fit from the boxes alone, without a list per tile.
  TempFolder dir;
  copy_inputs(dir, "repeat_tiny_tile.grm");
  const auto m = test::run_program_measured(
      "check", {"repeat_tiny_tile.grm", "two_parts.obj", "--max-steps", "1000000000000000"}, dir.path());
  EXPECT_EQ(m.result.exit_code, 1) << m.result.err;
  EXPECT_NE(m.result.out.find("boxes cross the tile boundaries of 2e+12 tiles"), std::string::npos) << m.result.out;
  EXPECT_LT(m.peak_kib, 100 * 1024) << "peak memory in KiB";
}

}  // namespace
}  // namespace vern
