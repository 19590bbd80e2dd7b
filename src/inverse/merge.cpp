#include "inverse/merge.hpp"

#include "inverse/generalise.hpp"

#include <algorithm>
#include <map>
#include <unordered_map>

#include "graph/overload.hpp"
#include "graph/structural.hpp"

namespace vern {

std::optional<Range> literal_range(const Expr& e) {
  if (auto v = e.literal()) return Range{*v, *v};
  const ExprNode& root = e.node(e.root());
  if (root.kind != ExprKind::Call || static_cast<Function>(root.op) != Function::Rand || root.argc != 2 ||
      e.nodes().size() != 3)
    return std::nullopt;
  const ExprNode& a = e.node(0);
  const ExprNode& b = e.node(1);
  if (a.kind != ExprKind::Number || b.kind != ExprKind::Number) return std::nullopt;
  return Range{std::min(a.number, b.number), std::max(a.number, b.number)};
}

Expr range_expr(Range r, double tolerance) {
  if (r.hi - r.lo <= tolerance) return Expr::number(r.lo);
  return Expr::call(Function::Rand, {Expr::number(r.lo), Expr::number(r.hi)});
}

namespace {

// Unifies nodes of equal structure anywhere below a root (thesis 10.3):
// the same operation, axis, relative flags, counts and children (after
// unification), whatever their sizes. Each group becomes one node whose
// sizes are ranges over its members, so parents whose children now
// coincide fall into one group in turn. Bottom-up, one pass: a node's key
// names its children's groups, which are settled before it.
class Unifier {
 public:
  Unifier(Grammar& g, const MergeOptions& o) : g_(g), opt_(o) {}

  NodeId run(NodeId root) {
    visit(root);
    std::vector<NodeId> built(groups_.size(), 0);
    for (std::size_t k = 0; k < groups_.size(); ++k) built[k] = build(groups_[k], built);
    return built[group_of_.at(root)];
  }

 private:
  struct Group {
    NodeId first;                     // a member: the operation's form
    std::vector<std::size_t> children;  // child groups, in order
    std::vector<Range> ranges;        // per split part, over the members
    std::vector<double> weights;      // per child, for chooses: summed over the members
  };

  // A choose without conditions and with literal priorities: what merging
  // makes. Two of them over the same alternatives are one choice, whatever
  // their weights; the weights add up.
  static bool plain(const Choose& c) {
    return std::all_of(c.options.begin(), c.options.end(),
                       [](const ChooseOption& o) { return o.condition.empty() && o.priority.literal(); });
  }

  void visit_choose(NodeId id, const Choose& c, const std::vector<std::size_t>& children) {
    std::map<std::size_t, double> weight;  // child group -> weight; ordered, so the key is canonical
    for (std::size_t i = 0; i < children.size(); ++i) weight[children[i]] += *c.options[i].priority.literal();
    std::string key = "choose";
    for (const auto& [child, w] : weight) key += "," + std::to_string(child);
    auto [it, fresh] = group_by_key_.emplace(std::move(key), groups_.size());
    if (fresh) {
      Group group{id, {}, {}, {}};
      for (const auto& [child, w] : weight) {
        group.children.push_back(child);
        group.weights.push_back(0);
      }
      groups_.push_back(std::move(group));
    }
    Group& group = groups_[it->second];
    for (std::size_t k = 0; k < group.children.size(); ++k) group.weights[k] += weight[group.children[k]];
    group_of_.emplace(id, it->second);
  }

