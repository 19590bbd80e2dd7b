#include "inverse/sizes/size_plan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "inverse/merge/examples_cost.hpp"
#include "inverse/sizes/fit_distribution.hpp"
#include "inverse/sizes/linear_size.hpp"

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
  // What each member's absolute parts leave, once: the absolute lengths
  // are settled now, and asking per part made the checks below quadratic
  // in the parts (long rows of windows).
  std::vector<double> rests(lengths.size());
  for (std::size_t m = 0; m < lengths.size(); ++m) {
    double r = totals[m];
    for (std::size_t i = 0; i < parts; ++i) r -= plan[i].absolute ? plan[i].value : 0.0;
    rests[m] = r;
  }
  auto rest = [&](std::size_t m) { return rests[m]; };
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
  double fixed_shares = 0;  // the fixed relative parts' weights
  for (std::size_t i = 0; i < parts; ++i) fixed_shares += !plan[i].absolute && plan[i].fixed ? plan[i].value : 0.0;
  for (std::size_t m = 0; m < lengths.size(); ++m) {
    double weights = 0;  // the ranged parts' weights: this member's own lengths
    for (std::size_t i = 0; i < parts; ++i) weights += plan[i].absolute || plan[i].fixed ? 0.0 : lengths[m][i];
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

namespace {

// Of three or more relative parts that all vary, none in a ratio to
// another, the one the others are drawn beside, if any: two aisles of
// independent widths beside a nave of one share are shares of the nave,
// and drawn as metres, or as shares of the whole, each would carry the
// plot's variation too (a narrow aisle beside a wide nave, in a proportion
// the style never shows). Only the part that spreads least in metres may
// be the scale (a part as small as it is variable, a sliver of a tower's
// podium, would spread the others as much as the plot does), and only
// where the others spread less beside it than in metres: spread summed as
// log(largest / smallest), what a range costs to say at a given precision.
// In metres, a part on a straight line of an earlier one's length (a
// podium and the storeys 1.5 times its height plus 2.5 m) costs nothing:
// joint_sizes draws it from the other.
std::optional<std::size_t> scale_part(const std::vector<std::vector<double>>& lengths,
                                      const std::vector<std::size_t>& relative, double tolerance) {
  const std::size_t rows = lengths.size();
  auto column = [&](std::size_t i) {
    std::vector<double> c(rows);
    for (std::size_t m = 0; m < rows; ++m) c[m] = lengths[m][i];
    return c;
  };
  auto spread = [&](std::size_t i, std::optional<std::size_t> ref) {
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    for (std::size_t m = 0; m < rows; ++m) {
      const double w = lengths[m][i] / (ref ? lengths[m][*ref] : 1.0);
      lo = std::min(lo, w);
      hi = std::max(hi, w);
    }
    return lo > 0 ? std::log(hi / lo) : std::numeric_limits<double>::infinity();
  };
  auto follows_earlier = [&](std::size_t i) {
    if (rows < 4) return false;
    const std::vector<double> y = column(i);
    for (std::size_t j : relative) {
      if (j == i) break;
      const std::vector<double> x = column(j);
      if (!shows_a_line(x, tolerance)) continue;
      const Fit f = line_fit(x, y);
      if (worst_miss(x, y, f.a, f.b) <= tolerance) return true;
    }
    return false;
  };
  double in_metres = 0, steadiest_spread = std::numeric_limits<double>::infinity();
  std::optional<std::size_t> steadiest;
  for (std::size_t i : relative) {
    const double own = spread(i, std::nullopt);
    in_metres += follows_earlier(i) ? 0.0 : own;
    if (own < steadiest_spread) {
      steadiest_spread = own;
      steadiest = i;
    }
  }
  if (!steadiest) return std::nullopt;
  for (std::size_t m = 0; m < rows; ++m)
    if (!(lengths[m][*steadiest] > tolerance)) return std::nullopt;
  double beside = 0;
  for (std::size_t i : relative)
    if (i != *steadiest) beside += spread(i, steadiest);
  if (!(beside < in_metres)) return std::nullopt;
  return steadiest;
}

// Do the sizes give every row its own cuts, within the tolerance? Absolute
// drawn parts take the row's own length; relative parts share the rest by
// their weights (fixed, or the row's own drawn weight).
bool cuts_hold(const std::vector<std::vector<double>>& lengths, const std::vector<PartSizes>& plan, double tolerance) {
  for (std::size_t m = 0; m < lengths.size(); ++m) {
    const auto& row = lengths[m];
    auto size_of = [&](std::size_t i) { return plan[i].fixed ? plan[i].value : plan[i].values[m]; };
    double total = 0, absolute = 0, weights = 0;
    for (std::size_t i = 0; i < row.size(); ++i) {
      total += row[i];
      if (plan[i].absolute) absolute += size_of(i);
      else weights += size_of(i);
    }
    if (!(weights > 0)) return false;
    double at = 0, expected = 0;
    for (std::size_t i = 0; i < row.size(); ++i) {
      expected += row[i];
      at += plan[i].absolute ? size_of(i) : size_of(i) / weights * (total - absolute);
      if (std::abs(at - expected) > tolerance) return false;
    }
  }
  return true;
}

}  // namespace

std::optional<std::vector<PartSizes>> plan_drawn_sizes(const std::vector<std::vector<double>>& lengths,
                                                       double tolerance) {
  return plan_drawn_sizes(lengths, plan_sizes(lengths, tolerance), tolerance);
}

std::optional<std::vector<PartSizes>> plan_drawn_sizes(const std::vector<std::vector<double>>& lengths,
                                                       const std::optional<std::vector<PartPlan>>& base,
                                                       double tolerance) {
  if (lengths.size() < 2) return std::nullopt;
  const std::size_t parts = lengths[0].size(), rows = lengths.size();
  for (const auto& row : lengths)
    if (row.size() != parts) return std::nullopt;
  std::vector<PartSizes> plan(parts);
  std::vector<double> totals(rows, 0.0);
  for (std::size_t m = 0; m < rows; ++m)
    for (double l : lengths[m]) totals[m] += l;
  const std::size_t widest = static_cast<std::size_t>(std::max_element(totals.begin(), totals.end()) - totals.begin());
  auto column = [&](std::size_t i) {
    std::vector<double> c(rows);
    for (std::size_t m = 0; m < rows; ++m) c[m] = lengths[m][i];
    return c;
  };
  if (base) {
    bool all_fixed = true;
    for (std::size_t i = 0; i < parts; ++i) {
      plan[i].absolute = (*base)[i].absolute && (*base)[i].fixed;
      plan[i].fixed = plan[i].absolute;
      plan[i].value = plan[i].absolute ? (*base)[i].value : 0.0;
      all_fixed = all_fixed && (*base)[i].fixed;
    }
    if (all_fixed) return std::nullopt;  // plan_sizes says all there is
    // Parts drawn in metres: what it costs to say each row's length, to
    // the tolerance, when it is drawn from the range of lengths seen,
    // against drawn from the range of shares seen and scaled by the row's
    // split (the two hypotheses write the same two numbers, so only this
    // differs: a minimum description length choice).
    std::vector<std::size_t> drawn;
    std::vector<double> margin(parts, 0.0);
    for (std::size_t i = 0; i < parts; ++i) {
      if (plan[i].absolute) continue;
      const std::vector<double> metres = column(i);
      std::vector<double> shares(rows);
      for (std::size_t m = 0; m < rows; ++m) shares[m] = metres[m] / totals[m];
      const auto [mlo, mhi] = std::minmax_element(metres.begin(), metres.end());
      const auto [slo, shi] = std::minmax_element(shares.begin(), shares.end());
      // Lengths on an evenly spaced row that some repeat (whole tiles: a
      // door bay after one to four bays of 4.3 m) say one of its points.
      const auto row = even_row(metres, tolerance);
      double in_metres = 0, as_shares = 0;
      for (std::size_t m = 0; m < rows; ++m) {
        in_metres += row ? std::log(static_cast<double>(row->size())) : drawn_value_cost(*mhi - *mlo, tolerance);
        as_shares += drawn_value_cost((*shi - *slo) * totals[m], tolerance);
      }
      if (in_metres < as_shares) {
        drawn.push_back(i);
        margin[i] = in_metres - as_shares;
      }
    }
    std::size_t relative = 0;
    for (std::size_t i = 0; i < parts; ++i) relative += plan[i].absolute ? 0 : 1;
    if (!drawn.empty() && drawn.size() == relative) {
      // One part must stay relative: the one least like a length of its own.
      const auto keep = std::max_element(drawn.begin(), drawn.end(),
                                         [&](std::size_t a, std::size_t b) { return margin[a] < margin[b]; });
      drawn.erase(keep);
    }
    for (std::size_t i : drawn) {
      plan[i].absolute = true;
      plan[i].values = column(i);
    }
  }
  // The relative parts share what the absolute ones leave: in the same
  // ratios in every row, they are those ratios (the widest member's
  // lengths); else each row's own lengths, as weights (joint_sizes then
  // draws shares that vary in one way once).
  std::vector<std::size_t> relative;
  for (std::size_t i = 0; i < parts; ++i)
    if (!plan[i].absolute) relative.push_back(i);
  if (relative.empty()) return std::nullopt;
  auto relative_total = [&](std::size_t m) {
    double t = 0;
    for (std::size_t i : relative) t += lengths[m][i];
    return t;
  };
  bool ratios_fixed = relative_total(widest) > tolerance;
  for (std::size_t i : relative) {
    const double share = lengths[widest][i] / relative_total(widest);
    for (std::size_t m = 0; m < rows && ratios_fixed; ++m)
      ratios_fixed = std::abs(share * relative_total(m) - lengths[m][i]) <= tolerance;
  }
  bool varies = false;
  for (std::size_t i = 0; i < parts; ++i) {
    if (plan[i].absolute) {
      varies = varies || !plan[i].fixed;
    } else if (ratios_fixed) {
      plan[i].fixed = true;
      plan[i].value = lengths[widest][i];
    } else {
      plan[i].values = column(i);
    }
  }
  // Some relative parts in one ratio to each other, others varying (a
  // pillar and a wing of fixed proportions beside two bays that vary):
  // the parts in ratio to one of them keep that ratio and the others are
  // drawn as weights beside it (the widest member's scale). Only where it
  // fixes a part: two parts that both vary are left as each row's own
  // lengths, whose shares joint_sizes links as straight lines.
  // Where none keeps a ratio to another, one of them may still be the
  // scale the others are drawn in (scale_part).
  if (!ratios_fixed && relative.size() >= 3) {
    std::size_t best = parts, best_fixed = 0;
    for (std::size_t ref : relative) {
      bool usable = true;
      for (std::size_t m = 0; m < rows && usable; ++m) usable = lengths[m][ref] > tolerance;
      if (!usable) continue;
      std::size_t fixed = 0;
      for (std::size_t i : relative) {
        if (i == ref) continue;
        const double ratio = lengths[widest][i] / lengths[widest][ref];
        bool same = true;
        for (std::size_t m = 0; m < rows && same; ++m) same = std::abs(ratio * lengths[m][ref] - lengths[m][i]) <= tolerance;
        fixed += same ? 1 : 0;
      }
      if (fixed > best_fixed) {
        best_fixed = fixed;
        best = ref;
      }
    }
    if (best == parts) best = scale_part(lengths, relative, tolerance).value_or(parts);
    if (best != parts && best_fixed + 1 < relative.size()) {
      for (std::size_t i : relative) {
        const double ratio = lengths[widest][i] / lengths[widest][best];
        std::vector<double> w(rows);
        bool same = true;
        for (std::size_t m = 0; m < rows; ++m) {
          w[m] = lengths[m][i] / lengths[m][best] * lengths[widest][best];
          same = same && std::abs(ratio * lengths[m][best] - lengths[m][i]) <= tolerance;
        }
        if (same) {
          plan[i].fixed = true;
          plan[i].value = lengths[widest][i];
          plan[i].values.clear();
        } else {
          plan[i].values = std::move(w);
        }
      }
      varies = true;
    }
  }

  if (!varies) return std::nullopt;
  if (!cuts_hold(lengths, plan, tolerance)) return std::nullopt;
  return plan;
}

std::optional<std::vector<PartSizes>> planned_sizes(const std::vector<std::vector<double>>& lengths, double tolerance) {
  const auto base = plan_sizes(lengths, tolerance);
  if (!base) return std::nullopt;
  if (std::all_of(base->begin(), base->end(), [](const PartPlan& p) { return p.fixed; })) {
    std::vector<PartSizes> out;
    for (const PartPlan& p : *base) out.push_back({p.absolute, true, p.value, {}});
    return out;
  }
  return plan_drawn_sizes(lengths, base, tolerance);
}

std::size_t draws_of(const std::vector<PartSizes>& sizes) {
  std::size_t absolute = 0, relative = 0, relative_drawn = 0;
  for (const PartSizes& p : sizes) {
    if (p.absolute) {
      absolute += p.fixed ? 0 : 1;
    } else {
      ++relative;
      relative_drawn += p.fixed ? 0 : 1;
    }
  }
  return absolute + (relative > 0 && relative_drawn == relative ? relative_drawn - 1 : relative_drawn);
}

}  // namespace vern
