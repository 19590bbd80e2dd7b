#include "inverse/merge.hpp"

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

class Merger {
 public:
  Merger(Grammar& g, const MergeOptions& o) : g_(g), opt_(o) {}

  // Groups nodes by shape and merges each group; one group merges to its
  // node, several to a choose weighted by their sizes (first seen first).
  NodeId merge_alternatives(const std::vector<NodeId>& nodes, const std::vector<double>& weights) {
    std::vector<std::vector<NodeId>> groups;
    std::vector<double> group_weight;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      std::size_t k = 0;
      while (k < groups.size() && !same_shape(groups[k].front(), nodes[i])) ++k;
      if (k == groups.size()) {
        groups.emplace_back();
        group_weight.push_back(0);
      }
      groups[k].push_back(nodes[i]);
      group_weight[k] += weights[i];
    }
    if (groups.size() == 1) return merge_group(groups[0]);
    Choose choose;
    for (std::size_t k = 0; k < groups.size(); ++k)
      choose.options.push_back({Expr{}, Expr::number(group_weight[k]), merge_group(groups[k])});
    return g_.intern({std::move(choose), {}});
  }

 private:
  // Same operations, axes, labels, relative flags, counts and structure;
  // sizes may differ. Memoised: graphs are DAGs with much sharing.
  bool same_shape(NodeId a, NodeId b) {
    if (a == b) return true;
    const auto key = std::minmax(a, b);
    if (auto it = shape_memo_.find(key); it != shape_memo_.end()) return it->second;
    const bool same = compare_shapes(g_.op(a), g_.op(b));
    shape_memo_.emplace(key, same);
    return same;
  }

  bool compare_shapes(const Operation& x, const Operation& y) {
    if (x.index() != y.index()) return false;
    return std::visit(
        Overload{
            [&](const Split& s) {
              const auto& t = std::get<Split>(y);
              if (s.axis != t.axis || s.parts.size() != t.parts.size()) return false;
              for (std::size_t i = 0; i < s.parts.size(); ++i) {
                if (s.parts[i].size.relative != t.parts[i].size.relative) return false;
                if (!literal_range(s.parts[i].size.value) || !literal_range(t.parts[i].size.value)) {
                  if (s.parts[i].size.value != t.parts[i].size.value) return false;
                }
                if (!same_shape(s.parts[i].child, t.parts[i].child)) return false;
              }
              return true;
            },
            [&](const RepeatN& r) {
              const auto& t = std::get<RepeatN>(y);
              return r.axis == t.axis && r.count == t.count && same_shape(r.child, t.child);
            },
            [&](const Repeat& r) {
              const auto& t = std::get<Repeat>(y);
              return r.axis == t.axis && r.size == t.size && same_shape(r.child, t.child);
            },
            [&](const Rotate& r) {
              const auto& t = std::get<Rotate>(y);
              return r.axis == t.axis && r.angle == t.angle && same_shape(r.child, t.child);
            },
            [&](const Primitive& p) { return p.label == std::get<Primitive>(y).label; },
            [&](const Nil&) { return true; },
            // Anything else merges only when identical (interned: same id).
            [&](const auto&) { return false; },
        },
        x);
  }

  // Merges nodes of one shape: sizes become ranges, children merge part by part.
  NodeId merge_group(const std::vector<NodeId>& group) {
    const NodeId first = group.front();
    if (std::all_of(group.begin(), group.end(), [&](NodeId n) { return n == first; })) return first;
    const Operation& op = g_.op(first);
    if (const auto* s = std::get_if<Split>(&op)) {
      Split merged;
      merged.axis = s->axis;
      for (std::size_t i = 0; i < s->parts.size(); ++i) {
        std::vector<NodeId> children;
        Range range{0, 0};
        bool has_range = false;
        for (NodeId n : group) {
          const SplitPart& part = std::get<Split>(g_.op(n)).parts[i];
          children.push_back(part.child);
          if (auto r = literal_range(part.size.value)) {
            range = has_range ? Range{std::min(range.lo, r->lo), std::max(range.hi, r->hi)} : *r;
            has_range = true;
          }
        }
        SplitPart part;
        part.size.relative = s->parts[i].size.relative;
        part.size.value = has_range ? range_expr(range, opt_.tolerance) : s->parts[i].size.value;
        part.child = merge_group(children);
        merged.parts.push_back(std::move(part));
      }
      return g_.intern({std::move(merged), {}});
    }
    // Single-child operations of one shape differ only below.
    auto merged_child = [&](auto member) {
      std::vector<NodeId> children;
      for (NodeId n : group) children.push_back(member(g_.op(n)));
      return merge_group(children);
    };
    if (const auto* r = std::get_if<RepeatN>(&op)) {
      RepeatN m = *r;
      m.child = merged_child([](const Operation& o) { return std::get<RepeatN>(o).child; });
      return g_.intern({std::move(m), {}});
    }
    if (const auto* r = std::get_if<Repeat>(&op)) {
      Repeat m = *r;
      m.child = merged_child([](const Operation& o) { return std::get<Repeat>(o).child; });
      return g_.intern({std::move(m), {}});
    }
    if (const auto* r = std::get_if<Rotate>(&op)) {
      Rotate m = *r;
      m.child = merged_child([](const Operation& o) { return std::get<Rotate>(o).child; });
      return g_.intern({std::move(m), {}});
    }
    return first;  // primitives and nil of one shape are one node already
  }

  Grammar& g_;
  const MergeOptions& opt_;
  std::map<std::pair<NodeId, NodeId>, bool> shape_memo_;
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
  NodeId simplify_split(const Split& s) {
    std::vector<SplitPart> parts;
    for (const auto& p : s.parts) parts.push_back({p.size, run(p.child)});
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
  Merger merger(g, options);
  const NodeId merged = merger.merge_alternatives(roots, std::vector<double>(roots.size(), 1.0));
  return Simplifier(g, options).run(merged);
}

}  // namespace vern
