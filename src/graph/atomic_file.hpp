// Output files that are either complete or absent.
//
// Everything the toolkit writes goes through here: the bytes go to a
// temporary file in the destination's folder, which is renamed over the
// destination only once it is complete. A failure (or Ctrl-C, see
// install_interrupt_cleanup) leaves whatever was there before untouched.
#pragma once

#include <filesystem>
#include <span>
#include <string_view>

namespace vern {

// Writes content to path atomically; throws vern::Error (Io) naming the path
// and the reason when the folder is missing or not writable.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

// The same for content in pieces, written one after another: a large file
// need not be joined in memory first.
void write_file_atomically(const std::filesystem::path& path, std::span<const std::string_view> pieces);

// Installs SIGINT/SIGTERM handlers that delete temporary files still being
// written, then exit with the signal's status. Call once from main().
void install_interrupt_cleanup();

}  // namespace vern
