#include "graph/import.hpp"

#include <unordered_map>

#include "base/overload.hpp"

namespace vern {

namespace {

class Importer {
 public:
  Importer(Grammar& to, const Grammar& from) : to_(to), from_(from) {}

  NodeId copy(NodeId id) {
    if (auto it = done_.find(id); it != done_.end()) return it->second;
    Operation op = from_.op(id);
    std::visit(Overload{
                   [&](Split& s) {
                     for (auto& p : s.parts) p.child = copy(p.child);
                   },
                   [&](Repeat& r) { r.child = copy(r.child); },
                   [&](RepeatN& r) { r.child = copy(r.child); },
                   [&](Choose& c) {
                     for (auto& o : c.options) o.child = copy(o.child);
                   },
                   [&](Call& c) {
                     throw Error(ErrorKind::Internal, "import_subgraph: the subgraph calls rule '" +
                                                          from_.rules[c.rule].label + "'; only rule-free graphs copy");
                   },
                   [&](Primitive& p) { p.label = to_.label_id(from_.label(p.label)); },
                   [&](Translate& t) { t.child = copy(t.child); },
                   [&](Scale& s) { s.child = copy(s.child); },
                   [&](Rotate& r) { r.child = copy(r.child); },
                   [&](Comp& c) {
                     for (auto& p : c.parts) p.child = copy(p.child);
                   },
                   [](auto&) {},
               },
               op);
    const NodeId out = to_.intern({std::move(op), from_.node(id).loc});
    done_.emplace(id, out);
    return out;
  }

 private:
  Grammar& to_;
  const Grammar& from_;
  std::unordered_map<NodeId, NodeId> done_;
};

}  // namespace

NodeId import_subgraph(Grammar& to, const Grammar& from, NodeId node) { return Importer(to, from).copy(node); }

}  // namespace vern
