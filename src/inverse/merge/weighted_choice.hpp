// A choice among what one place held, weighted by how often each was seen.
//
// A child that is itself a plain choice (weights only, no conditions)
// gives its options their share of its weight, so a place that held the
// shop once and "the door or the window" twice is one choice of the shop,
// the door and the window, not a choice of the shop and of a choice: the
// same buildings with the same odds, one rule fewer to read. Children
// held more than once are one option with their weights summed.
#pragma once

#include <utility>
#include <vector>

#include "graph/grammar.hpp"

namespace vern {

// held: each child with its weight (> 0). Returns the child itself where
// only one remains, else the interned choice, options in order of first
// appearance.
NodeId weighted_choice(Grammar& g, const std::vector<std::pair<NodeId, double>>& held);

}  // namespace vern
