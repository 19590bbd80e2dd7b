// Running out of memory, said where: the input being worked on.
//
// std::bad_alloc says nothing of what was being done, so a command's last
// resort (apps/support/guarded_main) can only say "out of memory". Work on
// one input runs through here instead, and the message names that input.
#pragma once

#include <new>
#include <string>

#include "base/error.hpp"

namespace vern {

// Returns work(); running out of memory in it throws vern::Error (Limit)
// "where: error: out of memory <doing>" with the hint. Building the message
// may run out of memory too: then the std::bad_alloc goes on as before.
template <class Work>
auto naming_out_of_memory(const std::string& where, const std::string& doing, const std::string& hint, Work&& work)
    -> decltype(work()) {
  try {
    return work();
  } catch (const std::bad_alloc&) {
    fail(ErrorKind::Limit, where, {}, "out of memory " + doing, hint);
  }
}

}  // namespace vern
