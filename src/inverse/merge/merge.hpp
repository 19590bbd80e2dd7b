// Merging the operation graphs of several examples into one (thesis,
// chapter 10), so that the result derives every example and new buildings
// made of their parts.
//
// The examples' graphs live in one Grammar, interned, so identical parts
// are already one node (10.2). merge_examples
//   1. puts the examples under one choose, one option each (10.1);
//   2. unifies nodes of equal structure anywhere in the graph (the same
//      operation, axis, relative flags, counts and children, whatever the
//      sizes) into one node whose sizes are ranges over them (10.3), bottom
//      up, so parents whose children coincide unify in turn; chooses over
//      the same alternatives are one, their weights added;
//   3. makes places that combine freely choices (generalise.hpp), which
//      unifies more; 2 and 3 repeat until nothing changes;
//   4. writes each varying size as the distribution its values fit best
//      (fit_distribution.hpp): the values each range stands for are kept
//      through steps 2 and 3, counted once per time an example uses them;
//   5. adds the priorities of alternatives that became one (10.4), turns
//      runs of equal parts into repeats and flattens nested splits.
//
// Before all this, each example's runs of equal parts and repeating
// patterns that fill (almost) a whole split become stretching repeats
// (repeat_folding.hpp), so rows of 3, 4 and 6 windows have one structure.
// When unified splits span different lengths, parts of one length in all
// of them become absolute sizes and the others share the rest
// (size_plan.hpp): a wider plot keeps its 0.6 m walls.
//
// Steps 2 and 3 need two examples or more: one example is reproduced
// exactly as it is, since ranges should come from variation across
// examples, never from one building's own parts (which only parameters
// could share exactly). Every example stays derivable: each of its sizes
// lies in its range and each of its parts was replaced by a node that
// covers it. Unifying equal structures everywhere is the thesis's rule; it
// also joins parts that only look alike (its balcony bars), which keeping
// parts apart must refine.
#pragma once

#include <vector>

#include "graph/grammar.hpp"
#include "inverse/merge/sample_book.hpp"

namespace vern {

struct MergeOptions {
  // Sizes that differ by at most this (metres, or relative units, which
  // inference writes as metres) are the same size.
  double tolerance = 1e-9;
  // Varying sizes as the thesis wrote them, rand(min, max), instead of the
  // distribution the values fit best (fit_distribution.hpp).
  bool uniform_distributions = false;
  // Sizes the examples vary drawn in metres where their lengths say so
  // (drawn_sizes.hpp). Their plan reads the lengths noted for each split;
  // a split that free combinations (generalise.hpp) also let an example
  // reach through another choice's alternative never noted that
  // example's lengths, and its sizes in metres may then not fit it
  // where shares did. infer merges once more without them when its
  // check finds an example underived. Without them, alternatives seen at
  // different lengths keep their shares too (alternative_lengths.hpp): a
  // bay whose parts keep one proportion is one node at every width it
  // was seen at, which that step cannot tell from a bay seen at one.
  bool draw_sizes = true;
  // Equal tiles of unlike contents (repeat_folding.hpp's UnlikeTiles::Fold)
  // folded from two examples on. infer's last attempt leaves them out
  // where every other attempt's grammar missed an example: each row then
  // keeps its own tiles, as one example alone does.
  bool fold_unlike = true;
  // The nodes of placed groups (split_graph.hpp): parts no straight cut
  // separates, placed with S(...) that reaches into the next piece. check
  // can follow such a group only by deriving it, which needs one outcome:
  // neither a group nor anything below it is unified with other nodes or
  // joined into choices, so each is copied as it is, never varied.
  std::vector<NodeId> placed;
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

// One example's split, never unified (`rows` knows the splits that were):
// its sizes are that example's lengths, and which of them are relative
// says nothing yet.
bool lone_split(const Grammar& g, NodeId id, const RowBook& rows);

}  // namespace vern
