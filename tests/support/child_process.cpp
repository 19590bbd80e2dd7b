#include "support/child_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <stdexcept>
#include <string>

namespace vern::test {

ChildProcess::ChildProcess(const std::string& program, const std::vector<std::string>& args,
                           const std::filesystem::path& folder, const ChildSetup& setup) {
  const std::string out = (capture_ / "out").string(), err = (capture_ / "err").string();
  const std::string tool = std::string(VERN_BIN_DIR) + "/" + program;
  measured_ = setup.measure_peak;
  const std::string binary = measured_ ? std::string(VERN_PEAK_METER) : tool;
  std::vector<std::string> words{binary};
  if (measured_) words.insert(words.end(), {(capture_ / "peak").string(), tool});
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);

  pid_ = fork();
  if (pid_ < 0) throw std::runtime_error("fork failed");
  if (pid_ != 0) return;
  // The child: only async-signal-safe calls until exec.
  const int o = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int e = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int in = open("/dev/null", O_RDONLY);
  if (o < 0 || e < 0 || in < 0 || chdir(folder.c_str()) != 0) _exit(127);
  dup2(o, 1);
  dup2(e, 2);
  dup2(in, 0);
  if (setup.limits.address_space_mib != 0) {
    const rlimit cap{setup.limits.address_space_mib << 20, setup.limits.address_space_mib << 20};
    if (setrlimit(RLIMIT_AS, &cap) != 0) _exit(127);
  }
  if (setup.limits.file_bytes != 0) {
    const rlimit cap{setup.limits.file_bytes, setup.limits.file_bytes};
    if (setrlimit(RLIMIT_FSIZE, &cap) != 0) _exit(127);
    signal(SIGXFSZ, SIG_IGN);  // inherited: the write fails instead of killing the program
  }
  if (setup.limits.stack_kib != 0) {
    const rlimit cap{setup.limits.stack_kib << 10, setup.limits.stack_kib << 10};
    if (setrlimit(RLIMIT_STACK, &cap) != 0) _exit(127);
  }
  // No core files in the run folder from signals that dump one (SIGQUIT).
  const rlimit no_core{0, 0};
  setrlimit(RLIMIT_CORE, &no_core);
  if (setup.umask >= 0) umask(static_cast<mode_t>(setup.umask));
  for (const int sig : setup.ignored_signals) signal(sig, SIG_IGN);
  alarm(kHangSeconds);  // kept across exec: a hang fails the test, not the suite
  execv(binary.c_str(), argv.data());
  _exit(127);
}

ChildProcess::~ChildProcess() {
  if (pid_ <= 0) return;
  kill(pid_, SIGKILL);
  int status = 0;
  waitpid(pid_, &status, 0);
}

ChildProcess::Ended ChildProcess::wait() {
  int status = 0;
  if (waitpid(pid_, &status, 0) != pid_) throw std::runtime_error("waitpid failed");
  pid_ = -1;
  Ended r;
  r.result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  r.result.out = read_file(capture_ / "out");
  r.result.err = read_file(capture_ / "err");
  if (measured_) {
    const std::string peak = read_file(capture_ / "peak");
    if (peak.empty()) throw std::runtime_error("vern_peak wrote no peak memory");
    r.peak_kib = std::stol(peak);
  }
  return r;
}

std::string ChildProcess::err_so_far() const { return read_file(capture_ / "err"); }

}  // namespace vern::test
