// Structures that nest themselves become recursion (issue 4, item 6).
//
// A tiered tower is a storey with a smaller tiered tower on it: each tier
// is split(z){ storey | inset(the rest) }, the rest one tier less. Box
// splitting gives each example's towers as such nests (box_split.cpp,
// narrowing stacks), and merging gives one node per depth: the towers of
// three, four and seven tiers are different alternatives, each spelling
// out its tiers. Here a chain of one context F repeated, F[F[...F[B]]],
// is found along a node's spine (its one child that is a split, followed
// down), and every chain of the same F and innermost piece B, seen nested
// twice over somewhere, becomes one recursive rule with a counter
//     nest(n) : n <= 0 --> B
//     nest(n) : n > 0 --> F[nest(n - 1)]
// called nest(k), k drawn from the chain lengths seen (a pagoda of three
// to six tiers has three to six, where stopping at each level with the
// odds seen gave towers of one tier and of ten), with F's sizes in n
// where they follow the levels left (levels_left.hpp), else ranging over
// every level of every chain. Every example stays derivable: each of its
// chains is F applied k times to B, each level's sizes in F's ranges.
// Where one node is seen at two counts (a chain inside another at another
// depth), the rule stops and goes on with the odds seen instead:
//     nest --> B | F[nest]
#pragma once

#include <utility>
#include <vector>

#include "graph/grammar.hpp"
#include "inverse/merge/sample_book.hpp"

namespace vern {

struct SelfNesting {
  NodeId root = 0;
  std::size_t rules = 0;  // recursive rules added to the grammar's rules
  std::vector<std::pair<NodeId, NodeId>> rebuilt;  // nodes above a chain, rebuilt (substitute)
};

// Adds each recursive rule to g.rules (its body a choose; the graph calls
// it with Call nodes) and books the values behind F's ranges in book.
// `rows` tells the splits unified from examples (merge.cpp): one that is
// not, all of whose sizes are one example's lengths, has relative flags
// that say nothing yet (every part a weight in metres), and is read as a
// level of any context it fits but for them: the tallest tower, seen
// once, has a top tier no other example shares.
SelfNesting fold_self_nesting(Grammar& g, NodeId root, SampleBook& book, double tolerance, const RowBook& rows);

}  // namespace vern
