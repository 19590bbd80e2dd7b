#include "graph/structural.hpp"

#include <functional>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>

#include "base/overload.hpp"

namespace vern {

namespace {

std::size_t hash_size(std::size_t h, const Size& s) {
  return hash_combine(hash_combine(h, s.value.hash()), s.relative ? 1 : 2);
}

// Hashes an operation's own fields; `child` says how a child id enters the
// hash (its id, or its deep hash) and `label`/`rule` how names do.
template <class ChildHash, class LabelHash, class RuleHash>
std::size_t hash_operation(const Operation& op, ChildHash child, LabelHash label, RuleHash rule) {
  std::size_t h = op.index() * 0x100000001b3ULL;
  std::visit(Overload{
                 [&](const Split& s) {
                   h = hash_combine(h, s.axis.hash());
                   for (const auto& p : s.parts) h = hash_combine(hash_size(h, p.size), child(p.child));
                 },
                 [&](const Repeat& r) {
                   h = hash_combine(hash_combine(hash_combine(h, r.axis.hash()), r.size.hash()), child(r.child));
                 },
                 [&](const RepeatN& r) {
                   h = hash_combine(hash_combine(hash_combine(h, r.axis.hash()), r.count.hash()), child(r.child));
                 },
                 [&](const Choose& c) {
                   for (const auto& o : c.options) {
                     h = hash_combine(hash_combine(h, o.condition.hash()), o.priority.hash());
                     h = hash_combine(h, child(o.child));
                   }
                 },
                 [&](const Call& c) {
                   h = hash_combine(h, rule(c.rule));
                   for (const auto& a : c.args) h = hash_combine(h, a.hash());
                 },
                 [&](const Primitive& p) { h = hash_combine(h, label(p.label)); },
                 [&](const Nil&) {},
                 [&](const Translate& t) {
                   for (const auto& s : t.offset) h = hash_size(h, s);
                   h = hash_combine(h, child(t.child));
                 },
                 [&](const Scale& s) {
                   for (const auto& z : s.size) h = hash_size(h, z);
                   h = hash_combine(h, child(s.child));
                 },
                 [&](const Rotate& r) {
                   h = hash_combine(hash_combine(hash_combine(h, r.axis.hash()), r.angle.hash()), child(r.child));
                 },
                 [&](const Comp& c) {
                   for (const auto& p : c.parts) h = hash_combine(hash_combine(h, std::size_t(p.face)), child(p.child));
                 },
                 [&](const Colour& c) {
                   h = hash_combine(hash_combine(hash_combine(h, c.rgb[0].hash()), c.rgb[1].hash()), c.rgb[2].hash());
                 },
             },
             op);
  return h;
}

// Deep comparison of two graphs, memoised on node pairs so shared subgraphs
// (DAGs from hash-consing) are compared once.
class Comparer {
 public:
  Comparer(const Grammar& a, const Grammar& b) : a_(a), b_(b) {}

  // Pairs to compare on a stack of its own: graphs tens of thousands deep
  // (inference makes them) ran a recursion out of stack.
  bool nodes(NodeId x, NodeId y) {
    std::vector<std::pair<NodeId, NodeId>> unchecked{{x, y}};
    while (!unchecked.empty()) {
      const auto [p, q] = unchecked.back();
      unchecked.pop_back();
      if (&a_ == &b_ && p == q) continue;
      const Operation& op = a_.op(p);
      const Operation& oq = b_.op(q);
      // Own fields first: most unequal pairs differ there already, and need
      // no memo entry then. A pair met again is being or was found equal (a
      // DAG holds no node below itself), so it need not be looked at again.
      if (!same_fields(op, oq)) return false;
      if (!same_.insert({p, q}).second) continue;
      // The same kind with the same fields has as many children.
      std::size_t i = 0;
      for_each_child(op, [&](NodeId c) { unchecked.emplace_back(c, child_at(oq, i++)); });
    }
    return true;
  }

 private:
  // Everything but the children.
  bool same_fields(const Operation& ox, const Operation& oy) const {
    if (ox.index() != oy.index()) return false;
    return std::visit(
        Overload{
            [&](const Split& s) {
              const auto& t = std::get<Split>(oy);
              if (s.axis != t.axis || s.parts.size() != t.parts.size()) return false;
              for (std::size_t i = 0; i < s.parts.size(); ++i)
                if (s.parts[i].size != t.parts[i].size) return false;
              return true;
            },
            [&](const Repeat& r) {
              const auto& t = std::get<Repeat>(oy);
              return r.axis == t.axis && r.size == t.size;
            },
            [&](const RepeatN& r) {
              const auto& t = std::get<RepeatN>(oy);
              return r.axis == t.axis && r.count == t.count;
            },
            [&](const Choose& c) {
              const auto& t = std::get<Choose>(oy);
              if (c.options.size() != t.options.size()) return false;
              for (std::size_t i = 0; i < c.options.size(); ++i) {
                const auto& p = c.options[i];
                const auto& q = t.options[i];
                if (p.condition != q.condition || p.priority != q.priority) return false;
              }
              return true;
            },
            [&](const Call& c) {
              const auto& t = std::get<Call>(oy);
              return a_.rules[c.rule].label == b_.rules[t.rule].label && c.args == t.args;
            },
            [&](const Primitive& p) { return a_.label(p.label) == b_.label(std::get<Primitive>(oy).label); },
            [&](const Nil&) { return true; },
            [&](const Translate& tr) { return tr.offset == std::get<Translate>(oy).offset; },
            [&](const Scale& s) { return s.size == std::get<Scale>(oy).size; },
            [&](const Rotate& r) {
              const auto& t = std::get<Rotate>(oy);
              return r.axis == t.axis && r.angle == t.angle;
            },
            [&](const Comp& c) {
              const auto& t = std::get<Comp>(oy);
              if (c.parts.size() != t.parts.size()) return false;
              for (std::size_t i = 0; i < c.parts.size(); ++i)
                if (c.parts[i].face != t.parts[i].face) return false;
              return true;
            },
            [&](const Colour& c) { return c == std::get<Colour>(oy); },
        },
        ox);
  }

