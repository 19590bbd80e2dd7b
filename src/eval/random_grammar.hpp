// Random grammars: synthetic workloads for the benchmarks (issue 5) and a
// sweep of styles no one wrote for evaluating inference (issue 15). Seeded:
// the same options give the same text, byte for byte, on every machine
// (the draws come from the project's own RandomStream).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace vern {

// The labels workloads use, as building parts are named.
inline constexpr std::array<const char*, 8> kWorkloadLabels = {"wall",    "window",  "door",   "floor",
                                                               "roof",    "balcony", "pillar", "glass"};

// A grammar of `rules` rules that derives without errors: rule i calls only
// rules after it, and every rule but the start is called once, so a
// derivation makes a number of terminals proportional to the rule count.
// Bodies mix split (relative, absolute and random sizes), repeat, repeatN,
// nil and primitives; about one label in eight has two alternatives.
struct GrammarOptions {
  std::size_t rules = 100;  // >= 1
  int branching = 4;        // parts per split at most (>= 2)
  std::uint64_t seed = 1;
  // @scope draws each plot size within 30 % of 40 x 30 x 60 m (for
  // evaluating inference on plots of many sizes), instead of exactly that.
  bool varied_plots = false;
};
// Throws vern::Error (Usage) for options out of range.
std::string random_grammar(const GrammarOptions& options);

}  // namespace vern
