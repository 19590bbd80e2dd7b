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

// The first position of each cluster of `sorted` (ascending; NaN-free),
// in order; the first is 0 (empty input: none). O(n) where every run of
// neighbours within the tolerance spans at most the tolerance (the usual
// case), O(n log n) at worst.
std::vector<std::uint32_t> cluster_starts(std::span<const double> sorted, double tolerance);

}  // namespace vern
