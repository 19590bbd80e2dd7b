// Coordinates that measure one place: clusters of sorted numbers, none
// spanning more than a tolerance.
//
// A box split (box_split.hpp) gives coordinates within the tolerance of
// each other one rank, so that export noise neither blocks a cut nor makes
// a sliver. Joining every pair of neighbours within the tolerance would
// chain: three windows 0.04 m apart at a tolerance of 0.05 m would become
// one coordinate though the outer two lie 0.08 m apart, and a layout whose
// distinct coordinates lie a fraction of the tolerance apart would collapse
// into a handful of ranks, its parts all overlapping. So neighbours are
// joined closest first (ties left to right), and a join that would make a
// cluster span more than the tolerance is not made: a cluster never spans
// more than the tolerance, and equal coordinates are always one.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace vern {

// Appends to `starts` the first position (offset by `from`) of every
// cluster of `chain` but its first: a run of sorted values, each within
// the tolerance of the next, spanning more than it.
void split_chain(std::span<const double> chain, std::uint32_t from, double tolerance,
                 std::vector<std::uint32_t>& starts);

// The first position of each cluster of the n values value(0) <= value(1)
// <= ... (NaN-free), in order; the first is 0 (n = 0: none). One pass
// where every run of neighbours within the tolerance spans at most the
// tolerance (the usual case); a longer run is copied and split, O(k log k).
template <typename Value>
std::vector<std::uint32_t> cluster_starts(std::uint32_t n, Value value, double tolerance) {
  std::vector<std::uint32_t> starts;
  std::uint32_t chain = 0;  // first position of the current run of near neighbours
  double first = 0, previous = 0;
  for (std::uint32_t i = 0; i <= n; ++i) {
    const double v = i < n ? value(i) : 0.0;
    if (i < n && i > 0 && v - previous <= tolerance) {
      previous = v;
      continue;
    }
    // [chain, i) is a run of neighbours within the tolerance.
    if (i > 0 && previous - first > tolerance) {
      std::vector<double> run(i - chain);
      for (std::uint32_t k = chain; k < i; ++k) run[k - chain] = value(k);
      split_chain(run, chain, tolerance, starts);
    }
    if (i < n) starts.push_back(i);
    chain = i;
    first = previous = v;
  }
  return starts;
}

inline std::vector<std::uint32_t> cluster_starts(std::span<const double> sorted, double tolerance) {
  return cluster_starts(static_cast<std::uint32_t>(sorted.size()), [&](std::uint32_t i) { return sorted[i]; },
                        tolerance);
}

}  // namespace vern
