#include "inverse/sizes/linear_size.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "inverse/sizes/tidy_numbers.hpp"

namespace vern {

Expr linear_expr(const Linear& f) {
  std::optional<Expr> out;
  auto plus = [&](Expr term, bool negative) {
    if (!out) out = negative ? Expr::unary(UnaryOp::Neg, std::move(term)) : std::move(term);
    else out = Expr::binary(negative ? BinaryOp::Sub : BinaryOp::Add, std::move(*out), std::move(term));
  };
  const bool lead = f.c0 > 0 && std::ranges::any_of(f.c, [](double v) { return v < 0; });
  if (lead) out = Expr::number(f.c0);
  for (std::size_t k = 0; k < f.c.size(); ++k) {
    const double v = f.c[k];
    if (v == 0) continue;
    Expr p = Expr::param(static_cast<std::uint32_t>(k));
    if (std::abs(v) != 1) p = Expr::binary(BinaryOp::Mul, Expr::number(std::abs(v)), std::move(p));
    plus(std::move(p), v < 0);
  }
  if (!lead && (f.c0 != 0 || (!out && f.draws.empty()))) {
    if (!out) out = Expr::number(f.c0);
    else plus(Expr::number(std::abs(f.c0)), f.c0 < 0);
  }
  for (const Expr& d : f.draws) plus(d, false);
  return *out;
}

bool shows_a_line(const std::vector<double>& x, double tol) {
  if (x.size() < 4) return false;
  std::vector<double> sorted = x;
  std::ranges::sort(sorted);
  std::size_t distinct = 1;
  for (std::size_t i = 1; i < sorted.size(); ++i) distinct += sorted[i] - sorted[i - 1] > tol ? 1 : 0;
  return distinct >= 3;
}

Fit line_fit(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    mx += x[i] / n;
    my += y[i] / n;
  }
  double sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  Fit f;
  if (sxx <= 0) return f;
  f.b = sxy / sxx;
  f.a = my - f.b * mx;
  f.r = syy > 0 ? sxy / std::sqrt(sxx * syy) : 0;
  return f;
}

double worst_miss(const std::vector<double>& x, const std::vector<double>& y, double a, double b) {
  double worst = 0;
  for (std::size_t i = 0; i < x.size(); ++i) worst = std::max(worst, std::abs(y[i] - a - b * x[i]));
  return worst;
}

Fit short_line(const std::vector<double>& x, const std::vector<double>& y, Fit f, double tol) {
  double reach = 1;
  for (double v : x) reach = std::max(reach, std::abs(v));
  const double slack = std::max(tol, 0.1 * f.worst);
  for (double step : {0.5, 0.1, 0.01, 0.001, 0.0001}) {
    Fit t = f;
    t.b = shortest_decimal(f.b, step * slack / reach);
    double mean = 0;
    for (std::size_t i = 0; i < x.size(); ++i) mean += (y[i] - t.b * x[i]) / static_cast<double>(x.size());
    t.a = shortest_decimal(mean, step * slack);
    t.worst = worst_miss(x, y, t.a, t.b);
    if (t.worst <= f.worst + slack) return t;
  }
  return f;
}

}  // namespace vern