  // Post-order: children's groups exist before their parents' keys.
  void visit(NodeId id) {
    if (group_of_.count(id)) return;
    const Operation& op = g_.op(id);
    std::vector<std::size_t> children;
    for (NodeId c : node_children(op)) {
      visit(c);
      children.push_back(group_of_.at(c));
    }
    if (const auto* c = std::get_if<Choose>(&op); c && plain(*c)) {
      visit_choose(id, *c, children);
      return;
    }
    std::string key = structure_key(op, children);
    auto [it, fresh] = group_by_key_.emplace(std::move(key), groups_.size());
    if (fresh) groups_.push_back({id, children, {}, {}});
    Group& group = groups_[it->second];
    if (const auto* s = std::get_if<Split>(&op)) {
      // Each part's range starts at the first member's own value.
      const bool first_member = group.ranges.empty();
      if (first_member) group.ranges.resize(s->parts.size());
      for (std::size_t i = 0; i < s->parts.size(); ++i) {
        const auto r = literal_range(s->parts[i].size.value);
        if (!r) continue;  // non-literal sizes are part of the key
        Range& range = group.ranges[i];
        range = first_member ? *r : Range{std::min(range.lo, r->lo), std::max(range.hi, r->hi)};
      }
    }
    group_of_.emplace(id, it->second);
  }

  // Everything that must agree for two nodes to be one, sizes excepted:
  // the operation with its numbers blanked, and the child groups.
  std::string structure_key(const Operation& op, const std::vector<std::size_t>& children) const {
    Operation blank = op;
    if (auto* s = std::get_if<Split>(&blank)) {
      for (auto& p : s->parts) {
        if (literal_range(p.size.value)) p.size.value = Expr::number(0);
        p.child = 0;
      }
    } else {
      for (auto* child : child_slots(blank)) *child = 0;
    }
    std::string key = form_id(blank);
    for (std::size_t c : children) key += "," + std::to_string(c);
    return key;
  }

  // Two blank forms with one hash may still differ: give each distinct form
  // its own id by comparing with the forms seen under that hash.
  std::string form_id(const Operation& form) const {
    const std::size_t h = shallow_hash(form);
    auto& seen = forms_by_hash_[h];
    for (std::size_t i = 0; i < seen.size(); ++i)
      if (seen[i] == form) return std::to_string(h) + "." + std::to_string(i);
    seen.push_back(form);
    return std::to_string(h) + "." + std::to_string(seen.size() - 1);
  }

  static std::vector<NodeId*> child_slots(Operation& op) {
    std::vector<NodeId*> out;
    std::visit(Overload{
                   [&](Split& s) {
                     for (auto& p : s.parts) out.push_back(&p.child);
                   },
                   [&](Repeat& r) { out.push_back(&r.child); },
                   [&](RepeatN& r) { out.push_back(&r.child); },
                   [&](Choose& c) {
                     for (auto& o : c.options) out.push_back(&o.child);
                   },
                   [&](Translate& t) { out.push_back(&t.child); },
                   [&](Scale& s) { out.push_back(&s.child); },
                   [&](Rotate& r) { out.push_back(&r.child); },
                   [&](Comp& c) {
                     for (auto& p : c.parts) out.push_back(&p.child);
                   },
                   [](auto&) {},
               },
               op);
    return out;
  }

  NodeId build(const Group& group, const std::vector<NodeId>& built) {
    if (!group.weights.empty()) {
      Choose choose;
      for (std::size_t k = 0; k < group.children.size(); ++k)
        choose.options.push_back({Expr{}, Expr::number(group.weights[k]), built[group.children[k]]});
      if (choose.options.size() == 1) return choose.options[0].child;
      return g_.intern({std::move(choose), {}});
    }
    Operation op = g_.op(group.first);
    auto slots = child_slots(op);
    for (std::size_t i = 0; i < slots.size(); ++i) *slots[i] = built[group.children[i]];
    if (auto* s = std::get_if<Split>(&op)) {
      for (std::size_t i = 0; i < s->parts.size() && i < group.ranges.size(); ++i)
        if (literal_range(s->parts[i].size.value)) s->parts[i].size.value = range_expr(group.ranges[i], opt_.tolerance);
    }
    return g_.intern({std::move(op), {}});
  }

