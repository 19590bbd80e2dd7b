// How much work a check may do (CheckOptions::max_steps, check --max-steps).
//
// Matching can try exponentially many placements and alternatives; every
// step of it passes through one Budget for the whole check, so a grammar
// and example that would take too long stop with an error that names the
// limit, whatever part of the search runs.
#pragma once

#include <cstdint>
#include <string>

#include "base/error.hpp"
#include "base/stack_guard.hpp"

namespace vern::check_detail {

class Budget {
 public:
  explicit Budget(std::uint64_t max) : max_(max) {}
  // The most steps a check may take.
  std::uint64_t limit() const { return max_; }
  void step() {
    if (++used_ > max_)
      throw Error(ErrorKind::Limit, "error: more than " + std::to_string(max_) +
                                        " matching steps\n  hint: raise CheckOptions::max_steps (check --max-steps), "
                                        "or check a smaller example");
    // Matching recurses once per split part and per nested operation, and
    // every step passes here: stop while the stack still has room
    // (base/stack_guard.hpp) rather than crash on a split of 20000 parts.
    if (stack_.exhausted())
      throw Error(ErrorKind::Limit, "error: matching nests deeper than this thread's " + stack_.size_text() +
                                        " stack holds\n  hint: check a smaller example (fewer parts side by side), "
                                        "or raise the stack limit (ulimit -s)");
  }

 private:
  std::uint64_t max_;
  std::uint64_t used_ = 0;
  const StackGuard& stack_ = StackGuard::for_this_thread();
};

}  // namespace vern::check_detail
