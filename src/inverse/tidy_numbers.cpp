#include "inverse/tidy_numbers.hpp"

#include <cmath>
#include <unordered_map>

#include "inverse/merge.hpp"

namespace vern {

double shortest_decimal(double v, double tolerance, int direction) {
  if (v == 0.0 || !std::isfinite(v)) return v;
  for (int digits = 0; digits <= 17; ++digits) {
    const double scale = std::pow(10.0, digits);
    double r;
    if (direction < 0) r = std::floor(v * scale) / scale;
    else if (direction > 0) r = std::ceil(v * scale) / scale;
    else r = std::round(v * scale) / scale;
    if (std::abs(r - v) <= tolerance) return r;
  }
  return v;
}

std::optional<std::vector<double>> whole_ratios(const std::vector<double>& sizes, int max_whole) {
  double smallest = 0;
  for (double s : sizes) {
    if (!(s > 0)) return std::nullopt;
    smallest = smallest == 0 ? s : std::min(smallest, s);
  }
  // The smallest part is some whole k of the unit; try k = 1, 2, ...
  for (int k = 1; k <= max_whole; ++k) {
    const double unit = smallest / k;
    std::vector<double> out;
    bool ok = true;
    for (double s : sizes) {
      const double n = std::round(s / unit);
      if (n < 1 || n > max_whole || std::abs(s / unit - n) > 1e-9 * n) {
        ok = false;
        break;
      }
      out.push_back(n);
    }
    if (ok) return out;
  }
  return std::nullopt;
}

namespace {

class Tidier {
 public:
  Tidier(Grammar& g, double tolerance) : g_(g), tol_(tolerance) {}

  NodeId run(NodeId id) {
    if (auto it = memo_.find(id); it != memo_.end()) return it->second;
    Operation op = g_.op(id);
    if (auto* s = std::get_if<Split>(&op)) {
      tidy_split(*s);
    } else if (auto* c = std::get_if<Choose>(&op)) {
      for (auto& o : c->options) {
        o.child = run(o.child);
        if (auto p = o.priority.literal()) o.priority = Expr::number(shortest_decimal(*p, 1e-9 * *p));
      }
    } else if (auto* tiles = std::get_if<RepeatN>(&op)) {
      tiles->child = run(tiles->child);
    } else if (auto* repeat = std::get_if<Repeat>(&op)) {
      repeat->child = run(repeat->child);
      repeat->size = tidy(repeat->size);
    } else if (auto* turn = std::get_if<Rotate>(&op)) {
      turn->child = run(turn->child);
    }
    const NodeId out = g_.intern({std::move(op), g_.node(id).loc});
    memo_.emplace(id, out);
    return out;
  }

 private:
  Expr tidy(const Expr& e) const {
    if (auto v = e.literal()) return Expr::number(shortest_decimal(*v, tol_));
    if (auto r = literal_range(e))
      return range_expr({shortest_decimal(r->lo, tol_, -1), shortest_decimal(r->hi, tol_, +1)}, 0.0);
    return e;
  }

  void tidy_split(Split& s) {
    for (auto& p : s.parts) p.child = run(p.child);
    std::vector<double> relative;
    bool all_relative_literals = true;
    for (const auto& p : s.parts) {
      const auto v = p.size.value.literal();
      if (!p.size.relative || !v) all_relative_literals = false;
      else relative.push_back(*v);
    }
    if (all_relative_literals) {
      if (auto ratios = whole_ratios(relative)) {
        for (std::size_t i = 0; i < s.parts.size(); ++i) s.parts[i].size.value = Expr::number((*ratios)[i]);
        return;
      }
    }
    // Literal sizes: round the cut positions, not the sizes, so errors do
    // not add up along a split of many parts; each size is then the
    // difference of two short decimals (cleaned of binary noise).
    double position = 0, rounded_previous = 0;
    for (auto& p : s.parts) {
      const auto v = p.size.value.literal();
      if (!v) {
        // Past a range the cut positions are unknown: start again.
        p.size.value = tidy(p.size.value);
        position = rounded_previous = 0;
        continue;
      }
      position += *v;
      const double rounded = shortest_decimal(position, tol_);
      p.size.value = Expr::number(shortest_decimal(rounded - rounded_previous, 1e-12 * std::max(1.0, rounded)));
      rounded_previous = rounded;
    }
  }

  Grammar& g_;
  double tol_;
  std::unordered_map<NodeId, NodeId> memo_;
};

}  // namespace

NodeId tidy_numbers(Grammar& g, NodeId root, double tolerance) { return Tidier(g, tolerance).run(root); }

}  // namespace vern
