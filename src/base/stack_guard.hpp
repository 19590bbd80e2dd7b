// How much of the running thread's stack is left, for recursion whose
// depth the input decides.
//
// A rule call nests the derivation one level deeper, and how many bytes a
// level takes depends on the operations in the rule's body (and on the
// build: sanitizers make frames several times larger). A count of calls
// alone (--max-depth) cannot promise that the stack holds, so the
// derivation also asks this guard before each call and stops with a Limit
// error while there is still room, instead of crashing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace vern {

class StackGuard {
 public:
  // Measures the calling thread's stack; keeps `reserve` bytes untouched
  // for what runs below the last check (the body of one rule, evaluating
  // an expression, formatting the error). On a stack of less than twice
  // the reserve (a small thread of a program that embeds the library) half
  // of it is kept instead: a guard that keeps less still stops runaway
  // recursion, where no guard at all would let it crash.
  explicit StackGuard(std::size_t reserve = kDefaultReserve);

  // True when the caller's frame is within `reserve` bytes of the end.
  bool exhausted() const {
    const auto here = reinterpret_cast<std::uintptr_t>(__builtin_frame_address(0));
    return here < limit_;
  }

  // Bytes of stack the thread has in all (0 when it cannot be told).
  std::size_t size() const { return size_; }
  // The size as messages state it: "8 MiB", "512 KiB".
  std::string size_text() const;

  // The calling thread's guard, measured once per thread (measuring the
  // main thread reads /proc/self/maps: too slow for every derivation).
  static const StackGuard& for_this_thread();

  // Enough for a rule body of the parser's maximum nesting (graph/parser)
  // with sanitizer-sized frames.
  static constexpr std::size_t kDefaultReserve = std::size_t{512} << 10;

 private:
  std::uintptr_t limit_ = 0;  // the lowest frame address allowed
  std::size_t size_ = 0;
};

}  // namespace vern
