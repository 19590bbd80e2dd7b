// Merging's notes on the values behind its ranges.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "graph/node.hpp"
#include "inverse/merge/substitute.hpp"
#include "inverse/sizes/fit_distribution.hpp"

namespace vern {

// The values that merging's ranges stand for: per node built with ranges,
// per split part (a repeat: its tile size), each value with the number of
// times the examples use it. Kept across rounds of unification, keyed by
// the built node, so that a range widened again still knows its values.
// An empty list means unknown: the range joined values that were not kept.
using SampleBook = std::unordered_map<NodeId, std::vector<std::vector<Observation>>>;

// Nodes rebuilt with new children keep their sizes: the values behind
// their ranges carry over from each old node to its new one.
inline void carry_samples(const std::vector<std::pair<NodeId, NodeId>>& rebuilt, SampleBook& book) {
  for (const auto& [old, now] : rebuilt) {
    const auto it = book.find(old);
    if (it == book.end() || book.count(now)) continue;
    std::vector<std::vector<Observation>> copy = it->second;  // a copy: inserting below may move it
    book.emplace(now, std::move(copy));
  }
}

// substitute_until_settled, the nodes rebuilt above a replaced one keeping
// their values (carry_samples); each (old, new) pair is also appended to
// `rebuilt` when given, for whatever else is noted of the old node.
inline NodeId substitute_keeping_samples(Grammar& g, NodeId root, const std::vector<NodeId>& replace, SampleBook& book,
                                         std::vector<std::pair<NodeId, NodeId>>* rebuilt = nullptr) {
  std::vector<std::pair<NodeId, NodeId>> moved;
  root = substitute_until_settled(g, root, replace, &moved);
  carry_samples(moved, book);
  if (rebuilt) rebuilt->insert(rebuilt->end(), moved.begin(), moved.end());
  return root;
}

// The lengths behind a split built from several: one row per split of the
// examples it stands for (its parts' lengths in metres, with the times the
// examples use it), kept across rounds of unification so that sizes can
// be planned from the examples' own lengths however often the split was
// unified again (size_plan.hpp, drawn_sizes.hpp).
struct LengthRow {
  std::vector<double> lengths;
  double weight = 1;
  std::int64_t example = -1;  // the one example it stands for, where it is one (Observation::example)
};
using RowBook = std::unordered_map<NodeId, std::vector<LengthRow>>;

}  // namespace vern
