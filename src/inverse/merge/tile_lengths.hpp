// Repeats whose tiles differ in length by a wide gap are different kinds
// of repeat, though alike in structure: a block's strips of buildings and
// a tower cluster's strips a third as wide. Ranging one tile size over
// both would give blocks of a dozen slivers and clusters of two towers.
// The kinds: per axis, the repeats' tile lengths (ranges, once merged) in
// order, a new kind wherever the next length is more than kLengthGap
// times the longest so far. Merging's unification keeps kinds apart.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "graph/grammar.hpp"

namespace vern {

class TileLengths {
 public:
  static constexpr double kLengthGap = 1.25;

  TileLengths() = default;
  // The kinds among the repeats below root.
  TileLengths(const Grammar& g, NodeId root);

  // The repeat's kind: 1 + the index of its length's kind on its axis
  // (0 for a repeat without a literal axis and length).
  std::size_t kind(const Repeat& r) const;

 private:
  std::array<std::vector<double>, 3> starts_;  // per axis: each kind's shortest length, ascending
};

}  // namespace vern
