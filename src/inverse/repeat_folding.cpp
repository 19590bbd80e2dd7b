#include "inverse/repeat_folding.hpp"

#include <cmath>
#include <optional>
#include <unordered_map>

#include "graph/structural.hpp"
#include "inverse/tidy_numbers.hpp"

namespace vern {

namespace {

class Folder {
 public:
  Folder(Grammar& g, double tolerance) : g_(g), tol_(tolerance) {}

  NodeId run(NodeId id) {
    if (auto it = memo_.find(id); it != memo_.end()) return it->second;
    const Operation op = g_.op(id);  // a copy: interning below may grow the arena
    NodeId out = id;
    if (const auto* s = std::get_if<Split>(&op)) {
      out = fold_split(*s);
    } else if (std::holds_alternative<Choose>(op) || std::holds_alternative<Rotate>(op) ||
               std::holds_alternative<Repeat>(op) || std::holds_alternative<RepeatN>(op)) {
      Operation copy = op;
      bool changed = false;
      std::visit(
          [&](auto& o) {
            using T = std::decay_t<decltype(o)>;
            if constexpr (std::is_same_v<T, Choose>) {
              for (auto& option : o.options) {
                const NodeId c = run(option.child);
                changed = changed || c != option.child;
                option.child = c;
              }
            } else if constexpr (std::is_same_v<T, Rotate> || std::is_same_v<T, Repeat> || std::is_same_v<T, RepeatN>) {
              const NodeId c = run(o.child);
              changed = c != o.child;
              o.child = c;
            }
          },
          copy);
      if (changed) out = g_.intern({std::move(copy), {}});
    }
    memo_.emplace(id, out);
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

  NodeId fold_split(const Split& s) {
    std::vector<SplitPart> parts;
    bool literal = s.axis.nodes().size() == 1 && s.axis.node(0).kind == ExprKind::Axis;
    for (const SplitPart& p : s.parts) {
      parts.push_back({p.size, run(p.child)});
      literal = literal && p.size.value.literal();
    }
    if (literal) {
      // Adjacent empty parts are one empty part.
      std::vector<SplitPart> joined;
      for (const SplitPart& p : parts) {
        if (!joined.empty() && is_nil(p.child) && is_nil(joined.back().child) &&
            joined.back().size.relative == p.size.relative) {
          joined.back().size.value = Expr::number(*joined.back().size.value.literal() + *p.size.value.literal());
        } else {
          joined.push_back(p);
        }
      }
      parts = std::move(joined);
      // Only a run of three parts or more that is (almost) the whole split
      // is folded: the walls or margins at its ends may differ. A run
      // inside a mixed row (a | a | b)
      // is left to merging, which lines alike rows up first and finds what
      // combines freely there.
      if (const auto r = best_run(parts); r && r->parts() >= 3 && r->parts() + 2 >= parts.size()) {
        if (const std::optional<SplitPart> folded = fold(s.axis, parts, *r)) {
          parts.erase(parts.begin() + static_cast<std::ptrdiff_t>(r->start),
                      parts.begin() + static_cast<std::ptrdiff_t>(r->start + r->parts()));
          parts.insert(parts.begin() + static_cast<std::ptrdiff_t>(r->start), *folded);
        }
      }
    }
    if (parts.size() == 1 && parts[0].size.relative) return parts[0].child;
    return g_.intern({Split{s.axis, std::move(parts)}, {}});
  }

  static constexpr std::size_t kMaxPeriod = 4;
  Grammar& g_;
  double tol_;
  std::unordered_map<NodeId, NodeId> memo_;
};

}  // namespace

NodeId fold_repeats(Grammar& g, NodeId root, double tolerance) { return Folder(g, tolerance).run(root); }

}  // namespace vern
