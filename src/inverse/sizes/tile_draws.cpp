#include "inverse/sizes/tile_draws.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "inverse/sizes/tidy_numbers.hpp"

namespace vern {

Distribution tile_size_distribution(const std::vector<TileRun>& runs, const std::vector<Observation>& lengths,
                                    const FitOptions& fit, double tolerance) {
  std::vector<std::pair<double, double>> intervals;
  for (const TileRun& run : runs) {
    if (run.count < 2) return fit_distribution(lengths, fit);
    intervals.emplace_back(run.length, run.length * run.count / (run.count - 1));
  }
  if (intervals.empty()) return fit_distribution(lengths, fit);
  // A range meeting every interval starts below the least upper end and
  // ends above the greatest lower end: its ends are taken from those
  // (at most kEnds of each, evenly: a real facade set has hundreds).
  double least_upper = std::numeric_limits<double>::infinity(), greatest_lower = 0;
  for (const auto& [a, b] : intervals) {
    least_upper = std::min(least_upper, b);
    greatest_lower = std::max(greatest_lower, a);
  }
  std::vector<double> lows, highs;
  for (const auto& [a, b] : intervals)
    for (const double v : {a, b}) {
      if (v <= least_upper) lows.push_back(v);
      if (v >= greatest_lower) highs.push_back(v);
    }
  constexpr std::size_t kEnds = 48;
  auto thinned = [](std::vector<double> v) {
    std::ranges::sort(v);
    v.erase(std::unique(v.begin(), v.end()), v.end());
    if (v.size() <= kEnds) return v;
    std::vector<double> out;
    for (std::size_t k = 0; k < kEnds; ++k) out.push_back(v[k * (v.size() - 1) / (kEnds - 1)]);
    return out;
  };
  lows = thinned(std::move(lows));
  highs = thinned(std::move(highs));
  double best = -std::numeric_limits<double>::infinity(), lo = 0, hi = 0;
  for (const double from : lows)
    for (const double to : highs) {
      if (!(to > from)) continue;
      double log_likelihood = 0;
      for (const auto& [a, b] : intervals) {
        const double covered = std::min(b, to) - std::max(a, from);
        if (!(covered > 0)) {
          log_likelihood = -std::numeric_limits<double>::infinity();
          break;
        }
        log_likelihood += std::log(covered / (to - from));
      }
      if (log_likelihood > best) {
        best = log_likelihood;
        lo = from;
        hi = to;
      }
    }
  if (!std::isfinite(best)) return fit_distribution(lengths, fit);
  // In short decimals, moved inwards by at most a hundredth of the range,
  // still meeting every interval by the tolerance.
  const double slack = (hi - lo) / 100;
  auto shortest_in = [](double a, double b, double otherwise) {
    return a < b ? shortest_decimal((a + b) / 2, (b - a) / 2) : otherwise;
  };
  const double from = shortest_in(lo, std::min(lo + slack, least_upper - tolerance), lo);
  const double to = shortest_in(std::max(hi - slack, greatest_lower + tolerance), hi, hi);
  return Distribution{DistributionKind::Uniform, {}, from, to};
}

Expr count_line_expr(const Linear& f) {
  Linear rest = f;
  std::vector<std::pair<std::size_t, double>> divided;  // parameter, divisor
  for (std::size_t k = 0; k < f.c.size(); ++k) {
    if (f.c[k] == 0) continue;
    const double d = std::abs(1 / f.c[k]), short_d = shortest_decimal(d, d * 1e-5);
    if (short_d == shortest_decimal(d, d * 1e-3)) {  // as short as it gets
      divided.emplace_back(k, f.c[k] < 0 ? -short_d : short_d);
      rest.c[k] = 0;
    }
  }
  if (divided.empty()) return linear_expr(f);
  std::optional<Expr> out;
  const bool any_left = rest.c0 != 0 || std::ranges::any_of(rest.c, [](double v) { return v != 0; });
  if (any_left) out = linear_expr(rest);
  for (const auto& [k, d] : divided) {
    Expr term = Expr::binary(BinaryOp::Div, Expr::param(static_cast<std::uint32_t>(k)), Expr::number(std::abs(d)));
    if (!out) out = d < 0 ? Expr::unary(UnaryOp::Neg, std::move(term)) : std::move(term);
    else out = Expr::binary(d < 0 ? BinaryOp::Sub : BinaryOp::Add, std::move(*out), std::move(term));
  }
  return *out;
}

}  // namespace vern
