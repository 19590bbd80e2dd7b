#include "graph/freed_memory.hpp"

#include <cstdlib>  // defines __GLIBC__ where the C library is glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace vern {

namespace {
// The largest block served from the heap: glibc's own ceiling for the
// threshold it raises by itself, so a larger one is mapped from the start.
constexpr int kLargestHeapBlock = 32 << 20;
// Free memory kept at the top of a heap before it is given back.
constexpr int kKeptFree = 64 << 20;
}  // namespace

void keep_freed_memory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, kLargestHeapBlock);
  mallopt(M_TRIM_THRESHOLD, kKeptFree);
#endif
}

}  // namespace vern
