#include "inverse/write/unused_rules.hpp"

#include <algorithm>
#include <functional>
#include <unordered_map>
#include <unordered_set>

namespace vern {

void drop_unused_rules(Grammar& g) {
  std::vector<bool> used(g.rules.size(), false);
  std::vector<RuleId> stack{g.start_rule};
  used[g.start_rule] = true;
  std::unordered_set<NodeId> seen;
  while (!stack.empty()) {
    const RuleId r = stack.back();
    stack.pop_back();
    std::vector<NodeId> nodes{g.rules[r].body};
    while (!nodes.empty()) {
      const NodeId id = nodes.back();
      nodes.pop_back();
      if (!seen.insert(id).second) continue;
      if (const auto* c = std::get_if<Call>(&g.op(id)); c && !used[c->rule]) {
        used[c->rule] = true;
        stack.push_back(c->rule);
      }
      for_each_child(g.op(id), [&](NodeId child) { nodes.push_back(child); });
    }
  }
  if (std::ranges::all_of(used, [](bool u) { return u; })) return;
  // A fresh grammar of what is still used: derive() compiles every node
  // it holds, and the dropped rules' calls would name rules gone.
  std::vector<RuleId> index(g.rules.size(), 0);
  RuleId next = 0;
  for (RuleId r = 0; r < g.rules.size(); ++r)
    if (used[r]) index[r] = next++;
  Grammar out;
  out.source_name = g.source_name;
  out.start_rule = index[g.start_rule];
  out.start_written = g.start_written;
  out.scope = g.scope;
  out.primitives = g.primitives;
  out.constants = g.constants;
  for (const std::string& label : g.labels()) out.label_id(label);  // the same ids
  std::unordered_map<NodeId, NodeId> copied;
  std::function<NodeId(NodeId)> copy = [&](NodeId id) {
    if (const auto it = copied.find(id); it != copied.end()) return it->second;
    Operation op = g.op(id);
    for (NodeId* child : child_slots(op)) *child = copy(*child);
    if (auto* c = std::get_if<Call>(&op)) c->rule = index[c->rule];
    const NodeId now = out.intern({std::move(op), g.node(id).loc});
    copied.emplace(id, now);
    return now;
  };
  for (RuleId r = 0; r < g.rules.size(); ++r) {
    if (!used[r]) continue;
    Rule rule = g.rules[r];
    rule.body = copy(rule.body);
    out.rules.push_back(std::move(rule));
  }
  g = std::move(out);
}


}  // namespace vern
