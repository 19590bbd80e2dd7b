// The nodes a graph reaches from a root, for passes that look at some
// kind of node wherever it stands (every choice, say) before rewriting.
#pragma once

#include <vector>

#include "graph/grammar.hpp"

namespace vern {

// Every node reachable from root through children (not into the bodies of
// rules it calls), root included, each once, in ascending id order: the
// same list, so the same rewrite, whatever the graph's layout.
std::vector<NodeId> nodes_below(const Grammar& g, NodeId root);

// The same from every rule's body: all the nodes a grammar's rules hold.
std::vector<NodeId> nodes_of_rules(const Grammar& g);

}  // namespace vern
