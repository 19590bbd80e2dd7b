#include "child_process.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <stdexcept>

extern char** environ;

namespace vern {

namespace {

// Spawns argv with its standard output sent to fd `out`; returns the pid.
pid_t spawn(const std::vector<std::string>& argv, int out) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (out >= 0) posix_spawn_file_actions_adddup2(&actions, out, 1);
  else posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int error = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) throw std::runtime_error("cannot run " + argv[0] + ": " + std::strerror(error));
  return pid;
}

}  // namespace

ChildRun run_child(const std::vector<std::string>& argv) {
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) throw std::runtime_error("cannot make a pipe");
  std::vector<std::string> helper{sibling_program("vern_bench").string(), "--measure-child"};
  helper.insert(helper.end(), argv.begin(), argv.end());
  const pid_t pid = spawn(helper, pipe_fds[1]);
  close(pipe_fds[1]);
  std::string report;
  char buffer[256];
  for (ssize_t got; (got = read(pipe_fds[0], buffer, sizeof buffer)) > 0;) report.append(buffer, static_cast<std::size_t>(got));
  close(pipe_fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  ChildRun run;
  long long rss = 0;
  if (std::sscanf(report.c_str(), "%lf %lf %lld %d", &run.seconds, &run.cpu_seconds, &rss, &run.exit_code) != 4)
    throw std::runtime_error("no measurement from " + helper[0]);
  run.peak_rss = rss;
  return run;
}

std::filesystem::path sibling_program(const std::string& name) {
  return std::filesystem::read_symlink("/proc/self/exe").parent_path() / name;
}

bool is_measure_child_command(const char* arg) { return std::strcmp(arg, "--measure-child") == 0; }

int measure_child_main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: vern_bench --measure-child COMMAND [ARGS...]\n");
    return 2;
  }
  const std::vector<std::string> command(argv + 2, argv + argc);
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = spawn(command, -1);
  int status = 0;
  rusage usage{};
  // wait4: this child's own peak, which began at this small process's size.
  if (wait4(pid, &status, 0, &usage) != pid) return 70;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  auto in_seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  std::printf("%.6f %.6f %lld %d\n", seconds, in_seconds(usage.ru_utime) + in_seconds(usage.ru_stime),
              static_cast<long long>(usage.ru_maxrss) * 1024,  // Linux: kilobytes
              WIFEXITED(status) ? WEXITSTATUS(status) : -1);
  return 0;
}

}  // namespace vern
