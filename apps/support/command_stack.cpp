#include "support/command_stack.hpp"

#include <pthread.h>
#include <signal.h>
#include <sys/resource.h>

#include <algorithm>
#include <exception>

namespace vern {

std::size_t command_stack_size() {
  rlimit limit{};
  if (::getrlimit(RLIMIT_STACK, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return kMaximumStack;
  return std::clamp(static_cast<std::size_t>(limit.rlim_cur), kMinimumStack, kMaximumStack);
}

namespace {

struct Job {
  const std::function<int()>* work;
  int result = 0;
  std::exception_ptr error;
  sigset_t mask;  // the signal mask the work runs with: the caller's own
};

void* run_job(void* arg) {
  auto* job = static_cast<Job*>(arg);
  pthread_sigmask(SIG_SETMASK, &job->mask, nullptr);
  try {
    job->result = (*job->work)();
  } catch (...) {
    job->error = std::current_exception();
  }
  return nullptr;
}

}  // namespace

int run_on_command_stack(const std::function<int()>& work) {
  // The default for every thread created from now on: std::thread has no
  // way to ask for a stack size, and parallel_for's workers, run_alongside's
  // helper and the OBJ reader's read-ahead recurse on the same input.
  pthread_attr_t attr;
  if (::pthread_attr_init(&attr) != 0) return work();
  const bool sized = ::pthread_attr_setstacksize(&attr, command_stack_size()) == 0;
  if (sized) ::pthread_setattr_default_np(&attr);
  // Signals from outside (Ctrl-C, SIGTERM) go to the thread that writes
  // the files, as they did when the work ran here: its handler removes the
  // temporaries (interrupt_cleanup.hpp) while no other thread makes more.
  // This thread only waits, with every signal blocked.
  Job job{&work, 0, nullptr, {}};
  sigset_t all;
  sigfillset(&all);
  pthread_sigmask(SIG_BLOCK, &all, &job.mask);
  pthread_t thread;
  const bool started = sized && ::pthread_create(&thread, &attr, run_job, &job) == 0;
  ::pthread_attr_destroy(&attr);
  if (!started) {
    pthread_sigmask(SIG_SETMASK, &job.mask, nullptr);
    return work();
  }
  ::pthread_join(thread, nullptr);
  pthread_sigmask(SIG_SETMASK, &job.mask, nullptr);
  if (job.error) std::rethrow_exception(job.error);
  return job.result;
}

}  // namespace vern
