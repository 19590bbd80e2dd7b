#include "base/stack_guard.hpp"

#include <pthread.h>

#include <algorithm>

namespace vern {

StackGuard::StackGuard(std::size_t reserve) {
  // Linux (glibc): the thread's stack as mapped, the main thread's included
  // (sized by its resource limit). Stacks grow down from addr + size.
  pthread_attr_t attr;
  if (pthread_getattr_np(pthread_self(), &attr) != 0) return;  // no guard: limit_ stays 0
  void* addr = nullptr;
  std::size_t size = 0;
  if (pthread_attr_getstack(&attr, &addr, &size) == 0 && size > 0) {
    size_ = size;
    limit_ = reinterpret_cast<std::uintptr_t>(addr) + std::min(reserve, size / 2);
  }
  pthread_attr_destroy(&attr);
}

std::string StackGuard::size_text() const {
  if (size_ >= (std::size_t{1} << 20)) return std::to_string(size_ >> 20) + " MiB";
  return std::to_string(size_ >> 10) + " KiB";
}

const StackGuard& StackGuard::for_this_thread() {
  thread_local const StackGuard guard;
  return guard;
}

}  // namespace vern