  Grammar& g_;
  const MergeOptions& opt_;
  std::vector<Group> groups_;
  std::unordered_map<std::string, std::size_t> group_by_key_;
  std::unordered_map<NodeId, std::size_t> group_of_;
  mutable std::unordered_map<std::size_t, std::vector<Operation>> forms_by_hash_;
};

// ---- simplification ----

class Simplifier {
 public:
  Simplifier(Grammar& g, const MergeOptions& o) : g_(g), opt_(o) {}

  NodeId run(NodeId id) {
    if (auto it = memo_.find(id); it != memo_.end()) return it->second;
    const NodeId out = simplify(id);
    memo_.emplace(id, out);
    return out;
  }

 private:
  NodeId simplify(NodeId id) {
    const Operation op = g_.op(id);  // a copy: interning below may grow the arena
    if (const auto* s = std::get_if<Split>(&op)) return simplify_split(*s);
    if (const auto* c = std::get_if<Choose>(&op)) return simplify_choose(*c);
    if (const auto* r = std::get_if<RepeatN>(&op)) {
      RepeatN m = *r;
      m.child = run(r->child);
      return g_.intern({std::move(m), {}});
    }
    if (const auto* r = std::get_if<Repeat>(&op)) {
      Repeat m = *r;
      m.child = run(r->child);
      return g_.intern({std::move(m), {}});
    }
    if (const auto* r = std::get_if<Rotate>(&op)) {
      Rotate m = *r;
      m.child = run(r->child);
      return g_.intern({std::move(m), {}});
    }
    return id;
  }

  bool same_size(const Size& a, const Size& b) const {
    if (a.relative != b.relative) return false;
    auto ra = literal_range(a.value);
    auto rb = literal_range(b.value);
    if (!ra || !rb) return a.value == b.value;
    return std::abs(ra->lo - rb->lo) <= opt_.tolerance && std::abs(ra->hi - rb->hi) <= opt_.tolerance;
  }

  // A run of two or more equal parts (same child, same size) is one part
  // holding repeatN: on its own scope the tiles come out the same, since
  // repeatN cuts equal tiles. Only literal sizes qualify: tiles of a range
  // are equal to each other, but the parts of a split draw independently.
  // A part holding a split along the same axis whose sizes are all
  // relative literals is that split's parts, in place: part size s and
  // inner sizes c_j give parts s * c_j / sum(c), relative or absolute as
  // the outer part was, which derive the same lengths. Inner absolute
  // sizes or ranges would not (they share space differently), so those stay.
  void flatten_into(std::vector<SplitPart>& out, const SplitPart& part, const Expr& axis) {
    const auto outer = part.size.value.literal();
    const auto* inner = std::get_if<Split>(&g_.op(part.child));
    if (outer && inner && inner->axis == axis) {
      double total = 0;
      bool literal_relative = true;
      for (const auto& q : inner->parts) {
        const auto v = q.size.value.literal();
        literal_relative = literal_relative && q.size.relative && v;
        if (v) total += *v;
      }
      if (literal_relative && total > 0) {
        for (const auto& q : inner->parts)
          flatten_into(out, {{Expr::number(*outer * *q.size.value.literal() / total), part.size.relative}, q.child}, axis);
        return;
      }
    }
    out.push_back(part);
  }

