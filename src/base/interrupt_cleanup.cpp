#include "base/interrupt_cleanup.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <pthread.h>
#include <sys/random.h>
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <mutex>

namespace vern {

namespace fs = std::filesystem;

namespace {

// Only async-signal-safe calls run in the handler: open, getdents64,
// unlinkat, close, nanosleep, signal, raise; the folders and the name to
// look for are prepared before any signal can need them.
constexpr std::size_t kMaxFolders = 64;
constexpr std::size_t kMaxPath = 4096;

struct WatchedFolder {
  std::atomic<bool> ready{false};
  char path[kMaxPath];
};
WatchedFolder g_folders[kMaxFolders];
std::atomic<std::size_t> g_folder_count{0};
std::mutex g_watch_mutex;  // serialises watch_folder, never taken in the handler

// ".vern-<pid>-<run>-": what this process's file names hold, for the handler.
char g_own_tag[48];

// Six letters and digits, as mkstemp draws them (some 36 bits), so that
// two processes with one process id (in two PID namespaces) differ.
std::string run_letters() {
  static constexpr char kLetters[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  unsigned char bytes[6] = {};
  if (::getrandom(bytes, sizeof bytes, 0) != static_cast<ssize_t>(sizeof bytes)) {
    // No entropy to be had: the clock's nanoseconds differ as well.
    std::uint64_t t = static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
    for (unsigned char& b : bytes) b = static_cast<unsigned char>(t), t >>= 8;
  }
  std::string letters;
  for (const unsigned char b : bytes) letters += kLetters[b % (sizeof kLetters - 1)];
  return letters;
}

const char* own_tag() {
  static std::once_flag once;
  std::call_once(once, [] {
    const std::string tag = ".vern-" + std::to_string(::getpid()) + "-" + run_letters() + "-";
    std::memcpy(g_own_tag, tag.c_str(), tag.size() + 1);
  });
  return g_own_tag;
}

// Whether `name` is one of this process's files: a hidden name holding
// the tag. (No library call: strstr is not on the list of
// async-signal-safe functions.)
bool is_own_temporary(const char* name, const char* tag) {
  if (name[0] != '.') return false;
  for (const char* start = name; *start; ++start) {
    const char* a = start;
    const char* b = tag;
    while (*b && *a == *b) ++a, ++b;
    if (!*b) return true;
  }
  return false;
}

void remove_own_temporaries(const char* folder, const char* tag) {
  const int dir = ::open(folder, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir < 0) return;
  alignas(dirent64) char buffer[8192];
  for (;;) {
    const ssize_t n = ::getdents64(dir, buffer, sizeof buffer);
    if (n <= 0) break;
    for (ssize_t at = 0; at < n;) {
      const auto* entry = reinterpret_cast<const dirent64*>(buffer + at);
      if (is_own_temporary(entry->d_name, tag)) ::unlinkat(dir, entry->d_name, 0);
      at += entry->d_reclen;
    }
  }
  ::close(dir);
}

// A signal is ending the run; changes to its files under way (SignalsWait).
std::atomic<bool> g_ending{false};
std::atomic<int> g_changing{0};

void on_signal(int sig) {
  // Changes begun from now on wait for the end; those under way end first.
  g_ending.store(true);
  while (g_changing.load() > 0) {
    const timespec a_millisecond{0, 1'000'000};
    ::nanosleep(&a_millisecond, nullptr);
  }
  const std::size_t count = g_folder_count.load();
  for (std::size_t i = 0; i < count && i < kMaxFolders; ++i)
    if (g_folders[i].ready.load()) remove_own_temporaries(g_folders[i].path, g_own_tag);
  // Ends the process as the signal would have: the raised signal waits
  // (it is blocked in its own handler) and ends it when this returns.
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

constexpr int kEndingSignals[] = {SIGHUP,    SIGINT,  SIGQUIT,   SIGTERM, SIGPIPE, SIGALRM, SIGUSR1,
                                  SIGUSR2,   SIGXCPU, SIGXFSZ,   SIGVTALRM, SIGPROF, SIGABRT};

}  // namespace

const std::string& run_tag() {
  static const std::string tag = own_tag();
  return tag;
}

std::string temporary_template(const fs::path& destination) {
  const fs::path folder = destination.has_parent_path() ? destination.parent_path() : fs::path(".");
  return (folder / ("." + destination.filename().string() + own_tag() + "XXXXXX")).string();
}

std::string lock_file_template(const fs::path& folder) {
  return ((folder.empty() ? fs::path(".") : folder) / (std::string(own_tag()) + "XXXXXX.lock")).string();
}

void watch_folder(const fs::path& folder) {
  own_tag();  // ready before any handler reads it
  // A folder of a million variants asks a million times: the same folder
  // as last time costs no system call.
  static fs::path last;
  {
    std::lock_guard lock(g_watch_mutex);
    if (folder == last) return;
  }
  std::error_code ec;
  const std::string path = fs::absolute(folder.empty() ? fs::path(".") : folder, ec).lexically_normal().string();
  if (ec || path.size() >= kMaxPath) return;
  std::lock_guard lock(g_watch_mutex);
  last = folder;
  const std::size_t count = g_folder_count.load();
  for (std::size_t i = 0; i < count; ++i)
    if (path == g_folders[i].path) return;
  if (count == kMaxFolders) return;
  std::memcpy(g_folders[count].path, path.c_str(), path.size() + 1);
  g_folders[count].ready.store(true);
  g_folder_count.store(count + 1);
}

SignalsWait::SignalsWait() {
  sigset_t all;
  sigfillset(&all);
  pthread_sigmask(SIG_BLOCK, &all, &saved_);
  g_changing.fetch_add(1);
  if (g_ending.load()) {
    // Too late: the handler, on another thread, has removed (or is
    // removing) this run's files and ends the process.
    g_changing.fetch_sub(1);
    for (;;) ::pause();
  }
}

SignalsWait::~SignalsWait() {
  g_changing.fetch_sub(1);
  pthread_sigmask(SIG_SETMASK, &saved_, nullptr);
}

void install_interrupt_cleanup() {
  own_tag();
  struct sigaction handler {};
  handler.sa_handler = on_signal;
  // One handler at a time: a second signal waits for the first to end the process.
  sigemptyset(&handler.sa_mask);
  for (const int sig : kEndingSignals) sigaddset(&handler.sa_mask, sig);
  for (const int sig : kEndingSignals) {
    struct sigaction current {};
    if (::sigaction(sig, nullptr, &current) != 0) continue;
    const bool by_default = !(current.sa_flags & SA_SIGINFO) && current.sa_handler == SIG_DFL;
    if (by_default) ::sigaction(sig, &handler, nullptr);
  }
}

}  // namespace vern
