// Files the toolkit reads are regular files.
//
// Every file read is named by the user or by a file they were given: a
// grammar, an example, a primitives file, a buffer a glTF names. A FIFO
// would make the run wait for a writer that may never come, and a device
// may never end (/dev/zero is read whole as a grammar until memory runs
// out). Such paths are refused before they are opened, saying what they are.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "base/error.hpp"

namespace vern {

// Throws vern::Error (Io) naming `path` when it exists and is not a
// regular file once links are followed ("is a FIFO (named pipe), not a
// regular file"). A missing path passes: opening it says so. A regular
// file is noted as read (files_read.hpp): the caller reads it next.
void require_regular_file(const std::filesystem::path& path);

// Why a file was not read: its error kind and what to say after the name.
struct ReadRefusal {
  ErrorKind kind;
  std::string problem;  // "is a FIFO (named pipe), not a regular file", "is larger than 256 MiB"
};

// Reads the regular file at `path` whole into `out`, or says why not: Io
// when it is missing, unreadable or not a regular file (checked on the
// opened file too, which is opened without waiting on a FIFO); Limit when
// it holds more than max_bytes, which is then not read. The problem never
// says how large the file is. The file opened is noted as read
// (files_read.hpp).
std::optional<ReadRefusal> read_regular_file(const std::filesystem::path& path, std::uint64_t max_bytes,
                                             std::vector<unsigned char>& out);

// The regular files directly in `folder` (links followed) whose path
// `wanted` accepts, sorted by name (the listing order is the file
// system's). Throws vern::Error (Io) naming the folder when it cannot be
// listed, or an entry `wanted` accepts that cannot be looked at (a link
// that leads to itself), saying `what` it should be ("an .obj file").
std::vector<std::filesystem::path> regular_files_in(const std::filesystem::path& folder,
                                                    const std::function<bool(const std::filesystem::path&)>& wanted,
                                                    const std::string& what);

// "256 MiB": how messages and hints state a byte limit.
std::string mebibytes(std::uint64_t bytes);

}  // namespace vern
