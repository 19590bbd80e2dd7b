// Merging's notes on the values behind its ranges.
#pragma once

#include <unordered_map>
#include <vector>

#include "graph/node.hpp"
#include "inverse/fit_distribution.hpp"

namespace vern {

// The values that merging's ranges stand for: per node built with ranges,
// per split part (a repeat: its tile size), each value with the number of
// times the examples use it. Kept across rounds of unification, keyed by
// the built node, so that a range widened again still knows its values.
// An empty list means unknown: the range joined values that were not kept.
using SampleBook = std::unordered_map<NodeId, std::vector<std::vector<Observation>>>;

}  // namespace vern
