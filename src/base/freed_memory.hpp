// Memory a command frees is kept for its own next allocations.
//
// glibc's malloc hands a large block (128 KB at first) to the system as
// soon as it is freed, and trims the top of its heap back whenever more
// than 128 KB lies free there. Inference builds and drops much in passes
// (a tree per example, a graph per merge round, a check's working lists),
// so the same memory went back and forth: every page asked for again is a
// page fault, about 7 microseconds each on the virtual machines we run on.
// Inferring the city took 15,100 faults and a fifth of its CPU time in the
// kernel; kept, it takes 12,800, 6 % less wall time. Blocks of 32 MB or
// more (a million-part example's arrays) still go back at once, so the
// peak stays as it was within 3 % (753 -> 778 MB).
#pragma once

#include <cstddef>

namespace vern {

// The largest block served from the heap, and how much free memory a heap
// keeps at its top, once keep_freed_memory() has run.
inline constexpr std::size_t kLargestHeapBlock = std::size_t{32} << 20;
inline constexpr std::size_t kKeptFree = std::size_t{64} << 20;

// Blocks under 32 MB come from the heap and freed memory stays there up to
// 64 MB. Once, at the start of a command (guarded_main.hpp); a no-op where
// the C library is not glibc.
void keep_freed_memory();

}  // namespace vern
