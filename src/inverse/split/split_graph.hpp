// From a split tree to an operation graph (thesis chapter 9, toOp).
//
// A Split container becomes split(axis){ ~l1 : ... | ~l2 : ... } with each
// part's length as its relative size, a Leaf becomes I(label), empty space
// nil, and an Unsplittable container (a pinwheel) cuts at its parts' corners
// with S(...) placements (placements.hpp). Nodes are interned bottom-up
// (Grammar::intern), so equal subtrees, within one example or across
// examples built into the same grammar, share one node. The graph uses only
// split, primitive, nil, S and R: it derives the example exactly, and
// deriving it needs no parsing.
//
// Exactness: deriving the graph on a scope at the origin whose size is the
// example's extent (example_size) reproduces every part's box translated by
// -example.min, within the split tolerance.
#pragma once

#include <string>
#include <vector>

#include "graph/grammar.hpp"
#include "inverse/load/example.hpp"
#include "inverse/load/orientation.hpp"
#include "inverse/split/box_split.hpp"

namespace vern {

struct SplitGraphOptions {
  // The tolerance the tree was split with: placed parts' corners this close
  // are one coordinate.
  double tolerance = 0;
  // Where to add one warning per Unsplittable container, naming the
  // example file and its parts (null: not reported).
  std::vector<std::string>* warnings = nullptr;
  // Where to add the node of each placed group (placements.hpp), which
  // merging copies as it is (MergeOptions::placed; null: not listed).
  std::vector<NodeId>* placed = nullptr;
};

// The graph of a split tree over `boxes` (the boxes it was split from).
// `source` names the example file in messages. Throws vern::Error (Input)
// for an Unsplittable container that placements cannot separate either
// (parts sharing their min corner), naming its parts.
// turns: per box, the quarter turns of its mesh (orientation.hpp); a
// turned box becomes R(axis, angle){ I(label) }. Empty: none turned.
NodeId split_graph(Grammar& grammar, const SplitTree& tree, const std::vector<LabelledBox>& boxes,
                   const std::string& source = {}, const std::vector<Orientation>& turns = {},
                   const SplitGraphOptions& options = {});

// split_boxes then split_graph for one loaded example.
NodeId example_graph(Grammar& grammar, const Example& example, const BoxSplitOptions& options,
                     const std::vector<Orientation>& turns = {}, std::vector<std::string>* warnings = nullptr);

}  // namespace vern
