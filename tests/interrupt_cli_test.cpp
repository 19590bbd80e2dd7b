// Runs that end early leave no temporary files: every signal that ends a
// run removes them, one that cannot be caught (SIGKILL) leaves them to the
// next run that writes the same outputs in that folder (never those of a
// run still holding its lock file, wherever it runs), and a signal the run
// was started ignoring stays ignored. Outputs take the umask, or the mode
// of the file they replace.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>
#include <regex>
#include <string>
#include <thread>

#include "support/child_process.hpp"
#include "support/run_command.hpp"

namespace vern {
namespace {

namespace fs = std::filesystem;
using test::ChildProcess;
using test::ChildSetup;
using test::TempFolder;

const std::string kCity = VERN_SOURCE_DIR "/data/grammars/skyscraper_city.grm";
const std::string kGarage = VERN_SOURCE_DIR "/data/grammars/garage.grm";

// The temporary files in a folder: ".NAME.vern-PID-RUN-XXXXXX" (atomic_file.hpp),
// and the runs' lock files ".vern-PID-RUN-XXXXXX.lock" (folder_claim.hpp).
std::vector<std::string> temporaries(const fs::path& folder) {
  static const std::regex temporary(R"(\.(.*\.)?vern-[0-9]+-.*)");
  std::vector<std::string> found;
  for (const auto& e : fs::directory_iterator(folder)) {
    const std::string name = e.path().filename().string();
    if (std::regex_match(name, temporary)) found.push_back(name);
  }
  std::sort(found.begin(), found.end());
  return found;
}

// Two hundred cities into out/: seconds of writing, every file staged
// until the end. Returns once the first temporary file is there.
void start_writing_cities(std::optional<ChildProcess>& child, const fs::path& dir, const ChildSetup& setup = {}) {
  fs::create_directory(dir / "out");
  child.emplace("generate", std::vector<std::string>{kCity, "-n", "200", "-j", "1", "-q", "-o", "out/"}, dir, setup);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (temporaries(dir / "out").empty()) {
    ASSERT_LT(std::chrono::steady_clock::now(), deadline) << "no temporary file appeared";
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

class EndingSignal : public ::testing::TestWithParam<int> {};

TEST_P(EndingSignal, RemovesTheTemporaryFiles) {
  const int sig = GetParam();
  TempFolder dir;
  std::optional<ChildProcess> child;
  start_writing_cities(child, dir.path());
  ASSERT_EQ(kill(child->pid(), sig), 0);
  const ChildProcess::Ended ended = child->wait();
  // Ended by the signal itself, as if it had not been caught.
  EXPECT_EQ(ended.signal, sig) << ended.result.err;
  EXPECT_EQ(temporaries(dir / "out"), std::vector<std::string>{});
}

INSTANTIATE_TEST_SUITE_P(Interrupt, EndingSignal,
                         ::testing::Values(SIGHUP, SIGINT, SIGQUIT, SIGTERM, SIGPIPE, SIGALRM, SIGUSR1, SIGUSR2),
                         [](const ::testing::TestParamInfo<int>& p) { return std::string(sigabbrev_np(p.param)); });

class IgnoredSignal : public ::testing::TestWithParam<int> {};

// `nohup` starts a program with SIGHUP ignored, a shell's background job
// with SIGINT ignored: the run goes on.
TEST_P(IgnoredSignal, StaysIgnored) {
  const int sig = GetParam();
  TempFolder dir;
  std::optional<ChildProcess> child;
  ChildSetup setup;
  setup.ignored_signals = {sig};
  start_writing_cities(child, dir.path(), setup);
  ASSERT_EQ(kill(child->pid(), sig), 0);
  const ChildProcess::Ended ended = child->wait();
  EXPECT_EQ(ended.signal, 0);
  EXPECT_EQ(ended.result.exit_code, 0) << ended.result.err;
  EXPECT_TRUE(fs::is_regular_file(dir / "out/variant_199.obj"));
  EXPECT_EQ(temporaries(dir / "out"), std::vector<std::string>{});
}

INSTANTIATE_TEST_SUITE_P(Interrupt, IgnoredSignal, ::testing::Values(SIGHUP, SIGINT),
                         [](const ::testing::TestParamInfo<int>& p) { return std::string(sigabbrev_np(p.param)); });

// An open file description lock on `path`, as a running run holds its
// lock file: held until destroyed, wherever the run is (here, the test).
class HeldLock {
 public:
  explicit HeldLock(const fs::path& path) : fd_(open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0600)) {
    struct flock lock {};
    lock.l_type = F_WRLCK;
    lock.l_whence = SEEK_SET;
    EXPECT_EQ(fcntl(fd_, F_OFD_SETLK, &lock), 0) << path;
  }
  ~HeldLock() { close(fd_); }
  HeldLock(const HeldLock&) = delete;
  HeldLock& operator=(const HeldLock&) = delete;

 private:
  int fd_;
};

// SIGKILL cannot be caught: the next run that writes the same outputs in
// the folder removes what the killed one left. It keeps the files of a
// run that still holds its lock file, though its process id is of no
// process here (a run in another PID namespace, a container sharing the
// folder), the files of names it does not write, and files it cannot tell
// are over (the older names, without a lock file).
TEST(Interrupt, TheNextRunSweepsAKilledRunsTemporaries) {
  TempFolder dir;
  std::optional<ChildProcess> child;
  start_writing_cities(child, dir.path());
  const std::string dead = std::to_string(child->pid());
  ASSERT_EQ(kill(child->pid(), SIGKILL), 0);
  EXPECT_EQ(child->wait().signal, SIGKILL);
  ASSERT_FALSE(temporaries(dir / "out").empty());
  // Another run's, under the process id of no process here, that holds its lock file.
  const std::string elsewhere = ".vern-" + dead + "-Elsewh-a1b2c3.lock";
  std::optional<HeldLock> held(std::in_place, dir / "out" / elsewhere);
  const std::vector<std::string> live = {elsewhere, ".variant_000.obj.vern-" + dead + "-Elsewh-d4e5f6",
                                         ".variant_001.obj.vern-" + dead + "-Elsewh-g7h8i9.old"};
  for (const std::string& name : {live[1], live[2]}) test::write_text(dir / "out" / name, "still being written\n");
  // A dead run's file of a name the next run does not write, one of the
  // older names, and a look-alike without a process id.
  const std::vector<std::string> kept = {".notes.txt.vern-" + dead + "-Killed-a1b2c3",
                                         ".variant_002.obj.vern-" + dead + "-a1b2c3"};
  for (const std::string& name : kept) test::write_text(dir / "out" / name, "not the next run's\n");
  test::write_text(dir / "out/.notes.vern-draft", "a user's file\n");

  const test::CommandResult r = test::run_program("generate", {kGarage, "-n", "200", "-q", "-o", "out/"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::string> expected = live;
  expected.insert(expected.end(), kept.begin(), kept.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(temporaries(dir / "out"), expected);
  EXPECT_TRUE(fs::exists(dir / "out/.notes.vern-draft"));

  // Its lock given up, the other run is over: its files go, its lock file with them.
  held.reset();
  const test::CommandResult again = test::run_program("generate", {kGarage, "-n", "2", "-q", "-o", "out/"}, dir.path());
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(temporaries(dir / "out"), kept);
}

mode_t mode_of(const fs::path& path) {
  struct stat st {};
  stat(path.c_str(), &st);
  return st.st_mode & 07777;
}

TEST(Interrupt, OutputsTakeTheUmaskOrTheModeOfTheFileTheyReplace) {
  TempFolder dir;
  test::write_text(dir / "house.obj", "an earlier house\n");
  ASSERT_EQ(chmod((dir / "house.obj").c_str(), 0640), 0);
  ChildSetup setup;
  setup.umask = 077;
  ChildProcess child("generate", {kGarage, "-q", "-o", "house.obj"}, dir.path(), setup);
  const ChildProcess::Ended ended = child.wait();
  ASSERT_EQ(ended.result.exit_code, 0) << ended.result.err;
  EXPECT_EQ(mode_of(dir / "house.obj"), 0640u);
  EXPECT_EQ(mode_of(dir / "house.mtl"), 0600u);
}

}  // namespace
}  // namespace vern
