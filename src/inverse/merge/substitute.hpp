// Rebuilding a graph with some of its nodes replaced: what every merging
// step that decides "these nodes become that one" needs after deciding.
#pragma once

#include <utility>
#include <vector>

#include "graph/grammar.hpp"

namespace vern {

// Node ids that stand for no replacement in a replacement table.
inline constexpr NodeId kNoReplacement = static_cast<NodeId>(-1);

// The graph below root with every node n for which replace[n] is not
// kNoReplacement replaced by replace[n] (replace is indexed by node id and
// may be shorter than the grammar: ids past its end are kept). Nodes whose
// children change are interned anew, keeping their source location;
// nothing else is copied. Memoised: a DAG is rebuilt in one pass.
// rebuilt, where given, gets each node rebuilt so (old id, new id): its
// sizes are the old node's, so notes kept about them carry over.
NodeId substitute(Grammar& g, NodeId root, const std::vector<NodeId>& replace,
                  std::vector<std::pair<NodeId, NodeId>>* rebuilt = nullptr);

// substitute, pass after pass until the graph stops changing: a pass does
// not look into a replacement, so where replacements hold nodes that are
// replaced in turn (a rebuilt choice holding another), the next pass
// reaches them. rebuilt as for substitute, over all passes.
NodeId substitute_until_settled(Grammar& g, NodeId root, const std::vector<NodeId>& replace,
                                std::vector<std::pair<NodeId, NodeId>>* rebuilt = nullptr);

}  // namespace vern
