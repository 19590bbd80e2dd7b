#include "base/spill_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <vector>

#include "base/error.hpp"
#include "base/write_all.hpp"

namespace vern {

namespace {

[[noreturn]] void io_error(const std::string& owner, const std::string& what, int err) {
  fail(ErrorKind::Io, owner, {}, what + ": " + std::strerror(err),
       "check that the output's folder is writable and its disk has room");
}

// A file without a name in `folder`: O_TMPFILE where the file system has
// it, else a named one unlinked at once.
int nameless_file(const std::filesystem::path& folder, const std::string& owner) {
#ifdef O_TMPFILE
  const int fd = ::open(folder.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (fd >= 0) return fd;
#endif
  std::string name = (folder / ".vern-spill-XXXXXX").string();
  const int named = ::mkstemp(name.data());
  if (named < 0) io_error(owner, "cannot create a temporary file in " + folder.string(), errno);
  ::unlink(name.c_str());
  return named;
}

}  // namespace

SpillFile::SpillFile(std::optional<std::filesystem::path> folder, std::string owner, std::size_t threshold)
    : folder_(std::move(folder)), owner_(std::move(owner)), threshold_(threshold) {
  if (folder_ && folder_->empty()) folder_ = ".";
}

SpillFile::~SpillFile() {
  if (fd_ >= 0) ::close(fd_);
}

void SpillFile::append(std::string_view bytes) {
  if (folder_ && memory_.size() + bytes.size() >= threshold_) {
    // Large pieces go straight to disk, not through memory_.
    write_to_disk(memory_);
    memory_.clear();  // keeps its capacity: the next bytes go where these were
    if (bytes.size() >= threshold_) return write_to_disk(bytes);
  }
  memory_.append(bytes);
}

void SpillFile::write_to_disk(std::string_view bytes) {
  if (bytes.empty()) return;
  if (fd_ < 0) fd_ = nameless_file(*folder_, owner_);
  if (const int err = write_all(fd_, bytes)) io_error(owner_, "cannot write a temporary file", err);
  on_disk_ += bytes.size();
}

void SpillFile::read(const std::function<void(std::string_view)>& take) const {
  if (on_disk_ > 0) {
    std::vector<char> piece(std::max<std::size_t>(threshold_, 1 << 16));
    std::uint64_t at = 0;
    while (at < on_disk_) {
      const ssize_t n = ::pread(fd_, piece.data(), piece.size(), static_cast<off_t>(at));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) io_error(owner_, "cannot read back a temporary file", n < 0 ? errno : EIO);
      take(std::string_view(piece.data(), static_cast<std::size_t>(n)));
      at += static_cast<std::uint64_t>(n);
    }
  }
  if (!memory_.empty()) take(memory_);
}

}  // namespace vern
