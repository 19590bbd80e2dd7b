// A size written as a straight line in a rule's parameters,
// `~(0.5 * s1 + 1)`, and the straight line through the values seen:
// what joint_sizes and share_splits write where one size follows another.
#pragma once

#include <vector>

#include "graph/expr.hpp"

namespace vern {

// c0 + sum(c[k] * param k) + draws: what a size becomes.
struct Linear {
  double c0 = 0;
  std::vector<double> c;    // per parameter
  std::vector<Expr> draws;  // draws written in place (a parameter used once), added
  double coefficient(std::size_t k) const { return k < c.size() ? c[k] : 0.0; }
  void add(std::size_t k, double v) {
    if (c.size() <= k) c.resize(k + 1, 0.0);
    c[k] += v;
  }
};

// As a person writes it: `10 - s1`, `0.5 * s1 + 1`, `s1 + rand(-0.2, 0.2)`.
Expr linear_expr(const Linear& f);

// y = a + b x, worst: the largest miss, r: the correlation.
struct Fit {
  double a = 0, b = 0, worst = 0, r = 0;
};

// Do the points show a line at all? Three or more distinct x among four or
// more points: through two, any points lie on one.
bool shows_a_line(const std::vector<double>& x, double tol);

// Least squares (worst left 0); b = 0 when x does not vary.
Fit line_fit(const std::vector<double>& x, const std::vector<double>& y);
double worst_miss(const std::vector<double>& x, const std::vector<double>& y, double a, double b);
// The line with short decimals: within `tol` where the exact line is, or,
// for a loose one, missing by at most a tenth more.
Fit short_line(const std::vector<double>& x, const std::vector<double>& y, Fit f, double tol);

}  // namespace vern
