// Two independent pieces of work at once, with errors that do not depend
// on timing: inference orients parts while it splits, and infer derives its
// test building while it writes the grammar.
#pragma once

#include <functional>

namespace vern {

// Runs `side` on a thread of its own while `main` runs on this one, and
// returns when both are done; with threads == 1 runs side, then main, here.
// main stays on the calling thread so that what it allocates comes from
// (and returns to) the caller's memory, as it would without the second
// thread. If either throws, side's exception is rethrown first: the same
// error as one thread gives.
void run_alongside(unsigned threads, const std::function<void()>& side, const std::function<void()>& main);

}  // namespace vern
