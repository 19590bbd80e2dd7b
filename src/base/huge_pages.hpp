// A command's heaps in huge pages.
//
// Inference allocates tens of megabytes in small blocks, and each 4 KB page
// touched for the first time is a page fault: about 7 microseconds each on
// the virtual machines we run on, 12,600 of them when inferring the city,
// about a fifth of its wall time. Transparent huge pages map 2 MB at one
// fault, but in Linux's "madvise" mode (this machine's) only for memory
// that asks for them. glibc asks for its heaps only when told so before the
// program starts (GLIBC_TUNABLES=glibc.malloc.hugetlb=1), so a command asks
// itself: each thread grows the heap it allocates from (its glibc arena) by
// a reserve, marks the reserve MADV_HUGEPAGE and frees it. Freed, the
// reserve stays at the heap's top (keep_freed_memory keeps up to 64 MB
// there), and the thread's next blocks are carved from it. Nothing is
// touched ahead: memory is taken 2 MB at a time as it is used.
//
// It is the command shell's choice (guarded_main), not the library's: a
// program that embeds the library keeps its own allocator's behaviour.
// Where the system has no transparent huge pages, or the C library is not
// glibc, or a sanitizer brings its own allocator, all of this does nothing.
#pragma once

namespace vern {

// Prepares this thread's heap, and from now on the heap of every thread
// parallel_for and run_alongside start. Once, at the start of a command,
// after keep_freed_memory() (the reserve must stay in the heap when freed).
void use_huge_pages();

// Prepares this thread's heap if use_huge_pages() was called; parallel_for
// and run_alongside call it first thing in each thread they start.
void huge_pages_for_this_thread();

// Whether this build asks for huge pages at all: glibc's allocator on
// Linux, no sanitizer's in its place.
bool huge_pages_built();

}  // namespace vern
