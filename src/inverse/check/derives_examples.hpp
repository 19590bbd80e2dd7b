// Does a grammar still derive every example? The guard of every inference
// step that rewrites a written grammar (joint_sizes, overflow_splits): a
// step is kept only where it is.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "graph/grammar.hpp"
#include "inverse/check/check.hpp"
#include "inverse/load/example.hpp"

namespace vern {

// Checks each example (at its own origin, on its own extent) on `threads`
// threads (0: one per core); results gets each example's result, an
// example that needs more steps than the check allows counting as not
// derivable. True when every example is derivable.
bool derives_examples(const Grammar& g, const std::vector<Example>& placed, const CheckOptions& check, unsigned threads,
                      std::vector<CheckResult>& results);

// How a step that rewrites a written grammar checks it.
struct RewriteCheck {
  double tolerance = 1e-6;  // metres, as check uses it
  unsigned threads = 0;     // 0: one per core
};

// The same for examples as infer was given (placed here), without the
// witness's text.
bool derives_examples(const Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options,
                      std::vector<CheckResult>& results);

// The examples' witnesses under a grammar as it is now, handed from one
// step that rewrites a written grammar to the next: each reads them
// (which alternative, which runs each example takes) and, where it
// changes the grammar, checks it again and leaves the new ones, so that
// steps in a row check the examples once between them.
struct Witnesses {
  bool known = false;      // results are the grammar's as it is now
  bool derivable = false;  // every example derives
  std::vector<CheckResult> results;
};

// Checks the examples against g where w is not known yet; returns whether
// every example derives.
bool witnesses_of(const Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options, Witnesses& w);

// An example a grammar does not derive, and why (CheckResult::mismatch).
struct NotDerived {
  std::size_t example = 0;  // its index
  std::string why;
};

// What `check` says of each example with default options (or the given
// tolerance, when > 0): each at its own origin, on its own extent, within
// its own example_tolerance. Nothing when every example is derivable, else
// the first one (in the examples' order) that is not. Throws vern::Error
// (Limit), naming the example, where checking one reaches a limit (steps,
// the stack): whether it is derivable is then not known.
std::optional<NotDerived> first_not_derived(const Grammar& g, const std::vector<Example>& examples, double tolerance,
                                            unsigned threads);

}  // namespace vern
