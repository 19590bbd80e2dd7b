// Checking: does a grammar derive an example exactly, and how?
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vernacular/grammar.hpp"
#include "vernacular/io.hpp"

namespace vernacular {

struct CheckOptions {
  // The plot to derive on, its lowest corner at the example's (a grammar's
  // plot may be larger than what it built); absent: the example's extent.
  std::optional<Vec3> plot;
  // The example's noise level in metres (0: its own float precision): its
  // coordinates are snapped to it, as infer snaps them.
  double tolerance = 0;
  std::uint64_t max_steps = 10'000'000;  // matching steps before giving up (Limit)
  // Labels bottom to top, as infer's InferOptions::stack: overlapping
  // parts each keep what is visible of them.
  std::vector<std::string> stack;
};

struct Verdict {
  bool derivable = false;
  // Derivable: the choices and values that reproduce the example, one a
  // line, in derivation order ("plot: alternative 2 of 2 (split(x) at 24:10)").
  std::vector<std::string> witness;
  // Not derivable: where the attempt that got furthest (the most boxes in
  // parts it had finished, then the deepest) failed, and why.
  std::string reason;
};

// Whether `grammar`, started on a plot of the example's size with its
// lowest corner at the example's, derives exactly the example's labelled
// parts (the same labels and boxes, within the tolerance). Throws Failure:
// Limit past options.max_steps, Input where the grammar cannot be derived
// at all. An error is never a verdict.
Verdict check(const Grammar& grammar, const Example& example, const CheckOptions& options = {});

}  // namespace vernacular
