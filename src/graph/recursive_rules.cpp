#include "graph/recursive_rules.hpp"

#include <unordered_set>

namespace vern {

std::vector<bool> recursive_rules(const Grammar& g) {
  const std::size_t n = g.rules.size();
  std::vector<std::vector<RuleId>> calls(n);
  for (RuleId r = 0; r < n; ++r) {
    std::vector<NodeId> stack{g.rules[r].body};
    std::unordered_set<NodeId> seen;
    while (!stack.empty()) {
      const NodeId id = stack.back();
      stack.pop_back();
      if (!seen.insert(id).second) continue;
      if (const auto* c = std::get_if<Call>(&g.op(id))) calls[r].push_back(c->rule);
      for_each_child(g.op(id), [&](NodeId child) { stack.push_back(child); });
    }
  }
  std::vector<bool> out(n, false);
  for (RuleId r = 0; r < n; ++r) {
    std::vector<RuleId> stack(calls[r].begin(), calls[r].end());
    std::vector<bool> seen(n, false);
    while (!stack.empty() && !out[r]) {
      const RuleId c = stack.back();
      stack.pop_back();
      if (c == r) out[r] = true;
      if (c >= n || seen[c]) continue;
      seen[c] = true;
      stack.insert(stack.end(), calls[c].begin(), calls[c].end());
    }
  }
  return out;
}

}  // namespace vern
