#include "base/freed_memory.hpp"

#include <cstdlib>  // defines __GLIBC__ where the C library is glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace vern {

// kLargestHeapBlock is glibc's own ceiling for the threshold it raises by
// itself, so a larger block is mapped from the start.
void keep_freed_memory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, static_cast<int>(kLargestHeapBlock));
  mallopt(M_TRIM_THRESHOLD, static_cast<int>(kKeptFree));
#endif
}

}  // namespace vern
