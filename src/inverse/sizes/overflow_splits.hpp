// A split and its overflow are one split (issue 15). docs/grammar.md (split): where the
// absolute parts of a split alone exceed its scope, they shrink in
// proportion and the relative parts get nothing. So a storey
// `split(z){ 0.9 : I(rect) | 1.5 : I(window) | ~1 : I(rect) }` in a repeat
// that makes storeys of 2 to 3 m is seen, in the examples whose storeys
// are under 2.4 m, as `split(z){ ~3 : I(rect) | ~5 : I(window) }`: another
// structure, which merging keeps as another alternative, drawn by weight
// whatever the storey's height (a 3 m storey with a window of 1.9 m, which
// the style never makes).
//
// A split S of relative literal sizes is taken for T's where T has
// absolute literal sizes and relative ones, and S holds, in order, either
// exactly T's absolute parts (T overflowing) or all of T's parts (a
// member merging kept apart by its sizes), the parts at T's absolute
// places in T's absolute ratios. Every such S is replaced by its T, and
// alternatives that so become alike are one. The whole change is kept
// only if every example still derives.
#pragma once

#include <cstddef>
#include <vector>

#include "graph/grammar.hpp"
#include "inverse/check/derives_examples.hpp"
#include "inverse/load/example.hpp"

namespace vern {

// Rewrites g in place; returns how many splits were replaced (0: g as it
// was). examples: as given to infer.
std::size_t unify_overflows(Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options);

}  // namespace vern
