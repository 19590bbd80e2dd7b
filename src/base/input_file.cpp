#include "base/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "base/files_read.hpp"

namespace vern {

namespace {

// What a path that is not a regular file is, for "is ..., not a regular file".
std::string kind_of(mode_t mode) {
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISDIR(mode)) return "a folder";
  return "a special file";
}

std::string not_regular(mode_t mode) { return "is " + kind_of(mode) + ", not a regular file"; }

// Closes the descriptor on every way out.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

void require_regular_file(const std::filesystem::path& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return;
  if (S_ISREG(st.st_mode)) {
    note_file_read(path, st);
    return;
  }
  fail(ErrorKind::Io, path.string(), {}, not_regular(st.st_mode),
       "name a regular file: pipes and devices are not read (save what they give to a file first)");
}

std::optional<ReadRefusal> read_regular_file(const std::filesystem::path& path, std::uint64_t max_bytes,
                                             std::vector<unsigned char>& out) {
  out.clear();
  // Refused before opening; then opened without blocking, so a path
  // swapped for a FIFO in between does not wait for a writer either.
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) return ReadRefusal{ErrorKind::Io, not_regular(st.st_mode)};
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) return ReadRefusal{ErrorKind::Io, std::string("cannot be opened: ") + std::strerror(errno)};
  if (::fstat(file.fd, &st) != 0) return ReadRefusal{ErrorKind::Io, std::string("cannot be read: ") + std::strerror(errno)};
  if (!S_ISREG(st.st_mode)) return ReadRefusal{ErrorKind::Io, not_regular(st.st_mode)};
  note_file_read(path, st);
  const auto size = static_cast<std::uint64_t>(st.st_size);
  if (size > max_bytes) return ReadRefusal{ErrorKind::Limit, "is larger than " + mebibytes(max_bytes)};
  out.resize(static_cast<std::size_t>(size));
  std::size_t done = 0;
  while (done < out.size()) {
    const ssize_t n = ::read(file.fd, out.data() + done, out.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return ReadRefusal{ErrorKind::Io, std::string("cannot be read: ") + std::strerror(errno)};
    if (n == 0) break;  // shorter than it was: what is there
    done += static_cast<std::size_t>(n);
  }
  out.resize(done);
  return std::nullopt;
}

std::vector<std::filesystem::path> regular_files_in(const std::filesystem::path& folder,
                                                    const std::function<bool(const std::filesystem::path&)>& wanted,
                                                    const std::string& what) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    if (!wanted(it->path())) continue;
    std::error_code entry_error;
    const bool regular = it->is_regular_file(entry_error);
    if (entry_error) {
      fail(ErrorKind::Io, it->path().string(), {}, "cannot read: " + entry_error.message(),
           "remove it from the folder, or make it " + what + " (a link that leads to itself cannot be read)");
    }
    if (regular) files.push_back(it->path());
  }
  if (ec) fail(ErrorKind::Io, folder.string(), {}, "cannot list the folder: " + ec.message(), "check its permissions");
  std::sort(files.begin(), files.end());
  return files;
}

std::string mebibytes(std::uint64_t bytes) {
  const std::uint64_t mib = bytes >> 20;
  return (mib << 20) == bytes ? std::to_string(mib) + " MiB" : std::to_string(bytes) + " bytes";
}

}  // namespace vern
