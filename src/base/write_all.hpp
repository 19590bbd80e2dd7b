// Writing bytes to a file descriptor whole: write(2) may write fewer than
// asked, or be interrupted by a signal, and both mean "go on".
#pragma once

#include <unistd.h>

#include <cerrno>
#include <string_view>

namespace vern {

// 0 when every byte was written, else the errno of the failure.
inline int write_all(int fd, std::string_view bytes) {
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    written += static_cast<std::size_t>(n);
  }
  return 0;
}

}  // namespace vern
