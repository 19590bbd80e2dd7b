// Rows whose tiles follow a progression (issue 15): houses stepping down a
// slope, each 0.85 as high as the one before. Merging sees equal tiles
// holding different houses and writes a repeat of a choice among the
// heights seen, in any order; the style's order is lost.
//
// Found on the written grammar, from the derivations that reproduce the
// examples (CheckResult::steps): a repeat whose tile is a choice among
// calls of one rule T(v) with drawn values (and tiles that are T's body
// at some v, where parts of it vanish: the highest house, with no air
// above it), whose tiles, in every run of every example, take values
// v0, v0 r, v0 r^2, ... (or v0, v0 + d, ...) with one v0 and one r, and
// whose tiles have one length t in every run. Such a repeat becomes
//   row(s1) --> split(axis){ t : T(s1) | ~1 : row(r * s1) }
// called as row(v0): each tile the next step, and the row ends where the
// plot does (a part of no length is not derived). The change is kept
// only if every example still derives.
#pragma once

#include <cstddef>
#include <vector>

#include "graph/grammar.hpp"
#include "inverse/check/derives_examples.hpp"
#include "inverse/load/example.hpp"

namespace vern {

// Rewrites g in place; returns how many repeats became progressions.
std::size_t fold_progressions(Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options);

}  // namespace vern
