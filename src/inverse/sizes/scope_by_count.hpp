// A plot whose size follows a count the grammar draws (issue 23, item 6).
//
// A pagoda of three to five tiers of 3 m, under its roof, is as tall as
// its tiers make it: modelled, or derived under air that no example shows,
// each example's height is 3 n + 2.5 for its n tiers. Inference writes
// the tiers as a recursion called with the count drawn,
//     building --> tiers(randint(3, 5))
// and the plot's height as a distribution of the heights seen, drawn
// apart from the count: a variant of three tiers on the plot of five
// stretches every tier by two thirds, on a plot given or drawn. Where
// the examples' size along an axis is, example by example, a straight
// line in a value drawn once per building (an argument drawn from a
// finite set by a call the start rule makes, not below a repeat or
// another call, of a rule that recurses: the count it runs down), the
// two are tied:
//   - a whole count on the plot itself (the call reached from the start
//     rule through choices only) is read off whatever plot the grammar
//     is given, and the plot is drawn as the line in the count:
//         @scope rand(14, 20), rand(14, 20), 3 * randint(3, 5) + 2.5
//         building --> tiers(round((size(z) - 2.5) / 3))
//   - otherwise (tiers on a podium: the call stands on a part of the
//     plot; a size rather than a count; several axes following it) the
//     value becomes a constant drawn once, which the plot follows:
//         tiersN = randint(2, 4)
//         @scope 10, 10, 3 * tiersN + 6
// Read from the derivations that reproduce the examples
// (CheckResult::steps: the value each example's call took); a line needs
// three examples, and every example must lie on it within the tolerance
// (two counts seen: one of them twice, at one size). Kept only if every
// example still derives.
#pragma once

#include <cstddef>
#include <vector>

#include "graph/grammar.hpp"
#include "inverse/check/derives_examples.hpp"
#include "inverse/load/example.hpp"

namespace vern {

// Rewrites g in place; returns how many of the plot's axes now follow a
// drawn value.
std::size_t tie_scope_to_counts(Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options);

}  // namespace vern
