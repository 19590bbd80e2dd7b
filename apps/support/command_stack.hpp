// The stack every thread of a command runs on, whatever `ulimit -s` says.
//
// Derivation, checking and the grammar reader recurse as deep as their
// input asks, within limits (--max-depth, the reader's 256 levels) that
// were set, and are tested, on the 8 MiB stack Linux gives by default.
// A user's smaller `ulimit -s` would turn those limits into crashes, and
// threads start with the same size as the main thread's limit. So a
// command runs its work on a thread of its own and gives that thread, and
// every thread started after it, at least kMinimumStack, or the user's
// limit when it is larger (a deeper grammar then goes deeper).
// base/stack_guard.hpp still stops recursion before the end of
// whatever stack a thread has.
#pragma once

#include <cstddef>
#include <functional>

#include "base/sanitizers.hpp"

namespace vern {

// How many times larger a frame is in this build than in a plain one: the
// address sanitizer's redzones and instrumentation make frames about three
// times larger, and the limits above are promises in depth, not in bytes.
#if defined(VERN_ADDRESS_SANITIZER)
inline constexpr std::size_t kFrameScale = 4;
#else
inline constexpr std::size_t kFrameScale = 1;
#endif

// The stack a command's threads get when the user's limit is smaller.
inline constexpr std::size_t kMinimumStack = (std::size_t{8} << 20) * kFrameScale;
// The most a thread is given when the limit is larger or unlimited: address
// space, reserved but only used as deep as recursion goes.
inline constexpr std::size_t kMaximumStack = std::size_t{1} << 30;

// The stack size a command's threads get under this process's limit.
std::size_t command_stack_size();

// Makes command_stack_size() the stack of every thread started from now on
// and runs `work` on such a thread, returning its result. Exceptions pass
// through to the caller. If no thread can be started (the address space is
// capped too tight), runs `work` here instead.
int run_on_command_stack(const std::function<int()>& work);

}  // namespace vern
