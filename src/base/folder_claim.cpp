#include "base/folder_claim.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <optional>
#include <string_view>

#include "base/error.hpp"
#include "base/interrupt_cleanup.hpp"

namespace vern {

namespace fs = std::filesystem;

namespace {

// A temporary whose run cannot be told over (its lock file cannot be
// probed) goes once nothing has changed it for a day: a run keeps its
// outputs waiting for minutes (a million variants are written in less
// than an hour), and a day is long enough for any clock two machines
// sharing the folder disagree by.
constexpr std::time_t kUntoldStaleSeconds = 24 * 60 * 60;

// A file of some run, as its name says.
struct RunFile {
  std::string output;  // the output a temporary stands for; empty for a lock file
  std::string run;     // "<pid>-<letters>"
};

bool six_letters(std::string_view s) {
  if (s.size() != 6) return false;
  for (const char c : s)
    if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9'))) return false;
  return true;
}

// ".NAME.vern-<pid>-<run>-XXXXXX" (a temporary), the same with ".old" (the
// backup a commit keeps), ".vern-<pid>-<run>-XXXXXX.lock" (a lock file).
std::optional<RunFile> parse(const std::string& name) {
  if (!name.starts_with('.')) return std::nullopt;
  const std::size_t tag = name.rfind(".vern-");
  if (tag == std::string::npos) return std::nullopt;
  const std::string_view rest = std::string_view(name).substr(tag + 6);
  std::size_t digits = 0;
  while (digits < rest.size() && digits < 10 && rest[digits] >= '0' && rest[digits] <= '9') ++digits;
  if (digits == 0 || rest.size() < digits + 14 || rest[digits] != '-' || rest[digits + 7] != '-') return std::nullopt;
  if (!six_letters(rest.substr(digits + 1, 6)) || !six_letters(rest.substr(digits + 8, 6))) return std::nullopt;
  const std::string_view suffix = rest.substr(digits + 14);
  const bool lock_file = tag == 0;
  if (lock_file ? suffix != ".lock" : !(suffix.empty() || suffix == ".old")) return std::nullopt;
  return RunFile{lock_file ? std::string() : name.substr(1, tag - 1), std::string(rest.substr(0, digits + 7))};
}

// This run's "<pid>-<letters>" (run_tag() is ".vern-<pid>-<letters>-").
const std::string& own_run() {
  static const std::string run = run_tag().substr(6, run_tag().size() - 7);
  return run;
}

// A whole-file open file description lock of `type` on fd, not waiting.
int lock_whole(int fd, short type) {
  struct flock lock {};
  lock.l_type = type;
  lock.l_whence = SEEK_SET;
  return ::fcntl(fd, F_OFD_SETLK, &lock);
}

enum class Probe { Held, Free, Gone, Untold };

// Whether lock file `name` is held by its run. A free one is removed
// when asked, while this process holds it (a run making it anew cannot
// lock it in between, and sees it gone once it has: FolderClaim's
// constructor).
Probe probe(int folder, const std::string& name, bool remove_when_free) {
  const int fd = ::openat(folder, name.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return errno == ENOENT ? Probe::Gone : Probe::Untold;
  Probe result = Probe::Free;
  if (lock_whole(fd, F_RDLCK) != 0) result = errno == EAGAIN || errno == EACCES ? Probe::Held : Probe::Untold;
  if (result == Probe::Free && remove_when_free) ::unlinkat(folder, name.c_str(), 0);
  ::close(fd);
  return result;
}

bool day_old(int folder, const std::string& name) {
  struct stat st {};
  if (::fstatat(folder, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0) return false;
  // The change time: a backup is a second name of the file it keeps,
  // whose modification time may be years old; naming it changed it.
  return std::time(nullptr) - st.st_ctime > kUntoldStaleSeconds;
}

// Calls each(name) for every entry of `folder`.
template <class Each>
void each_entry(int folder, Each each) {
  const int fd = ::openat(folder, ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  DIR* dir = ::fdopendir(fd);
  if (!dir) {
    ::close(fd);
    return;
  }
  while (const dirent* entry = ::readdir(dir)) each(std::string(entry->d_name));
  ::closedir(dir);
}

[[noreturn]] void io_error(const fs::path& path, const std::string& what, int err) {
  fail(ErrorKind::Io, path.string(), {}, what + ": " + std::strerror(err),
       "check that the folder exists and is writable");
}

}  // namespace

FolderClaim::FolderClaim(const fs::path& folder, const fs::path& output) : folder_(folder.empty() ? "." : folder) {
  watch_folder(folder_);  // from before the lock file is made: a signal removes it
  folder_fd_ = ::open(folder_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (folder_fd_ < 0) io_error(output, "cannot create a temporary file in " + folder_.string(), errno);
  for (int attempt = 0; lock_fd_ < 0; ++attempt) {
    std::string path = lock_file_template(folder_);
    const int fd = [&] {
      const SignalsWait made_whole;
      return ::mkostemps(path.data(), 5, O_CLOEXEC);
    }();
    if (fd < 0 || attempt == 8) {
      const int err = fd < 0 ? errno : EAGAIN;
      if (fd >= 0) ::close(fd);
      ::close(folder_fd_);
      io_error(output, "cannot create a temporary file in " + folder_.string(), err);
    }
    // A run sweeping the folder may have found the file free before it
    // was locked, and removed it (probe): then another. Where the file
    // system has no locks, the file is kept unlocked: other runs cannot
    // tell it either, and leave this run's files be for a day.
    struct stat st {};
    const bool locked = lock_whole(fd, F_WRLCK) == 0;
    const bool taken = !locked && (errno == EAGAIN || errno == EACCES);
    if (taken || (locked && (::fstat(fd, &st) != 0 || st.st_nlink == 0))) {
      ::close(fd);
      continue;
    }
    lock_fd_ = fd;
    lock_name_ = fs::path(path).filename().string();
  }
  try {
    list();
  } catch (...) {
    release();
    throw;
  }
}

FolderClaim::~FolderClaim() { release(); }

void FolderClaim::release() {
  // Removed while still locked: nobody sees it free first.
  ::unlinkat(folder_fd_, lock_name_.c_str(), 0);
  ::close(lock_fd_);
  ::close(folder_fd_);
}

void FolderClaim::list() {
  each_entry(folder_fd_, [&](const std::string& name) {
    if (name.size() < 20 || name[0] != '.') return;
    const std::optional<RunFile> file = parse(name);
    if (!file || file->run == own_run()) return;
    Run& run = runs_[file->run];
    if (file->output.empty()) {
      run.lock_files.push_back(name);
    } else {
      ++run.temporaries;
      leftovers_[file->output].push_back({name, file->run});
    }
  });
  // A run makes its lock file before its temporaries, but a listing may
  // show a file made during it and miss one made before (the order is the
  // file system's): runs seen without a lock file are looked for again.
  bool again = false;
  for (const auto& [id, run] : runs_) again |= run.lock_files.empty();
  if (again) {
    each_entry(folder_fd_, [&](const std::string& name) {
      if (!name.starts_with(".vern-")) return;
      const std::optional<RunFile> file = parse(name);
      if (!file || !file->output.empty()) return;
      const auto it = runs_.find(file->run);
      if (it != runs_.end() && it->second.temporaries > 0 && it->second.lock_files.empty())
        it->second.lock_files.push_back(name);
    });
  }
  // A run that left no temporary here needs no lock file either.
  for (auto& [id, run] : runs_)
    if (run.temporaries == 0) remove_lock_files(run);
}

FolderClaim::Holding FolderClaim::holding(Run& run) {
  if (run.holding != Holding::NotAsked) return run.holding;
  run.holding = Holding::Over;
  for (const std::string& lock_file : run.lock_files) {
    const Probe p = probe(folder_fd_, lock_file, false);
    if (p == Probe::Held) return run.holding = Holding::Live;
    if (p == Probe::Untold) run.holding = Holding::Untold;
  }
  return run.holding;
}

void FolderClaim::remove_lock_files(Run& run) {
  if (holding(run) != Holding::Over) return;
  for (const std::string& lock_file : run.lock_files) probe(folder_fd_, lock_file, true);
  run.lock_files.clear();
}

void FolderClaim::sweep(const std::string& name) {
  if (leftovers_.empty()) return;
  const auto it = leftovers_.find(name);
  if (it == leftovers_.end()) return;
  for (const Leftover& left : it->second) {
    Run& run = runs_[left.run];
    const Holding h = holding(run);
    if (h == Holding::Live || (h == Holding::Untold && !day_old(folder_fd_, left.file))) continue;
    if (::unlinkat(folder_fd_, left.file.c_str(), 0) != 0 && errno != ENOENT) continue;
    if (--run.temporaries == 0) remove_lock_files(run);
  }
  leftovers_.erase(it);
}

int FolderClaim::sync_folder() const { return ::fsync(folder_fd_) == 0 ? 0 : errno; }

int FolderClaim::sync_file_system() const { return ::syncfs(folder_fd_) == 0 ? 0 : errno; }

}  // namespace vern
