// The files a run has read, never written over by it.
//
// A command checks its outputs against the inputs its command line names
// before any work (apps/support/output_paths.hpp), but a run reads files
// no command line names: the buffers a glTF names, the meshes of a
// primitives folder, a grammar's @primitives. Every file is read through
// input_file.hpp, which notes it here, and the output staging
// (atomic_file.hpp) refuses an output that is a file noted: the run fails
// before anything is renamed. Files are known by device and inode, so a
// path spelled another way, or a link, is the same file.
//
// Only a command records (guarded_main.hpp): a library user or a test
// that does not ask for it reads and writes as before.
#pragma once

#include <sys/stat.h>

#include <filesystem>

namespace vern {

// Notes the files read while it lives (one at a time), and forgets them.
class FilesReadRecorded {
 public:
  FilesReadRecorded();
  ~FilesReadRecorded();
  FilesReadRecorded(const FilesReadRecorded&) = delete;
  FilesReadRecorded& operator=(const FilesReadRecorded&) = delete;
};

// Notes that the regular file `st` describes was read as `path`, when
// recording; otherwise does nothing.
void note_file_read(const std::filesystem::path& path, const struct stat& st);

// Throws vern::Error (Usage) naming `output` and the path the file was
// read as when `output` (whose status is `st`, when it exists) is a file
// this run has read.
void refuse_file_read(const std::filesystem::path& output);
void refuse_file_read(const std::filesystem::path& output, const struct stat& st);

}  // namespace vern
