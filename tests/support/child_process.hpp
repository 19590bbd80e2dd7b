// A command-line program run as a child process that the test controls:
// limits, umask and ignored signals set before it starts, signals sent to
// it while it runs, and how it ended (its exit code, or the signal).
#pragma once

#include <sys/types.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "support/run_command.hpp"

namespace vern::test {

// Limits a program is run under, to make it fail where it would not:
// address_space_mib caps its memory (RLIMIT_AS: it runs out), file_bytes
// the files it writes (RLIMIT_FSIZE with SIGXFSZ ignored: a write past it
// fails with EFBIG, as on a full disk), stack_kib its stack (`ulimit -s`).
// 0: no limit.
struct ChildLimits {
  std::size_t address_space_mib = 0;
  std::size_t file_bytes = 0;
  std::size_t stack_kib = 0;
};

struct ChildSetup {
  ChildLimits limits;
  int umask = -1;                   // the umask it starts with (-1: the test's own)
  std::vector<int> ignored_signals;  // SIG_IGN when it starts, as `nohup` leaves SIGHUP
  // Started through vern_peak (tests/tools/peak_meter.cpp), so that
  // Ended::peak_kib is the program's own and not the test process's: the
  // process the test sends signals to is then vern_peak, not the program.
  bool measure_peak = false;
};

class ChildProcess {
 public:
  // Starts VERN_BIN_DIR/program with the arguments in `folder`, stdin from
  // /dev/null, stdout and stderr captured, stopped after kHangSeconds.
  ChildProcess(const std::string& program, const std::vector<std::string>& args, const std::filesystem::path& folder,
               const ChildSetup& setup = {});
  // A child still running is killed and waited for.
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  pid_t pid() const { return pid_; }

  struct Ended {
    CommandResult result;  // exit_code -1 when a signal ended it
    int signal = 0;        // the signal that ended it, or 0
    long peak_kib = 0;     // peak resident memory (ChildSetup::measure_peak), else 0
  };
  // Waits for the child to end.
  Ended wait();

  // What it has written to stderr so far (a server's address, say).
  std::string err_so_far() const;

 private:
  TempFolder capture_;
  pid_t pid_ = -1;
  bool measured_ = false;
};

}  // namespace vern::test
