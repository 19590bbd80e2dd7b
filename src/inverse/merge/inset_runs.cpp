#include "inverse/merge/inset_runs.hpp"

#include <cmath>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "graph/structural.hpp"

namespace vern {

namespace {

// An inset: empty space on both ends of one axis, or of two axes, around
// what it holds; margins in the order axis b low, high, axis c low, high.
struct Inset {
  std::uint8_t b = 0;
  std::optional<std::uint8_t> c;
  std::vector<double> margins;
  NodeId held = 0;
};

class Nester {
 public:
  Nester(Grammar& g, double tolerance, const std::vector<bool>* kept) : g_(g), tol_(tolerance), kept_(kept) {}

  NodeId run(NodeId id) {
    if (const auto it = memo_.find(id); it != memo_.end()) return it->second;
    if (kept_ != nullptr && id < kept_->size() && (*kept_)[id]) return id;
    const auto [done, changed] = map_children(g_.op(id), [&](NodeId c) { return run(c); });
    NodeId out = id;
    if (changed) {
      Operation copy = g_.op(id);
      const std::vector<NodeId*> slots = child_slots(copy);
      for (std::size_t i = 0; i < slots.size(); ++i) *slots[i] = done[i];
      out = g_.intern({std::move(copy), g_.node(id).loc});
    }
    if (std::holds_alternative<Split>(g_.op(out))) out = nest_runs(out);
    memo_[id] = out;
    return out;
  }

 private:
  bool is_nil(NodeId id) const { return std::holds_alternative<Nil>(g_.op(id)); }

  static std::optional<double> length(const SplitPart& p) { return p.size.value.literal(); }

  // Empty space at both ends of one axis around what it holds.
  struct Margins {
    std::uint8_t axis = 0;
    double lo = 0, hi = 0;
    NodeId held = 0;
  };

  // nil | X | nil along an axis other than `not_axis`.
  std::optional<Margins> margins_of(NodeId id, std::uint8_t not_axis) const {
    const auto* s = std::get_if<Split>(&g_.op(id));
    if (!s || s->parts.size() != 3) return std::nullopt;
    const auto axis = s->axis.literal_axis();
    if (!axis || *axis == not_axis) return std::nullopt;
    const auto lo = length(s->parts[0]), mid = length(s->parts[1]), hi = length(s->parts[2]);
    if (!lo || !mid || !hi || !is_nil(s->parts[0].child) || !is_nil(s->parts[2].child) || is_nil(s->parts[1].child))
      return std::nullopt;
    return Margins{*axis, *lo, *hi, s->parts[1].child};
  }

  // The part's child as an inset across the split's axis a: margins on one
  // axis, and on a second where what they hold has margins of its own.
  std::optional<Inset> inset_of(NodeId id, std::uint8_t a) const {
    const auto outer = margins_of(id, a);
    if (!outer) return std::nullopt;
    Inset in{outer->axis, std::nullopt, {outer->lo, outer->hi}, outer->held};
    if (const auto inner = margins_of(outer->held, a); inner && inner->axis != outer->axis) {
      in.c = inner->axis;
      in.margins.push_back(inner->lo);
      in.margins.push_back(inner->hi);
      in.held = inner->held;
    }
    return in;
  }

  // Is `in` the step times k, on the same axes?
  bool scaled(const Inset& in, const Inset& step, double k) const {
    if (in.b != step.b || in.c != step.c || in.margins.size() != step.margins.size()) return false;
    for (std::size_t i = 0; i < in.margins.size(); ++i)
      if (std::abs(in.margins[i] - k * step.margins[i]) > tol_) return false;
    return true;
  }

  // One step's inset around x, on a scope already set in by depth - 1
  // steps from the run's scope (eb along b, ec along c): literal lengths,
  // as an example's are.
  NodeId wrap_in(const Inset& step, NodeId x, double depth, double eb, double ec) {
    NodeId middle = x;
    if (step.c) {
      const double sum = step.margins[2] + step.margins[3];
      const double extent = ec - (depth - 1) * sum;
      middle = split(*step.c, {{step.margins[2], nil()}, {extent - sum, x}, {step.margins[3], nil()}});
    }
    const double sum = step.margins[0] + step.margins[1];
    const double extent = eb - (depth - 1) * sum;
    return split(step.b, {{step.margins[0], nil()}, {extent - sum, middle}, {step.margins[1], nil()}});
  }

  NodeId nil() { return g_.intern({Nil{}, {}}); }

  NodeId split(std::uint8_t axis, const std::vector<std::pair<double, NodeId>>& parts) {
    Split s{Expr::axis(static_cast<Axis>(axis)), {}};
    for (const auto& [len, child] : parts) s.parts.push_back({{Expr::number(len), true}, child});
    return g_.intern({std::move(s), {}});
  }

