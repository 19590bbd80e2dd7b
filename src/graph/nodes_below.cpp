#include "graph/nodes_below.hpp"

#include <algorithm>

namespace vern {

namespace {

std::vector<NodeId> reachable(const Grammar& g, std::vector<NodeId> stack) {
  std::vector<bool> visited(g.node_count(), false);
  std::vector<NodeId> out;
  while (!stack.empty()) {
    const NodeId id = stack.back();
    stack.pop_back();
    if (visited[id]) continue;
    visited[id] = true;
    out.push_back(id);
    for_each_child(g.op(id), [&](NodeId c) { stack.push_back(c); });
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

std::vector<NodeId> nodes_below(const Grammar& g, NodeId root) { return reachable(g, {root}); }

std::vector<NodeId> nodes_of_rules(const Grammar& g) {
  std::vector<NodeId> bodies;
  for (const Rule& r : g.rules) bodies.push_back(r.body);
  return reachable(g, std::move(bodies));
}

}  // namespace vern
