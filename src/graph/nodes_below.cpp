#include "graph/nodes_below.hpp"

#include <algorithm>

namespace vern {

std::vector<NodeId> nodes_below(const Grammar& g, NodeId root) {
  std::vector<bool> visited(g.node_count(), false);
  std::vector<NodeId> stack{root}, out;
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

}  // namespace vern
