// Sizes that vary, in the unit they keep (issue 15): once merging has
// settled the structure, each split built from several of the examples'
// splits plans its sizes from their lengths (plan_drawn_sizes,
// size_plan.hpp): a part whose length spreads less than its share of the
// split is drawn in metres (a courtyard's ranges 5 to 8 m deep on plots of
// 24 to 44 m, not a share that grows with the plot), and relative parts
// that keep one ratio beside such a part keep it as fixed weights (a
// half's wall and roof under air of any height).
//
// Decided after unification, not while it runs: a part turned absolute
// changes a split's form, and splits of other forms never unify (towers
// of every tier count would no longer become one recursion).
#pragma once

#include "graph/grammar.hpp"
#include "inverse/merge/sample_book.hpp"

namespace vern {

// Rewrites the splits below root that `rows` knows and whose plan changes
// a size; the drawn sizes' values go into book, for fitting. Returns the
// new root. Nodes above a rewritten split are rebuilt: each (old, new)
// pair is appended to `rebuilt` when given, so that what else is noted
// of the old node (a repeat's tile counts) can go with it.
NodeId draw_sizes(Grammar& g, NodeId root, const RowBook& rows, SampleBook& book, double tolerance,
                  std::vector<std::pair<NodeId, NodeId>>* rebuilt = nullptr);

}  // namespace vern
