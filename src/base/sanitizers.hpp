// Which sanitizers this build runs under, as GCC (__SANITIZE_*__) and
// Clang (__has_feature) each say it. Code that a sanitizer changes the
// ground under (its own allocator, frames several times larger) asks here.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define VERN_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define VERN_ADDRESS_SANITIZER 1
#endif
#endif

// A sanitizer that brings its own allocator (address, memory, thread).
#if defined(VERN_ADDRESS_SANITIZER) || defined(__SANITIZE_THREAD__)
#define VERN_SANITIZER_ALLOCATOR 1
#elif defined(__has_feature)
#if __has_feature(memory_sanitizer) || __has_feature(thread_sanitizer)
#define VERN_SANITIZER_ALLOCATOR 1
#endif
#endif
