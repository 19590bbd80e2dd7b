#include "inverse/sizes/levels_left.hpp"

#include <cmath>
#include <map>

#include "inverse/sizes/linear_size.hpp"

namespace vern {

namespace {

// A straight line through as few points says nothing: two counts are
// always on one. But for a ratio of weights, whole numbers are what
// grammars write (`~1 : ~(n - 1)`, a tier's drum one part in n of what is
// left) and what continuous sizes hardly ever give by chance: a ratio
// that is one in whole numbers at both counts is that line (pagodas of
// two and three tiers).
constexpr std::size_t kFewestCounts = 3;

// The part's one size at each count, if every level at a count agrees.
std::optional<std::map<int, double>> by_count(const LevelPart& part, double tolerance) {
  if (part.ranged || part.seen.empty()) return std::nullopt;
  std::map<int, double> out;
  for (const auto& [n, v] : part.seen) {
    const auto [it, added] = out.emplace(n, v);
    if (!added && std::abs(it->second - v) > tolerance) return std::nullopt;
  }
  return out;
}

bool varies(const std::map<int, double>& values, double tolerance) {
  for (const auto& [n, v] : values)
    if (std::abs(v - values.begin()->second) > tolerance) return true;
  return false;
}

// y = a + b n through the points, rounded short, each within `tolerance`
// once scaled by `scale` (the reference part's weight, for a ratio).
std::optional<Linear> line_in_n(const std::map<int, double>& y, const std::map<int, double>* scale, double tolerance) {
  std::vector<double> xs, ys;
  for (const auto& [n, v] : y) {
    xs.push_back(n);
    ys.push_back(scale ? v / scale->at(n) : v);
  }
  double largest = 1;
  if (scale)
    for (const auto& [n, v] : *scale) largest = std::max(largest, std::abs(v));
  const double tol = tolerance / largest;
  Fit f = line_fit(xs, ys);
  f.worst = worst_miss(xs, ys, f.a, f.b);
  if (f.b != 0 && xs.size() < kFewestCounts) {
    if (!scale) return std::nullopt;
    f.a = std::round(f.a);
    f.b = std::round(f.b);
    if (f.b == 0) return std::nullopt;
  } else {
    f = short_line(xs, ys, f, tol);
  }
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const double miss = std::abs(f.a + f.b * xs[i] - ys[i]) * (scale ? scale->at(static_cast<int>(xs[i])) : 1.0);
    if (miss > tolerance) return std::nullopt;
  }
  Linear out;
  out.c0 = f.a;
  if (f.b != 0) out.add(0, f.b);
  return out;
}

// One level's sizes, or nullopt (the outer optional) when a part that
// varies with n follows no line.
std::optional<std::vector<std::optional<Size>>> level_sizes(const std::vector<LevelPart>& parts, double tolerance) {
  std::vector<std::optional<Size>> out(parts.size());
  std::vector<std::optional<std::map<int, double>>> values(parts.size());
  bool relative_varies = false;
  for (std::size_t q = 0; q < parts.size(); ++q) {
    values[q] = by_count(parts[q], tolerance);
    if (!values[q] || !varies(*values[q], tolerance)) continue;
    if (parts[q].relative) {
      relative_varies = true;
      continue;
    }
    const auto line = line_in_n(*values[q], nullptr, tolerance);
    if (!line) return std::nullopt;
    out[q] = Size{linear_expr(*line), false};
  }
  if (!relative_varies) return out;
  // Relative parts only share: their ratios to one of them must each be
  // a line in n. The first reference that makes all of them lines wins.
  for (std::size_t ref = 0; ref < parts.size(); ++ref) {
    if (!parts[ref].relative || !values[ref]) continue;
    std::vector<std::optional<Size>> tried = out;
    bool lines = true;
    for (std::size_t q = 0; q < parts.size() && lines; ++q) {
      if (!parts[q].relative) continue;
      if (q == ref) {
        tried[q] = Size{Expr::number(1), true};
        continue;
      }
      if (!values[q] || values[q]->size() != values[ref]->size()) {
        lines = false;
        break;
      }
      const auto line = line_in_n(*values[q], &*values[ref], tolerance);
      lines = static_cast<bool>(line);
      for (const auto& [n, v] : *values[q]) lines = lines && line->c0 + line->coefficient(0) * n > 0;
      if (lines) tried[q] = Size{linear_expr(*line), true};
    }
    if (lines) return tried;
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::vector<std::vector<std::optional<Size>>>> sizes_by_levels_left(
    const std::vector<std::vector<LevelPart>>& levels, double tolerance) {
  std::vector<std::vector<std::optional<Size>>> out;
  bool any = false;
  for (const auto& parts : levels) {
    auto sizes = level_sizes(parts, tolerance);
    if (!sizes) return std::nullopt;
    for (const auto& s : *sizes) any = any || s.has_value();
    out.push_back(std::move(*sizes));
  }
  if (!any) return std::nullopt;
  return out;
}

}  // namespace vern
