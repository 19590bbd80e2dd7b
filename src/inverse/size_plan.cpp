#include "inverse/size_plan.hpp"

#include <algorithm>
#include <cmath>

namespace vern {

std::optional<std::vector<PartPlan>> plan_sizes(const std::vector<std::vector<double>>& lengths, double tolerance) {
  if (lengths.size() < 2) return std::nullopt;
  const std::size_t parts = lengths[0].size();
  std::vector<double> totals;
  for (const auto& row : lengths) {
    if (row.size() != parts) return std::nullopt;
    double t = 0;
    for (const double l : row) t += l;
    totals.push_back(t);
  }
  const auto [lo, hi] = std::minmax_element(totals.begin(), totals.end());
  if (*hi - *lo <= tolerance) return std::nullopt;

  std::vector<PartPlan> plan(parts);
  std::size_t relative = 0;
  for (std::size_t i = 0; i < parts; ++i) {
    double a = lengths[0][i], b = a, sum = 0;
    for (const auto& row : lengths) {
      a = std::min(a, row[i]);
      b = std::max(b, row[i]);
      sum += row[i];
    }
    if (b - a <= tolerance) {
      plan[i] = {true, true, sum / static_cast<double>(lengths.size())};
    } else {
      ++relative;
    }
  }
  if (relative == 0) return std::nullopt;  // cannot happen while totals differ; kept for safety

  // Shares of what the absolute parts leave, taken from the member with the
  // most room (the best-conditioned ratio).
  const std::size_t widest = static_cast<std::size_t>(std::max_element(totals.begin(), totals.end()) - totals.begin());
  auto rest = [&](std::size_t m) {
    double r = totals[m];
    for (std::size_t i = 0; i < parts; ++i) r -= plan[i].absolute ? plan[i].value : 0.0;
    return r;
  };
  if (rest(widest) <= tolerance) return std::nullopt;
  bool shares_fixed = true;
  for (std::size_t i = 0; i < parts && shares_fixed; ++i) {
    if (plan[i].absolute) continue;
    const double share = lengths[widest][i] / rest(widest);
    for (std::size_t m = 0; m < lengths.size() && shares_fixed; ++m) {
      shares_fixed = std::abs(share * rest(m) - lengths[m][i]) <= tolerance;
    }
    plan[i].value = share;
  }
  // Shares are written as the widest member's lengths: rounding a weight
  // then moves a part by metres, not by a fraction of the whole.
  for (PartPlan& p : plan) {
    if (!p.absolute) {
      p.fixed = shares_fixed;
      p.value *= rest(widest);
    }
  }
  // The absolute lengths are means: every member's absolute parts, and
  // with fixed shares its relative ones, must still land within tolerance.
  for (std::size_t m = 0; m < lengths.size(); ++m) {
    double weights = 0;  // the ranged parts' weights: this member's own lengths
    for (std::size_t i = 0; i < parts; ++i) weights += plan[i].absolute || plan[i].fixed ? 0.0 : lengths[m][i];
    double fixed_shares = 0;  // the fixed relative parts' weights
    for (std::size_t i = 0; i < parts; ++i) fixed_shares += !plan[i].absolute && plan[i].fixed ? plan[i].value : 0.0;
    double at = 0, expected = 0;
    for (std::size_t i = 0; i < parts; ++i) {
      expected += lengths[m][i];
      if (plan[i].absolute) at += plan[i].value;
      else if (plan[i].fixed) at += plan[i].value / fixed_shares * rest(m);
      else at += lengths[m][i] / weights * rest(m);
      if (std::abs(at - expected) > tolerance) return std::nullopt;
    }
  }
  return plan;
}

}  // namespace vern
