// Merging the operation graphs of several examples into one (thesis,
// chapter 10), so that the result derives every example and new buildings
// made of their parts.
//
// The examples' graphs live in one Grammar, interned, so identical parts
// are already one node (10.2). merge_examples groups the roots by shape
// (the same operations, axes, labels and structure, whatever the numbers),
// merges each group into one graph whose sizes become ranges over the group
// (10.3), and puts the groups under one choose weighted by how many
// examples each holds (10.1, 10.4). Then it simplifies: runs of equal parts
// become repeats and identical alternatives add their priorities.
//
// Every example stays derivable: each of its sizes lies in its range.
// Groups of different shape stay separate alternatives; merging parts of
// different shape (generalising further) is left to later stages.
#pragma once

#include <vector>

#include "graph/grammar.hpp"

namespace vern {

struct MergeOptions {
  // Sizes that differ by at most this (metres, or relative units, which
  // inference writes as metres) are the same size.
  double tolerance = 1e-9;
};

// Returns the merged root; adds nodes to g (interned). roots must not be
// empty. Each root counts as one example.
NodeId merge_examples(Grammar& g, const std::vector<NodeId>& roots, const MergeOptions& options);

// The closed range a size expression covers, if it is a literal or
// rand(lo, hi) of literals: what merging widens.
struct Range {
  double lo = 0, hi = 0;
};
std::optional<Range> literal_range(const Expr& e);

// A literal for a range narrower than tolerance, else rand(lo, hi).
Expr range_expr(Range r, double tolerance);

}  // namespace vern
