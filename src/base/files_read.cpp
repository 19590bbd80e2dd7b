#include "base/files_read.hpp"

#include <atomic>
#include <map>
#include <mutex>
#include <string>
#include <utility>

#include "base/error.hpp"

namespace vern {

namespace {

// Examples are read on several threads at once.
std::atomic<bool> g_recording{false};
std::mutex g_mutex;
std::map<std::pair<dev_t, ino_t>, std::string> g_read;  // the file -> the path it was first read as

}  // namespace

FilesReadRecorded::FilesReadRecorded() { g_recording.store(true); }

FilesReadRecorded::~FilesReadRecorded() {
  g_recording.store(false);
  const std::lock_guard lock(g_mutex);
  g_read.clear();
}

void note_file_read(const std::filesystem::path& path, const struct stat& st) {
  if (!g_recording.load(std::memory_order_relaxed)) return;
  const std::lock_guard lock(g_mutex);
  g_read.try_emplace({st.st_dev, st.st_ino}, path.string());
}

void refuse_file_read(const std::filesystem::path& output) {
  if (!g_recording.load(std::memory_order_relaxed)) return;
  struct stat st {};
  if (::stat(output.c_str(), &st) == 0) refuse_file_read(output, st);
}

void refuse_file_read(const std::filesystem::path& output, const struct stat& st) {
  if (!g_recording.load(std::memory_order_relaxed)) return;
  std::string read_as;
  {
    const std::lock_guard lock(g_mutex);
    const auto it = g_read.find({st.st_dev, st.st_ino});
    if (it == g_read.end()) return;
    read_as = it->second;
  }
  // A file read and removed since leaves its inode to another: only an
  // input still there is one.
  struct stat now {};
  if (::stat(read_as.c_str(), &now) != 0 || now.st_dev != st.st_dev || now.st_ino != st.st_ino) return;
  fail(ErrorKind::Usage, output.string(), {},
       "this output is a file the run has read" + (read_as == output.string() ? "" : " (as " + read_as + ")") +
           ": writing it would destroy an input",
       "choose another output path; inputs are never overwritten");
}

}  // namespace vern
