// Output files that are either complete or absent: one file, or all the
// files of one run together.
//
// Everything the toolkit writes goes through here: the bytes go to a
// temporary file in the destination's folder (interrupt_cleanup.hpp names
// and watches it; folder_claim.hpp claims the folder while it is there),
// and every file of a run is written before any is renamed over its
// destination. A failure while writing (a full disk, a signal) leaves
// whatever was there before untouched; a rename that fails at the end
// puts back what the renames before it replaced. Each file is on disk
// (fsync) before it is renamed, and each folder's renames once they are
// all done, so that a power cut leaves the run's files whole or the
// earlier ones. A destination that is a file the run has read is refused
// (files_read.hpp).
#pragma once

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "base/folder_claim.hpp"

namespace vern {

class OutputFiles;

// One staged output being written piece by piece (OutputFiles::open): a
// writer that produces more than it wants to hold streams into it.
class OutputFile {
 public:
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  OutputFile(OutputFile&& other) noexcept
      : destination_(std::move(other.destination_)), fd_(std::exchange(other.fd_, -1)), sync_(other.sync_) {}
  OutputFile& operator=(OutputFile&&) = delete;
  ~OutputFile();

  // Appends bytes. Throws vern::Error (Io) naming the destination.
  void write(std::string_view bytes);
  // Gives the file its mode, puts it on disk (fsync, unless the commit
  // does: OutputFiles::commit) and closes it; the destructor closes it
  // too. Throws vern::Error (Io) naming the destination when its bytes
  // cannot be kept.
  void close();

 private:
  friend class OutputFiles;
  OutputFile(std::filesystem::path destination, int fd, bool sync)
      : destination_(std::move(destination)), fd_(fd), sync_(sync) {}
  std::filesystem::path destination_;
  int fd_ = -1;
  bool sync_ = true;
};

// The outputs of one run, staged until commit().
class OutputFiles {
 public:
  // Whether the files are put on disk: a run's outputs are, to survive a
  // power cut whole; a scratch file, read back at once and removed, need
  // not be (an fsync costs milliseconds: evaluate writes thousands).
  enum class Durability { Synced, Scratch };
  explicit OutputFiles(Durability durability = Durability::Synced) : durability_(durability) {}
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;
  // Removes the temporary files of a run that was not committed.
  ~OutputFiles();

  // Writes the pieces, one after another (a large file need not be joined
  // in memory first), to a temporary file beside `path`. Throws
  // vern::Error (Io) naming path when it is a folder, or its folder is
  // missing or not writable, or the disk is full; (Usage) when it is a
  // file this run has read (files_read.hpp). First removes what runs that
  // are over left for `path` (folder_claim.hpp).
  void stage(const std::filesystem::path& path, std::span<const std::string_view> pieces);
  void stage(const std::filesystem::path& path, std::string_view content);

  // The same, the bytes given later through the returned file (closed
  // before commit()). Throws as stage.
  OutputFile open(const std::filesystem::path& path);

  // Puts the staged files on disk where close() did not, renames every
  // staged file over its destination, in the order staged, then puts
  // each folder's renames on disk. Signals wait until it is
  // done. When a rename (or a folder's sync) fails, the destinations
  // replaced before it get their earlier files back (those that were new
  // are removed) and vern::Error (Io) names the one that failed. Throws
  // vern::Error (Usage) before renaming anything when a destination is a
  // file this run has read.
  void commit();

 private:
  struct Staged {
    std::filesystem::path destination;
    std::string temporary;
  };
  FolderClaim& claim(const std::filesystem::path& folder, const std::filesystem::path& output);
  Durability durability_;
  std::vector<std::unique_ptr<FolderClaim>> claims_;  // given up after the temporaries are gone
  std::vector<Staged> staged_;
};

// One file alone: staged and committed. Throws vern::Error (Io) as stage.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);
void write_file_atomically(const std::filesystem::path& path, std::span<const std::string_view> pieces);

}  // namespace vern
