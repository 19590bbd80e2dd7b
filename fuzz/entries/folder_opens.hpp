// Which files and folders were opened in some folders, as the kernel saw it
// (Linux inotify): the proof that a run read nothing outside the folder it
// was confined to, however the path it opened was spelled (`..`, an
// absolute path, a link, a percent-encoded URI).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace vern::fuzz {

class FolderOpens {
 public:
  // One inotify instance for the object's life; throws std::runtime_error
  // (the harness's failure) when the system gives none.
  FolderOpens();
  ~FolderOpens();
  FolderOpens(const FolderOpens&) = delete;
  FolderOpens& operator=(const FolderOpens&) = delete;

  // Starts watching these folders (only them, not what they hold below)
  // for opens, and forgets every open seen so far.
  void watch(const std::vector<std::filesystem::path>& folders);

  // What was opened in the watched folders since watch(): "folder/name",
  // or the folder itself.
  std::vector<std::string> opened();

 private:
  void drain(std::vector<std::string>* into);
  int fd_ = -1;
  std::vector<std::pair<int, std::filesystem::path>> watches_;
};

}  // namespace vern::fuzz
