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

// Calls visit(id) once for each node reachable from root (not into the
// bodies of rules it calls), depth first, going on below a node only
// where visit returns true: for passes that stop at some kinds of node.
template <class F>
void walk_below(const Grammar& g, NodeId root, F visit) {
  std::vector<bool> seen(g.node_count(), false);
  std::vector<NodeId> stack{root};
  while (!stack.empty()) {
    const NodeId id = stack.back();
    stack.pop_back();
    if (seen[id]) continue;
    seen[id] = true;
    if (visit(id)) for_each_child(g.op(id), [&](NodeId c) { stack.push_back(c); });
  }
}

}  // namespace vern