  NodeId simplify_split(const Split& s) {
    std::vector<SplitPart> parts;
    for (const auto& p : s.parts) flatten_into(parts, {p.size, run(p.child)}, s.axis);
    const Axis* axis = nullptr;
    Axis literal_axis{};
    if (s.axis.node(s.axis.root()).kind == ExprKind::Axis) {
      literal_axis = static_cast<Axis>(s.axis.node(s.axis.root()).op);
      axis = &literal_axis;
    }
    std::vector<SplitPart> out;
    for (std::size_t i = 0; i < parts.size();) {
      std::size_t j = i + 1;
      const auto lit = parts[i].size.value.literal();
      while (axis && lit && j < parts.size() && parts[j].child == parts[i].child && same_size(parts[j].size, parts[i].size))
        ++j;
      const std::size_t run_length = j - i;
      if (run_length >= 2 && !std::holds_alternative<Nil>(g_.op(parts[i].child))) {
        RepeatN rep{Expr::axis(*axis), Expr::number(static_cast<double>(run_length)), parts[i].child};
        const NodeId tiles = g_.intern({std::move(rep), {}});
        out.push_back({{Expr::number(*lit * static_cast<double>(run_length)), parts[i].size.relative}, tiles});
      } else if (run_length >= 2) {
        // Adjacent empty parts are one empty part.
        out.push_back({{Expr::number(*lit * static_cast<double>(run_length)), parts[i].size.relative}, parts[i].child});
      } else {
        out.push_back(parts[i]);
      }
      i = j;
    }
    // A split that is one relative part is that part's operation.
    if (out.size() == 1 && out[0].size.relative) return out[0].child;
    Split m{s.axis, std::move(out)};
    return g_.intern({std::move(m), {}});
  }

  // Identical alternatives are one, with their priorities added; nested
  // unconditional chooses are flattened (an option's share of the inner
  // choose times its own priority); a choose of one option is its child.
  NodeId simplify_choose(const Choose& c) {
    std::vector<std::pair<NodeId, double>> options;  // child, priority
    bool plain = true;                               // literal priorities, no conditions
    for (const auto& o : c.options) plain = plain && o.condition.empty() && o.priority.literal();
    if (!plain) {
      Choose m = c;
      for (auto& o : m.options) o.child = run(o.child);
      return g_.intern({std::move(m), {}});
    }
    auto add = [&](NodeId child, double priority) {
      for (auto& [n, p] : options) {
        if (n == child) {
          p += priority;
          return;
        }
      }
      options.emplace_back(child, priority);
    };
    for (const auto& o : c.options) {
      const NodeId child = run(o.child);
      const double priority = *o.priority.literal();
      const auto* inner = std::get_if<Choose>(&g_.op(child));
      bool inner_plain = inner != nullptr;
      double total = 0;
      if (inner)
        for (const auto& io : inner->options) {
          inner_plain = inner_plain && io.condition.empty() && io.priority.literal();
          if (inner_plain) total += *io.priority.literal();
        }
      if (inner_plain && total > 0) {
        for (const auto& io : inner->options) add(io.child, priority * *io.priority.literal() / total);
      } else {
        add(child, priority);
      }
    }
    if (options.size() == 1) return options[0].first;
    Choose m;
    for (const auto& [child, priority] : options) m.options.push_back({Expr{}, Expr::number(priority), child});
    return g_.intern({std::move(m), {}});
  }

  Grammar& g_;
  const MergeOptions& opt_;
  std::unordered_map<NodeId, NodeId> memo_;
};

}  // namespace

NodeId merge_examples(Grammar& g, const std::vector<NodeId>& roots, const MergeOptions& options) {
  Choose all;
  for (NodeId r : roots) all.options.push_back({Expr{}, Expr::number(1.0), r});
  const NodeId examples = g.intern({std::move(all), {}});
  // One example is reproduced as it is: ranges come only from variation
  // across examples, never from one building's own parts.
  if (roots.size() == 1) return Simplifier(g, options).run(examples);
  // Repeats are found at the end, once alike parts line up: finding them in
  // each example first would give rows of different fillings different
  // shapes (a | a | b is a repeat and a part, a | b | a is three parts).
  NodeId merged = Unifier(g, options).run(examples);
  // Free combinations make parents alike, which unify, which may show more
  // free combinations above: repeat until nothing changes (a few rounds:
  // each round generalises at least one frame, and frames only merge).
  for (int round = 0; round < 16; ++round) {
    bool changed = false;
    merged = generalise_free_parts(g, merged, options, changed);
    if (!changed) break;
    merged = Unifier(g, options).run(merged);
  }
  return Simplifier(g, options).run(merged);
}

}  // namespace vern
