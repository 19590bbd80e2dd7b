#include "inverse/repeat_folding.hpp"

#include <cmath>
#include <optional>
#include <vector>

#include "graph/structural.hpp"
#include "inverse/tidy_numbers.hpp"

namespace vern {

namespace {

class Folder {
 public:
  Folder(Grammar& g, double tolerance) : g_(g), tol_(tolerance) {}

  NodeId run(NodeId id) {
    if (id < memo_.size() && memo_[id] != kNotYet) return memo_[id];
    // Children first, by id: running them may intern nodes and move the
    // arena, so the operation is copied only when it must be rebuilt.
    const auto [done, changed] = map_children(g_.op(id), [&](NodeId c) { return run(c); });
    NodeId out = id;
    if (std::holds_alternative<Split>(g_.op(id))) {
      Split s = std::get<Split>(g_.op(id));
      for (std::size_t i = 0; i < s.parts.size(); ++i) s.parts[i].child = done[i];
      out = fold_split(s, changed);
      if (out == kNotYet) out = id;
    } else if (changed) {
      Operation copy = g_.op(id);
      const std::vector<NodeId*> slots = child_slots(copy);
      for (std::size_t i = 0; i < slots.size(); ++i) *slots[i] = done[i];
      out = g_.intern({std::move(copy), {}});
    }
    if (memo_.size() <= id) memo_.resize(std::max<std::size_t>(g_.node_count(), id + 1), kNotYet);
    memo_[id] = out;
    return out;
  }

 private:
  struct Run {
    std::size_t start = 0, period = 0, copies = 0;
    std::size_t parts() const { return period * copies; }
  };

  bool same(const SplitPart& a, const SplitPart& b) const {
    const auto x = a.size.value.literal(), y = b.size.value.literal();
    // Inference interns its graphs, so equal children are one node; a
    // grammar read from text is compared structurally.
    return a.size.relative == b.size.relative && x && y && std::abs(*x - *y) <= tol_ &&
           (a.child == b.child || structurally_equal(g_, a.child, g_, b.child));
  }

  // How many times parts[start, start + period) repeats from start on.
  std::size_t copies(const std::vector<SplitPart>& parts, std::size_t start, std::size_t period) const {
    std::size_t k = 1;
    while (start + (k + 1) * period <= parts.size()) {
      bool equal = true;
      for (std::size_t j = 0; j < period && equal; ++j) equal = same(parts[start + j], parts[start + k * period + j]);
      if (!equal) break;
      ++k;
    }
    return k;
  }

  std::optional<Run> best_run(const std::vector<SplitPart>& parts) const {
    std::optional<Run> best;
    for (std::size_t start = 0; start < parts.size(); ++start) {
      for (std::size_t period = 1; period <= kMaxPeriod && start + 2 * period <= parts.size(); ++period) {
        const std::size_t k = copies(parts, start, period);
        if (k < 2) continue;
        const Run r{start, period, k};
        if (!best || r.parts() > best->parts() || (r.parts() == best->parts() && r.period < best->period)) best = r;
      }
    }
    return best;
  }

  bool is_nil(NodeId id) const { return std::holds_alternative<Nil>(g_.op(id)); }

  // The run as one part: repeat(axis, tile){ pattern }, or nullopt when
  // equal tiles would move some original cut by more than the tolerance.
  std::optional<SplitPart> fold(const Expr& axis, const std::vector<SplitPart>& parts, const Run& r) {
    double total = 0;
    std::vector<double> cuts;  // the run's original cut positions
    for (std::size_t i = r.start; i < r.start + r.parts(); ++i) {
      total += *parts[i].size.value.literal();
      cuts.push_back(total);
    }
    const double tile = total / static_cast<double>(r.copies);
    double pattern = 0;
    std::vector<double> inner;
    for (std::size_t j = 0; j < r.period; ++j) inner.push_back(pattern += *parts[r.start + j].size.value.literal());
    for (std::size_t i = 0; i < cuts.size(); ++i) {
      const std::size_t copy = i / r.period, j = i % r.period;
      const double at = static_cast<double>(copy) * tile + inner[j] * (tile / pattern);
      if (std::abs(at - cuts[i]) > tol_) return std::nullopt;
    }
    NodeId body = parts[r.start].child;
    if (r.period > 1) {
      Split s{axis, {}};
      for (std::size_t j = 0; j < r.period; ++j) {
        s.parts.push_back({{parts[r.start + j].size.value, true}, parts[r.start + j].child});
      }
      body = g_.intern({std::move(s), {}});
    }
    // The written tile size: any size in (L / n, L / (n - 1)] makes n tiles
    // on L, and a size exactly L / n would make n + 1 once rounding nudges
    // L up. So the shortest decimal a hair above the tile, within a
    // percent (and a half tile count) of it: 2.9 for 2.8999997, not the
    // noise.
    const double n = static_cast<double>(r.copies);
    const double low = tile * (1 + 1e-5), high = tile * (1 + std::min(0.01, 0.5 / n));
    const double written = shortest_decimal((low + high) / 2, (high - low) / 2);
    const NodeId tiles = g_.intern({Repeat{axis, Expr::number(written), body}, {}});
    return SplitPart{{Expr::number(total), parts[r.start].size.relative}, tiles};
  }

  // The split with its parts' children already folded; kNotYet when
  // nothing changes (children_changed false and no run folded).
  NodeId fold_split(const Split& s, bool children_changed) {
    std::vector<SplitPart> parts = s.parts;
    bool literal = s.axis.nodes().size() == 1 && s.axis.node(0).kind == ExprKind::Axis;
    for (const SplitPart& p : parts) literal = literal && p.size.value.literal();
    bool changed = children_changed;
    if (literal) {
      // Adjacent empty parts are one empty part.
      std::vector<SplitPart> joined;
      for (const SplitPart& p : parts) {
        if (!joined.empty() && is_nil(p.child) && is_nil(joined.back().child) &&
            joined.back().size.relative == p.size.relative) {
          joined.back().size.value = Expr::number(*joined.back().size.value.literal() + *p.size.value.literal());
          changed = true;
        } else {
          joined.push_back(p);
        }
      }
      parts = std::move(joined);
      // Only a run of three parts or more that is (almost) the whole split
      // is folded: the walls or margins at its ends may differ. A run
      // inside a mixed row (a | a | b) is left to merging, which lines
      // alike rows up first and finds what combines freely there.
      if (const auto r = best_run(parts); r && r->parts() >= 3 && r->parts() + 2 >= parts.size()) {
        if (const std::optional<SplitPart> folded = fold(s.axis, parts, *r)) {
          parts.erase(parts.begin() + static_cast<std::ptrdiff_t>(r->start),
                      parts.begin() + static_cast<std::ptrdiff_t>(r->start + r->parts()));
          parts.insert(parts.begin() + static_cast<std::ptrdiff_t>(r->start), *folded);
          changed = true;
        }
      }
    }
    if (parts.size() == 1 && parts[0].size.relative) return parts[0].child;
    if (!changed) return kNotYet;
    return g_.intern({Split{s.axis, std::move(parts)}, {}});
  }

  static constexpr std::size_t kMaxPeriod = 4;
  static constexpr NodeId kNotYet = static_cast<NodeId>(-1);
  Grammar& g_;
  double tol_;
  std::vector<NodeId> memo_;  // by node id; kNotYet until folded
};

}  // namespace

NodeId fold_repeats(Grammar& g, NodeId root, double tolerance) { return Folder(g, tolerance).run(root); }

}  // namespace vern
