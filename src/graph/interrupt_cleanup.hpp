// Temporary files that a stopped run leaves behind: none.
//
// Outputs are written to temporary files beside them (atomic_file.hpp),
// named after the output and this process: ".style.grm.vern-4242-a8Xk2Q".
// The folders they are written in are watched: every signal that ends a
// run and can be caught removes this process's temporaries from each of
// them before the run ends, however many there are. What no handler can
// clean (SIGKILL, a crash, a power cut) the next run that writes into the
// folder sweeps: temporaries whose process is gone.
#pragma once

#include <filesystem>
#include <string>

namespace vern {

// The mkstemp template of a temporary file for `destination`, in its folder:
// "<folder>/.<name>.vern-<pid>-XXXXXX".
std::string temporary_template(const std::filesystem::path& destination);

// Watches `folder` from now on: a signal that ends the run removes this
// process's temporary files there. The first time, also removes the
// temporaries there of processes that no longer run (a process id that
// runs again, perhaps another program, keeps them: only the dead are
// swept). Up to 64 folders a process; more are not watched.
void watch_folder(const std::filesystem::path& folder);

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
