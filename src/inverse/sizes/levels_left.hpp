// Sizes of a recursion that follow the levels still to come (issue 23,
// item 6). A pagoda of set-in tiers gives each tier's drum one part in n
// of what is left, n the tiers still to come:
//     tier(n) : n > 1 --> split(z){ ~1 : drum | ~(n - 1) : inset(tier(n - 1)) }
// Merged, the tiers of all examples show one drum share per count left
// (a half, a third, a quarter...), and a recursion that draws the share
// at each level anew puts a tier's drum where no tier count would: the
// buildings it derives are no pagoda. Written with the count, each
// level's sizes are the examples' own.
//
// self_nesting.hpp reads a recursion's levels; here, from the sizes each
// level of the context F took at each count n of levels left (n = 1 for
// the innermost F), each part's size as a function of n: a length in
// metres on a straight line in n, or relative weights whose ratio to one
// of them is a straight line in n (`~1 : ~(n - 1)`): from three counts,
// or from two where the ratio is a whole number at both.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "graph/node.hpp"

namespace vern {

// One part of one level of F, over every chain: the (n, size) of each
// level whose size is one number, and whether some level's is a range
// (merged from examples that differ there).
struct LevelPart {
  bool relative = false;
  bool ranged = false;
  std::vector<std::pair<int, double>> seen;
};

// Per level of F, per part: its size in n (parameter 0) where it follows
// n, nullopt where it keeps the size it has. None when no part follows n,
// or one that varies with n follows no line; a line needs three counts.
std::optional<std::vector<std::vector<std::optional<Size>>>> sizes_by_levels_left(
    const std::vector<std::vector<LevelPart>>& levels, double tolerance);

}  // namespace vern
