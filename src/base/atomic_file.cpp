#include "base/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "base/error.hpp"
#include "base/files_read.hpp"
#include "base/interrupt_cleanup.hpp"
#include "base/write_all.hpp"

namespace vern {

namespace fs = std::filesystem;

namespace {

// The umask, read once before any thread could create files while it is
// changed (umask() can only be read by setting it).
const mode_t g_umask = [] {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return mask;
}();

// The mode an output gets: that of the file it replaces, else what any
// new file gets under the umask. (mkstemp creates 0600.)
mode_t output_mode(const fs::path& destination) {
  struct stat st {};
  if (::stat(destination.c_str(), &st) == 0 && S_ISREG(st.st_mode)) return st.st_mode & 07777;
  return 0666 & ~g_umask;
}

// A run of a few files (infer's three, one scene and its materials) puts
// each on disk alone as it is closed (fsync): it waits for its own bytes
// only. Past these, the commit puts the whole file system on disk at once
// (syncfs), as costly as one fsync where each costs a journal commit:
// generate's 2000 variants (4000 files) took a median 4.26 s so, 19.8 s
// with an fsync each, 3.91 s before anything was synced.
constexpr std::size_t kSyncedOneByOne = 16;

[[noreturn]] void io_error(const fs::path& path, const std::string& what, int err) {
  fail(ErrorKind::Io, path.string(), {}, what + ": " + std::strerror(err), "check that the folder exists and is writable");
}

// A destination's earlier file, kept under another name while the run's
// files are renamed, so that a failed rename can put it back.
struct Replaced {
  const fs::path* destination;
  std::string backup;  // empty: the destination was new
};

// Keeps the destination's current file as `backup`: a second name for it
// (nobody sees the destination missing), or, where the file system has
// no hard links, the file moved aside. False when there is nothing to keep.
bool keep_earlier(const fs::path& destination, const std::string& backup) {
  if (::link(destination.c_str(), backup.c_str()) == 0) return true;
  if (errno == ENOENT) return false;
  // A folder is never moved aside: the rename over it fails, as it must.
  struct stat st {};
  if (::lstat(destination.c_str(), &st) != 0 || S_ISDIR(st.st_mode)) return false;
  return std::rename(destination.c_str(), backup.c_str()) == 0;
}

void put_back(const std::vector<Replaced>& replaced) {
  for (auto it = replaced.rbegin(); it != replaced.rend(); ++it) {
    if (it->backup.empty())
      ::unlink(it->destination->c_str());
    else
      std::rename(it->backup.c_str(), it->destination->c_str());
  }
}

}  // namespace

OutputFiles::~OutputFiles() {
  for (const Staged& s : staged_) ::unlink(s.temporary.c_str());
}

void OutputFiles::stage(const fs::path& path, std::string_view content) {
  stage(path, std::span<const std::string_view>(&content, 1));
}

void OutputFiles::stage(const fs::path& path, std::span<const std::string_view> pieces) {
  OutputFile file = open(path);
  for (const std::string_view content : pieces) file.write(content);
  file.close();
}

FolderClaim& OutputFiles::claim(const fs::path& folder, const fs::path& output) {
  // A folder of a million variants asks a million times: the last one first.
  for (auto it = claims_.rbegin(); it != claims_.rend(); ++it)
    if ((*it)->folder() == folder) return **it;
  claims_.push_back(std::make_unique<FolderClaim>(folder, output));
  return *claims_.back();
}

OutputFile OutputFiles::open(const fs::path& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) fail(ErrorKind::Io, path.string(), {}, "is a folder, not a file", "name a file to write");
    refuse_file_read(path, st);
  }
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  claim(folder, path).sweep(path.filename().string());
  std::string temp = temporary_template(path);
  const int fd = [&] {
    const SignalsWait made_whole;
    return ::mkstemp(temp.data());
  }();
  if (fd < 0) io_error(path, "cannot create a temporary file in " + folder.string(), errno);
  staged_.push_back({path, temp});  // removed by the destructor unless committed
  return OutputFile(path, fd, durability_ == Durability::Synced && staged_.size() <= kSyncedOneByOne);
}

OutputFile::~OutputFile() {
  if (fd_ >= 0) ::close(fd_);
}

void OutputFile::write(std::string_view content) {
  if (const int err = write_all(fd_, content)) io_error(destination_, "cannot write", err);
}

void OutputFile::close() {
  if (fd_ < 0) return;
  ::fchmod(fd_, output_mode(destination_));
  const int fd = std::exchange(fd_, -1);
  // On disk before it is renamed over anything: after a power cut the
  // destination holds this file whole, or the earlier one.
  const int unsynced = !sync_ || ::fsync(fd) == 0 ? 0 : errno;
  if (::close(fd) != 0) io_error(destination_, "cannot write", errno);
  if (unsynced) io_error(destination_, "cannot write", unsynced);
}

void OutputFiles::commit() {
  // Checked again: a file read since it was staged is an input too.
  for (const Staged& s : staged_) refuse_file_read(s.destination);
  const bool synced = durability_ == Durability::Synced;
  if (synced && staged_.size() > kSyncedOneByOne)
    for (const std::unique_ptr<FolderClaim>& folder : claims_)
      if (const int err = folder->sync_file_system()) io_error(folder->folder(), "cannot write", err);
  const SignalsWait renamed_whole;
  std::vector<Replaced> replaced;
  replaced.reserve(staged_.size());
  for (const Staged& s : staged_) {
    std::string backup = s.temporary + ".old";
    if (!keep_earlier(s.destination, backup)) backup.clear();
    replaced.push_back({&s.destination, backup});
    if (std::rename(s.temporary.c_str(), s.destination.c_str()) != 0) {
      const int err = errno;
      // The file at hand is as it was, or moved aside: back it goes.
      std::error_code ec;
      if (!backup.empty() && !fs::exists(s.destination, ec)) std::rename(backup.c_str(), s.destination.c_str());
      else if (!backup.empty()) ::unlink(backup.c_str());
      replaced.pop_back();
      put_back(replaced);
      io_error(s.destination, "cannot replace", err);
    }
  }
  // The renames on disk: once per folder, not once per file.
  for (const std::unique_ptr<FolderClaim>& folder : claims_) {
    if (const int err = synced ? folder->sync_folder() : 0) {
      put_back(replaced);
      io_error(folder->folder(), "cannot write the folder", err);
    }
  }
  for (const Replaced& r : replaced)
    if (!r.backup.empty()) ::unlink(r.backup.c_str());
  staged_.clear();
  claims_.clear();
}

void write_file_atomically(const fs::path& path, std::string_view content) {
  write_file_atomically(path, std::span<const std::string_view>(&content, 1));
}

void write_file_atomically(const fs::path& path, std::span<const std::string_view> pieces) {
  OutputFiles files;
  files.stage(path, pieces);
  files.commit();
}

}  // namespace vern
