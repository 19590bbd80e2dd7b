#include "inverse/merge/substitute.hpp"

namespace vern {

namespace {

class Substitution {
 public:
  Substitution(Grammar& g, const std::vector<NodeId>& replace, std::vector<std::pair<NodeId, NodeId>>* log)
      : g_(g), replace_(replace), log_(log), rebuilt_(g.node_count(), kNoReplacement) {}

  // Post-order on a stack of its own, children left to right: the order
  // the nodes are interned in is the order a recursion would take, but a
  // graph thousands of nodes deep (378 CMP facades at --tolerance 0.045)
  // cannot run the thread's stack out.
  NodeId run(NodeId root) {
    std::vector<NodeId> unsettled{root};
    std::vector<NodeId> pending;
    while (!unsettled.empty()) {
      const NodeId id = unsettled.back();
      if (done(id)) {
        unsettled.pop_back();
        continue;
      }
      pending.clear();
      map_children(g_.op(id), [&](NodeId c) {
        if (!done(c)) pending.push_back(c);
        return c;
      });
      if (!pending.empty()) {
        unsettled.insert(unsettled.end(), pending.rbegin(), pending.rend());
        continue;
      }
      unsettled.pop_back();
      // Every child is settled: rebuild this node if one of them changed.
      const auto [children, changed] = map_children(g_.op(id), [&](NodeId c) { return result(c); });
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
    }
    return result(root);
  }

 private:
  bool done(NodeId id) const {
    return (id < replace_.size() && replace_[id] != kNoReplacement) ||
           (id < rebuilt_.size() && rebuilt_[id] != kNoReplacement);
  }
  // What a settled node became.
  NodeId result(NodeId id) const {
    if (id < replace_.size() && replace_[id] != kNoReplacement) return replace_[id];
    return rebuilt_[id];
  }

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
