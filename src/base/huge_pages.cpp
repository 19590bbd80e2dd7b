#include "base/huge_pages.hpp"

#include <atomic>
#include <cstdint>
#include <cstdlib>  // defines __GLIBC__ where the C library is glibc

#include "base/freed_memory.hpp"
#include "base/sanitizers.hpp"

#if defined(__GLIBC__) && defined(__linux__) && !defined(VERN_SANITIZER_ALLOCATOR)
#define VERN_HUGE_PAGES 1
#include <sys/mman.h>
#endif

namespace vern {

namespace {

#if defined(VERN_HUGE_PAGES)
std::atomic<bool> wanted{false};

constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
// Under the largest block the heap serves (a larger one would be mapped
// on its own and unmapped when freed) and under what it keeps free.
constexpr std::size_t kReserve = kLargestHeapBlock - kHugePage;
static_assert(kReserve < kKeptFree);

void prepare_heap() {
  void* block = std::malloc(kReserve);
  if (!block) return;  // no room for the reserve: the heap stays as it was
  // The whole huge pages inside the block.
  const auto start = reinterpret_cast<std::uintptr_t>(block);
  const std::uintptr_t first = (start + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t end = (start + kReserve) & ~(kHugePage - 1);
  if (end > first) madvise(reinterpret_cast<void*>(first), end - first, MADV_HUGEPAGE);  // advice: failing is harmless
  std::free(block);
}
#endif

}  // namespace

void use_huge_pages() {
#if defined(VERN_HUGE_PAGES)
  wanted.store(true, std::memory_order_relaxed);
  prepare_heap();
#endif
}

void huge_pages_for_this_thread() {
#if defined(VERN_HUGE_PAGES)
  if (wanted.load(std::memory_order_relaxed)) prepare_heap();
#endif
}

bool huge_pages_built() {
#if defined(VERN_HUGE_PAGES)
  return true;
#else
  return false;
#endif
}

}  // namespace vern
