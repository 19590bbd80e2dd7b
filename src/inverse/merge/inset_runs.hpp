// Tiers set in by a margin, read as the nesting they are (issue 23, item
// 6). A pagoda of drums each set in 0.7 m from the one below is, in an
// example, one stack along z whose k-th level is set in by k times 0.7 m:
//
//   split(z){ drum | inset(0.7){ drum } | inset(1.4){ drum } | inset(2.1){ roof } }
//
// where inset(m){ X } is empty space of m on both ends of one or two other
// axes around X (split(x){ m : nil | ~ : split(y){ m : nil | X | m : nil } | m : nil }).
// Insets along other axes commute with a split along z, and an inset of
// k times m is k insets of m, so the stack is
//
//   split(z){ drum | inset(0.7){ split(z){ drum | inset(0.7){ split(z){ drum | inset(0.7){ roof } } } } } }
//
// the nesting that self_nesting.hpp folds into a recursion with a count.
// Done on each example's graph before merging; the geometry is unchanged.
//
// A run is two or more consecutive parts whose children are insets with
// margins k, k + 1, ... times one step on every side (each side its own
// step), the first at once the step; each is rewritten nested, from the
// last level up.
#pragma once

#include <vector>

#include "graph/grammar.hpp"

namespace vern {

// The graph below root with such runs nested; tolerance: margins that
// agree within it are one. Nodes `kept` marks (by id; placed groups) are
// left as they are, and all below them.
NodeId nest_inset_runs(Grammar& g, NodeId root, double tolerance, const std::vector<bool>* kept = nullptr);

}  // namespace vern
