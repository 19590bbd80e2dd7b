#include "forward/stack_guard.hpp"

#include <pthread.h>

namespace vern {

StackGuard::StackGuard(std::size_t reserve) {
  // Linux (glibc): the thread's stack as mapped, the main thread's included
  // (sized by its resource limit). Stacks grow down from addr + size.
  pthread_attr_t attr;
  if (pthread_getattr_np(pthread_self(), &attr) != 0) return;  // no guard: limit_ stays 0
  void* addr = nullptr;
  std::size_t size = 0;
  if (pthread_attr_getstack(&attr, &addr, &size) == 0 && size > reserve) {
    size_ = size;
    limit_ = reinterpret_cast<std::uintptr_t>(addr) + reserve;
  }
  pthread_attr_destroy(&attr);
}

const StackGuard& StackGuard::for_this_thread() {
  thread_local const StackGuard guard;
  return guard;
}

}  // namespace vern
