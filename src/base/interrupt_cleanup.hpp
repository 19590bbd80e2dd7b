// Temporary files that a stopped run leaves behind: none.
//
// Outputs are written to temporary files beside them (atomic_file.hpp),
// named after the output and this run: ".style.grm.vern-4242-Qx7b2k-a8Xk2Q",
// the process id and six letters drawn once per process (process ids
// repeat across PID namespaces: two containers sharing a folder may both
// run process 7). The folders they are written in are watched: every
// signal that ends a run and can be caught removes this run's files (its
// temporaries and its lock files, folder_claim.hpp) from each of them
// before the run ends, however many there are. What no handler can clean
// (SIGKILL, a crash, a power cut) a later run that writes the same output
// into the folder sweeps (folder_claim.hpp).
#pragma once

#include <signal.h>

#include <filesystem>
#include <string>

namespace vern {

// ".vern-<pid>-<run>-": what the names of this run's files hold.
const std::string& run_tag();

// The mkstemp template of a temporary file for `destination`, in its folder:
// "<folder>/.<name>.vern-<pid>-<run>-XXXXXX".
std::string temporary_template(const std::filesystem::path& destination);

// The mkostemps template of this run's lock file in `folder`:
// "<folder>/.vern-<pid>-<run>-XXXXXX.lock" (a suffix of 5).
std::string lock_file_template(const std::filesystem::path& folder);

// Watches `folder` from now on: a signal that ends the run removes this
// run's files there. Up to 64 folders a process; more are not watched.
void watch_folder(const std::filesystem::path& folder);

// A change to the run's files that a signal must not cut short: a
// temporary made (the handler must find it to remove it), the files of a
// run renamed into place (all of them, or none). While one lasts, signals
// wait in its thread, and a handler running on another thread (the
// command runs on a thread of its own, and derives on several) waits for
// it to end. One begun after a signal has come waits for the end of the
// process instead.
class SignalsWait {
 public:
  SignalsWait();
  ~SignalsWait();
  SignalsWait(const SignalsWait&) = delete;
  SignalsWait& operator=(const SignalsWait&) = delete;

 private:
  sigset_t saved_;
};

// Installs handlers for the signals that end a process and come from
// outside it (SIGHUP, SIGINT, SIGQUIT, SIGTERM, SIGPIPE, SIGALRM, SIGUSR1,
// SIGUSR2, SIGXCPU, SIGXFSZ, SIGVTALRM, SIGPROF, SIGABRT): each removes the
// temporaries in the watched folders, then ends the process with the
// signal's own status. A signal the process was started ignoring (nohup's
// SIGHUP, a background job's SIGINT) or already handles is left as it is.
// Faults (SIGSEGV, SIGBUS, SIGFPE, SIGILL) are left to the sanitizers and
// debuggers that handle them, and their temporaries to the next run's
// sweep. Call once from main().
void install_interrupt_cleanup();

}  // namespace vern
