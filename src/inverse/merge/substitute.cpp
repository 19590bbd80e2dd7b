#include "inverse/merge/substitute.hpp"

namespace vern {

namespace {

class Substitution {
 public:
  Substitution(Grammar& g, const std::vector<NodeId>& replace, std::vector<std::pair<NodeId, NodeId>>* log)
      : g_(g), replace_(replace), log_(log), rebuilt_(g.node_count(), kNoReplacement) {}

  NodeId run(NodeId id) {
    if (id < replace_.size() && replace_[id] != kNoReplacement) return replace_[id];
    if (id < rebuilt_.size() && rebuilt_[id] != kNoReplacement) return rebuilt_[id];
    // Children first, by id: rebuilding them may move the arena.
    const auto [children, changed] = map_children(g_.op(id), [&](NodeId c) { return run(c); });
    NodeId out = id;
    if (changed) {
      Operation op = g_.op(id);
      const std::vector<NodeId*> slots = child_slots(op);
      for (std::size_t i = 0; i < slots.size(); ++i) *slots[i] = children[i];
      out = g_.intern({std::move(op), g_.node(id).loc});
      if (log_ && out != id) log_->emplace_back(id, out);
    }
    if (id >= rebuilt_.size()) rebuilt_.resize(id + 1, kNoReplacement);
    rebuilt_[id] = out;
    return out;
  }

 private:
  Grammar& g_;
  const std::vector<NodeId>& replace_;
  std::vector<std::pair<NodeId, NodeId>>* log_;  // rebuilt nodes, or null
  std::vector<NodeId> rebuilt_;  // by node id: what it became, or kNoReplacement
};

}  // namespace

NodeId substitute(Grammar& g, NodeId root, const std::vector<NodeId>& replace,
                  std::vector<std::pair<NodeId, NodeId>>* rebuilt) {
  return Substitution(g, replace, rebuilt).run(root);
}

NodeId substitute_until_settled(Grammar& g, NodeId root, const std::vector<NodeId>& replace,
                                std::vector<std::pair<NodeId, NodeId>>* rebuilt) {
  for (NodeId previous = kNoReplacement; root != previous;) {
    previous = root;
    root = substitute(g, root, replace, rebuilt);
  }
  return root;
}

}  // namespace vern
