// Temporary files that a stopped run leaves behind: none.
//
// Outputs are written to temporary files beside them (atomic_file.hpp),
// named after the output and this process: ".style.grm.vern-4242-a8Xk2Q".
// The folders they are written in are watched: a signal that ends the run
// removes this process's temporaries from each of them before the run
// ends, however many there are.
#pragma once

#include <filesystem>
#include <string>

namespace vern {

// The mkstemp template of a temporary file for `destination`, in its folder:
// "<folder>/.<name>.vern-<pid>-XXXXXX".
std::string temporary_template(const std::filesystem::path& destination);

// Watches `folder` from now on: a signal that ends the run removes this
// process's temporary files there. Up to 64 folders a process; more are
// not watched.
void watch_folder(const std::filesystem::path& folder);

// Installs the handlers of the signals that end a run (SIGINT, SIGTERM):
// they remove the temporaries in the watched folders, then end the process
// with the signal's own status. Call once from main().
void install_interrupt_cleanup();

}  // namespace vern