  // The extents along b and c of the outermost inset's scope: its parts'
  // lengths summed.
  std::pair<double, double> extents(NodeId inset_node, const Inset& in) const {
    const auto& s = std::get<Split>(g_.op(inset_node));
    double b = 0;
    for (const auto& p : s.parts) b += *length(p);
    double c = 0;
    if (in.c) {
      for (const auto& p : std::get<Split>(g_.op(s.parts[1].child)).parts) c += *length(p);
    }
    return {b, c};
  }

  NodeId nest_runs(NodeId id) {
    const Split s = std::get<Split>(g_.op(id));  // a copy: interning may move the arena
    const auto a = s.axis.literal_axis();
    if (!a) return id;
    for (const auto& p : s.parts)
      if (!length(p)) return id;
    // The first run of two insets or more scaling 1, 2, ... times a step.
    for (std::size_t first = 0; first + 1 < s.parts.size(); ++first) {
      const auto step = inset_of(s.parts[first].child, *a);
      if (!step) continue;
      std::vector<Inset> levels{*step};
      for (std::size_t i = first + 1; i < s.parts.size(); ++i) {
        const auto in = inset_of(s.parts[i].child, *a);
        if (!in || !scaled(*in, *step, static_cast<double>(levels.size() + 1))) break;
        levels.push_back(*in);
      }
      if (levels.size() < 2) continue;
      // Scope extents at the first level's inset: every level's lies
      // inside it, smaller by the steps taken.
      const auto [eb, ec] = extents(s.parts[first].child, *step);
      const std::size_t k = levels.size();
      // From the last level up: each level's content beside the inset of
      // what follows it.
      NodeId inner = levels[k - 1].held;
      double inner_length = *length(s.parts[first + k - 1]);
      for (std::size_t j = k - 1; j-- > 0;) {
        const double own = *length(s.parts[first + j]);
        inner = split(*a, {{own, levels[j].held},
                           {inner_length, wrap_in(*step, inner, static_cast<double>(j + 2), eb, ec)}});
        inner_length += own;
      }
      // The part before the run is its ground level where it holds what
      // the first level does (a drum below the drums set in): the stack
      // starts there.
      std::size_t from = first;
      NodeId stack = wrap_in(*step, inner, 1, eb, ec);
      if (first > 0 && (s.parts[first - 1].child == levels[0].held ||
                        structurally_equal(g_, s.parts[first - 1].child, g_, levels[0].held))) {
        from = first - 1;
        const double own = *length(s.parts[from]);
        stack = split(*a, {{own, levels[0].held}, {inner_length, stack}});
        inner_length += own;
      }
      Split out{s.axis, {}};
      for (std::size_t i = 0; i < from; ++i) out.parts.push_back(s.parts[i]);
      out.parts.push_back({{Expr::number(inner_length), true}, stack});
      for (std::size_t i = first + k; i < s.parts.size(); ++i) out.parts.push_back(s.parts[i]);
      return g_.intern({std::move(out), g_.node(id).loc});
    }
    // A stack of one level: a top set in all round on the part it stands
    // on, by one margin on each axis (a cap on the last tier), is one part
    // with it, as a stack of more levels is, where that part is not one of
    // a run below it (storeys under a roof set in from their eaves stay
    // storeys). A roof centred along one axis only is no tier.
    if (*a == 2 && s.parts.size() >= 3) {
      const std::size_t top = s.parts.size() - 1;
      const NodeId below = s.parts[top - 1].child, under = s.parts[top - 2].child;
      const auto cap = inset_of(s.parts[top].child, *a);
      const bool all_round = cap && cap->c && std::abs(cap->margins[0] - cap->margins[1]) <= tol_ &&
                             std::abs(cap->margins[2] - cap->margins[3]) <= tol_;
      if (all_round && !inset_of(below, *a) && !is_nil(below) && below != under &&
          !structurally_equal(g_, below, g_, under)) {
        const double own = *length(s.parts[top - 1]), capped = *length(s.parts[top]);
        const NodeId stack = split(*a, {{own, below}, {capped, s.parts[top].child}});
        Split out{s.axis, {}};
        for (std::size_t i = 0; i + 1 < top; ++i) out.parts.push_back(s.parts[i]);
        out.parts.push_back({{Expr::number(own + capped), true}, stack});
        return g_.intern({std::move(out), g_.node(id).loc});
      }
    }
    return id;
  }

  Grammar& g_;
  double tol_;
  const std::vector<bool>* kept_;  // by node id: left as it is, or null
  std::unordered_map<NodeId, NodeId> memo_;
};

}  // namespace

NodeId nest_inset_runs(Grammar& g, NodeId root, double tolerance, const std::vector<bool>* kept) {
  return Nester(g, tolerance, kept).run(root);
}

}  // namespace vern
