// Independent work items on several threads, with errors that do not
// depend on timing: what deriving variants, loading examples and splitting
// them share.
#pragma once

#include <cstddef>
#include <functional>

namespace vern {

// Runs task(i) for every i in [0, count) on `threads` threads (0: one per
// core; never more than count), each index once, claimed in increasing
// order. After a task throws, no new index is claimed; once every thread
// has stopped, the exception of the lowest failing index is rethrown, so
// the error a user sees is the same whatever the thread count. progress,
// if given, is called with the number of items done so far, one call at a
// time.
void parallel_for(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& task,
                  const std::function<void(std::size_t)>& progress = {});

}  // namespace vern