  // The i-th child, in for_each_child's order.
  static NodeId child_at(const Operation& op, std::size_t i) {
    if (const auto* s = std::get_if<Split>(&op)) return s->parts[i].child;
    if (const auto* c = std::get_if<Choose>(&op)) return c->options[i].child;
    if (const auto* m = std::get_if<Comp>(&op)) return m->parts[i].child;
    NodeId only = 0;  // the others have one child
    for_each_child(op, [&](NodeId c) { only = c; });
    return only;
  }

  const Grammar& a_;
  const Grammar& b_;
  // Pairs already compared or being compared; a mismatch anywhere makes the
  // whole answer false, so optimistic entries never leak a wrong "equal".
  std::set<std::pair<NodeId, NodeId>> same_;
};

}  // namespace

std::size_t shallow_hash(const Operation& op) {
  return hash_operation(
      op, [](NodeId id) { return std::size_t{id}; }, [](LabelId id) { return std::size_t{id}; },
      [](RuleId id) { return std::size_t{id}; });
}

std::size_t structural_hash(const Grammar& g, NodeId node) {
  // Children before parents on a stack of its own: a graph tens of
  // thousands deep (inference makes them) ran a recursion out of stack.
  std::unordered_map<NodeId, std::size_t> memo;
  std::vector<NodeId> unhashed{node};
  const auto label = [&](LabelId l) { return std::hash<std::string>{}(g.label(l)); };
  const auto rule = [&](RuleId r) { return std::hash<std::string>{}(g.rules[r].label); };
  while (!unhashed.empty()) {
    const NodeId id = unhashed.back();
    if (memo.contains(id)) {
      unhashed.pop_back();
      continue;
    }
    bool waiting = false;
    hash_operation(
        g.op(id),
        [&](NodeId c) {
          if (!memo.contains(c)) {
            unhashed.push_back(c);
            waiting = true;
          }
          return std::size_t{0};
        },
        label, rule);
    if (waiting) continue;
    unhashed.pop_back();
    memo.emplace(id, hash_operation(g.op(id), [&](NodeId c) { return memo.at(c); }, label, rule));
  }
  return memo.at(node);
}

std::vector<std::size_t> structural_hashes(const Grammar& g) {
  std::vector<std::size_t> hashes(g.node_count());
  std::vector<char> known(g.node_count(), 0);
  std::function<std::size_t(NodeId)> deep = [&](NodeId id) -> std::size_t {
    if (known[id]) return hashes[id];
    hashes[id] = hash_operation(
        g.op(id), deep, [&](LabelId l) { return std::hash<std::string>{}(g.label(l)); },
        [&](RuleId r) { return std::hash<std::string>{}(g.rules[r].label); });
    known[id] = 1;
    return hashes[id];
  };
  for (NodeId id = 0; id < g.node_count(); ++id) deep(id);
  return hashes;
}

bool structurally_equal(const Grammar& ga, NodeId a, const Grammar& gb, NodeId b) {
  return Comparer(ga, gb).nodes(a, b);
}

bool equal_grammars(const Grammar& a, const Grammar& b) {
  if (a.rules.size() != b.rules.size() || a.constants.size() != b.constants.size()) return false;
  if (a.primitives != b.primitives || a.scope != b.scope) return false;
  if (!a.rules.empty() && a.rules[a.start_rule].label != b.rules[b.start_rule].label) return false;
  for (std::size_t i = 0; i < a.constants.size(); ++i)
    if (a.constants[i].name != b.constants[i].name || a.constants[i].value != b.constants[i].value) return false;
  Comparer cmp(a, b);
  for (std::size_t i = 0; i < a.rules.size(); ++i) {
    const Rule& ra = a.rules[i];
    const Rule& rb = b.rules[i];
    if (ra.label != rb.label || ra.params.size() != rb.params.size()) return false;
    if (!cmp.nodes(ra.body, rb.body)) return false;
  }
  return true;
}

}  // namespace vern
