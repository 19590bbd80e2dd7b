// Outputs survive a power cut whole or not at all: each file is on disk
// before it is renamed over its destination, and the renames once they
// are all done (atomic_file.hpp). A test cannot pull the power; it watches
// the system calls a run makes instead, under strace (scripts/setup
// installs it), and checks their order.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_command.hpp"

namespace vern {
namespace {

namespace fs = std::filesystem;
using test::TempFolder;

const std::string kGarage = VERN_SOURCE_DIR "/data/grammars/garage.grm";

// One system call: its name and its arguments as strace -y writes them
// (a descriptor with its path: "5</tmp/x/.house.obj.vern-1-Ab12Cd-Xy34Zw>").
struct Call {
  std::string name, args;
};

// Whether strace is there (a failure when not: scripts/setup installs it)
// and may trace (not where ptrace is forbidden).
bool strace_can_trace() {
  if (std::system("command -v strace >/dev/null") != 0) {
    ADD_FAILURE() << "strace is not installed: run scripts/setup";
    return false;
  }
  return std::system("strace -qq -o /dev/null true 2>/dev/null") == 0;
}

// Runs generate with `args` in `folder` under strace, tracing the calls
// that put files on disk and rename them.
std::vector<Call> traced_generate(const fs::path& folder, const std::vector<std::string>& args) {
  const fs::path log = folder / "strace.log";
  // LeakSanitizer cannot run under ptrace (a sanitizer build's generate
  // would fail at exit): leaks are not what is traced here.
  std::string cmd = "cd '" + folder.string() + "' && ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0\" strace -f -qq -y -o '" + log.string() +
                    "' -e trace=fsync,fdatasync,syncfs,rename,renameat,renameat2 '" VERN_BIN_DIR "/generate'";
  for (const std::string& a : args) cmd += " '" + a + "'";
  cmd += " >/dev/null 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::vector<Call> calls;
  static const std::regex line(R"(^(?:\d+\s+)?(\w+)\((.*)\)\s+=\s+0$)");
  std::istringstream in(test::read_file(log));
  for (std::string text; std::getline(in, text);) {
    std::smatch m;
    if (std::regex_match(text, m, line)) calls.push_back({m[1], m[2]});
  }
  fs::remove(log);
  return calls;
}

// The first call named `name` whose arguments match `args`, or -1.
long find(const std::vector<Call>& calls, const std::string& name, const std::regex& args) {
  for (std::size_t i = 0; i < calls.size(); ++i)
    if (calls[i].name == name && std::regex_search(calls[i].args, args)) return static_cast<long>(i);
  return -1;
}

long last_rename(const std::vector<Call>& calls) {
  long last = -1;
  for (std::size_t i = 0; i < calls.size(); ++i)
    if (calls[i].name.starts_with("rename")) last = static_cast<long>(i);
  return last;
}

// The folder as strace names a descriptor of it: "3</tmp/x>".
std::regex descriptor_of(const fs::path& folder) {
  return std::regex("^\\d+<" + std::regex_replace(fs::canonical(folder).string(), std::regex(R"([.^$|()\[\]{}*+?\\])"),
                                                   R"(\$&)") + ">$");
}

// One file and its materials: each synced, then renamed, then the folder synced.
TEST(DurableOutputs, EachFileIsSyncedBeforeItsRenameAndTheFolderAfter) {
  if (!strace_can_trace()) GTEST_SKIP() << "strace cannot trace here (ptrace not permitted)";
  TempFolder dir;
  const std::vector<Call> calls = traced_generate(dir.path(), {kGarage, "-q", "-o", "house.obj"});
  const long folder_synced = find(calls, "fsync", descriptor_of(dir.path()));
  ASSERT_GE(folder_synced, 0) << "the folder is never synced";
  for (const std::string name : {"house.obj", "house.mtl"}) {
    const std::string escaped = std::regex_replace(name, std::regex(R"(\.)"), R"(\.)");
    const long synced = find(calls, "fsync", std::regex("/\\." + escaped + "\\.vern-[^/]*>$"));
    const long renamed = find(calls, "rename", std::regex("\"(.*/)?" + escaped + "\"$"));
    ASSERT_GE(synced, 0) << name << " is never synced";
    ASSERT_GE(renamed, 0) << name << " is never renamed";
    EXPECT_LT(synced, renamed) << name;
    EXPECT_LT(renamed, folder_synced) << name;
  }
  EXPECT_LT(last_rename(calls), folder_synced);
}

// A folder of many variants: the file system synced once before the
// renames (not a file at a time), the folder once after them.
TEST(DurableOutputs, AFolderOfVariantsIsSyncedOnceBeforeAndOnceAfter) {
  if (!strace_can_trace()) GTEST_SKIP() << "strace cannot trace here (ptrace not permitted)";
  TempFolder dir;
  const std::vector<Call> calls = traced_generate(dir.path(), {kGarage, "-n", "20", "-q", "-o", "out/"});
  const std::regex out = descriptor_of(dir / "out");
  const long synced = find(calls, "syncfs", out);
  const long folder_synced = find(calls, "fsync", out);
  const long first_rename = find(calls, "rename", std::regex("variant_"));
  ASSERT_GE(synced, 0) << "the file system is never synced";
  ASSERT_GE(folder_synced, 0) << "the folder is never synced";
  ASSERT_GE(first_rename, 0);
  EXPECT_LT(synced, first_rename);
  EXPECT_LT(last_rename(calls), folder_synced);
  long renames = 0;
  for (const Call& c : calls) renames += c.name.starts_with("rename");
  EXPECT_EQ(renames, 40);
}

}  // namespace
}  // namespace vern
