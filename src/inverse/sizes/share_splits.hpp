// A split whose relative parts all draw varies in fewer ways than it
// draws: `~rand(2.5, 3.4) : I(rect) | ~rand(5.6, 6.4) : nil` varies in its
// ratio only, a tier's `~rand : nil | ~rand : tier | ~rand : nil` in its
// (equal) insets only. Where the shares the examples show vary in one way
// (each a constant or a straight-line function of the first that varies,
// within the tolerance), the split becomes one draw and the rest:
// `rectZ(s1) --> split(z){ ~s1 : I(rect) | ~(9 - s1) : nil }`,
// `rectX(s1) --> split(x){ ~s1 : nil | ~(4.7 - 2 * s1) : ... | ~s1 : nil }`,
// s1 drawn by its callers from the distribution the first share fits best
// (all the split's runs, in every example; joint_sizes.hpp says where the
// lengths come from). A split that is a rule's body (not the start's)
// gives that rule the parameter; any other runs as a new rule named after
// its primitives. Shares that vary in two ways are left as they are:
// check() pins down one parameter per split. A split whose drawn shares
// stand beside shares written as numbers is read in the scale of those
// numbers, and keeps them: a bay's two piers that every bay shows equal,
// `~rand(0.8, 1.5) : pier | ~1 : window | ~rand(0.8, 1.5) : pier`, become
// `~s1 : pier | ~1 : window | ~s1 : pier` (a row's tiles are its runs).
// A split whose relative parts do not draw, and two or more of whose
// lengths in metres do, is read the same way in metres: a window pair
// seen in one proportion, `s1 : casement | 0.4 * s1 : mullion | s1 : ...`.
// Where that leaves no share in the split and every line is a multiple
// of s1, the parts always fill the split, so s1 is its length's: they
// become shares that draw nothing (`~1 : nil | ~8 : tier | ~1 : nil`, a
// tier set in by a tenth on each side).
#pragma once

#include <cstddef>
#include <vector>

#include "graph/grammar.hpp"
#include "inverse/check/check.hpp"

namespace vern {

struct ShareOptions {
  double tolerance = 1e-6;             // metres
  bool uniform_distributions = false;  // shares as rand(min, max)
  unsigned threads = 1;                // reading runs and fitting shares (0: all cores)
};

// results: each example checked against g (CheckResult::parts). Returns
// how many splits changed; rules it leaves uncalled stay (unused_rules.hpp).
std::size_t share_splits(Grammar& g, const std::vector<CheckResult>& results, const ShareOptions& options);

}  // namespace vern
