#include "folder_opens.hpp"

#include <sys/inotify.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace vern::fuzz {

FolderOpens::FolderOpens() : fd_(::inotify_init1(IN_NONBLOCK | IN_CLOEXEC)) {
  if (fd_ < 0) throw std::runtime_error(std::string("fuzz harness: no inotify instance: ") + std::strerror(errno));
}

FolderOpens::~FolderOpens() { ::close(fd_); }

void FolderOpens::watch(const std::vector<std::filesystem::path>& folders) {
  // Watches of removed folders went with them (IN_IGNORED); the others
  // are replaced.
  for (const auto& [wd, folder] : watches_) ::inotify_rm_watch(fd_, wd);
  watches_.clear();
  for (const std::filesystem::path& folder : folders) {
    const int wd = ::inotify_add_watch(fd_, folder.c_str(), IN_OPEN | IN_DONT_FOLLOW | IN_ONLYDIR);
    if (wd < 0)
      throw std::runtime_error("fuzz harness: cannot watch " + folder.string() + ": " + std::strerror(errno));
    watches_.emplace_back(wd, folder);
  }
  drain(nullptr);
}

std::vector<std::string> FolderOpens::opened() {
  std::vector<std::string> out;
  drain(&out);
  return out;
}

void FolderOpens::drain(std::vector<std::string>* into) {
  alignas(inotify_event) char buffer[16384];
  for (;;) {
    const ssize_t n = ::read(fd_, buffer, sizeof buffer);
    if (n <= 0) return;  // EAGAIN: nothing more
    for (ssize_t at = 0; at < n;) {
      const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
      at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
      if (into == nullptr || !(event->mask & IN_OPEN)) continue;
      const auto it = std::find_if(watches_.begin(), watches_.end(),
                                   [&](const auto& w) { return w.first == event->wd; });
      if (it == watches_.end()) continue;
      into->push_back(event->len > 0 ? (it->second / event->name).string() : it->second.string());
    }
  }
}

}  // namespace vern::fuzz
