#include "graph/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <string>

#include "graph/error.hpp"

namespace vern {

namespace {

// The temporary file being written right now, for the signal handler. Only
// async-signal-safe calls touch it there (unlink, _exit).
constexpr std::size_t kMaxPending = 16;
std::atomic<const char*> g_pending[kMaxPending];

void on_signal(int sig) {
  for (auto& p : g_pending) {
    if (const char* path = p.load()) unlink(path);
  }
  signal(sig, SIG_DFL);
  raise(sig);
}

struct PendingGuard {
  std::size_t slot = kMaxPending;
  explicit PendingGuard(const char* path) {
    for (std::size_t i = 0; i < kMaxPending; ++i) {
      const char* expected = nullptr;
      if (g_pending[i].compare_exchange_strong(expected, path)) {
        slot = i;
        break;
      }
    }
  }
  ~PendingGuard() {
    if (slot < kMaxPending) g_pending[slot].store(nullptr);
  }
};

[[noreturn]] void io_error(const std::filesystem::path& path, const std::string& what, int err) {
  fail(ErrorKind::Io, path.string(), {}, what + ": " + std::strerror(err),
       "check that the folder exists and is writable");
}

}  // namespace

void install_interrupt_cleanup() {
  signal(SIGINT, on_signal);
  signal(SIGTERM, on_signal);
}

void write_file_atomically(const std::filesystem::path& path, std::string_view content) {
  write_file_atomically(path, std::span<const std::string_view>(&content, 1));
}

void write_file_atomically(const std::filesystem::path& path, std::span<const std::string_view> pieces) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    fail(ErrorKind::Io, path.string(), {}, "is a folder, not a file", "name a file to write");
  }
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::string temp = (folder / ("." + path.filename().string() + ".tmpXXXXXX")).string();
  const int fd = mkstemp(temp.data());
  if (fd < 0) io_error(path, "cannot create a temporary file in " + folder.string(), errno);
  PendingGuard guard(temp.c_str());
  for (const std::string_view content : pieces) {
    std::size_t written = 0;
    while (written < content.size()) {
      const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
      if (n < 0) {
        if (errno == EINTR) continue;
        const int err = errno;
        ::close(fd);
        ::unlink(temp.c_str());
        io_error(path, "cannot write", err);
      }
      written += static_cast<std::size_t>(n);
    }
  }
  // mkstemp creates 0600; outputs are ordinary files.
  fchmod(fd, 0644);
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(temp.c_str());
    io_error(path, "cannot write", err);
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(temp.c_str());
    io_error(path, "cannot replace", err);
  }
}

}  // namespace vern
