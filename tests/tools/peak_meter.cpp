// vern_peak FILE PROGRAM [ARGS...]: runs PROGRAM and writes its peak
// resident memory in KiB to FILE, then ends as PROGRAM ended: with its exit
// code, or killed by the same signal.
//
// Why a program of its own: the tests measure a tool's memory with
// getrusage of the child they wait for, and Linux counts in a process's
// peak the memory of the process it was forked from, exec or not. A tool
// forked from the test process (over 100 MB when the whole suite runs in
// one process) was measured at the test's size, not its own. Forked from
// this small program, the tool's peak is its own.
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: vern_peak FILE PROGRAM [ARGS...]\n");
    return 127;
  }
  // The test's hang alarm (kept across exec) is the tool's to keep: fork
  // does not pass a pending alarm on.
  const unsigned remaining = alarm(0);
  const pid_t pid = fork();
  if (pid < 0) return 127;
  if (pid == 0) {
    if (remaining != 0) alarm(remaining);
    execv(argv[2], argv + 2);
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid) return 127;
  if (std::FILE* f = std::fopen(argv[1], "w")) {
    std::fprintf(f, "%ld\n", usage.ru_maxrss);
    std::fclose(f);
  }
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    signal(sig, SIG_DFL);
    raise(sig);
    return 128 + sig;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 127;
}
