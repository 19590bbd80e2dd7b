// Solving for the one continuous random value a split's sizes use
// (split_search.hpp): the value that makes a placement fit, found from the
// lengths when the sizes are linear in it, else by scanning its support.
#include "inverse/check/split_search.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "forward/evaluate.hpp"
#include "inverse/check/check_matcher.hpp"

namespace vern::check_detail {

double SplitSearch::violation(const ScaleState& sc) const {
  double v = sc.penalty / tol_;
  if (sc.lo > sc.hi) v += (sc.lo - sc.hi) / std::max({std::abs(sc.hi), std::abs(sc.lo), 1e-300});
  if (v == 0 && !sc.ok()) v = 1e-12;
  return v;
}

bool SplitSearch::refresh_shares() {
  m_.scope_ = &s_;
  for (std::size_t i = 0; i < parts_.size(); ++i) {
    try {
      parts_[i].share = expression_support(op_.parts[i].size.value, m_.lookup_).clamp(0, kInf);
    } catch (const EvaluationError&) {
      return false;
    } catch (const NotCheckable&) {
      return false;
    }
  }
  return true;
}

std::vector<double> SplitSearch::linear_guesses(Unknown& u) {
  std::vector<double> out;
  if (mode_ != Mode::Fill) return out;
  const double lo = u.support.lower(), hi = u.support.upper();
  const double u0 = lo + (hi - lo) / 4, step = (hi - lo) / 4;
  if (!(step > 0)) return out;
  std::vector<std::array<double, 3>> size(parts_.size());
  std::vector<bool> linear(parts_.size(), true);
  for (int k = 0; k < 3; ++k) {
    u.value = u0 + k * step;
    const bool ok = refresh_shares();
    for (std::size_t i = 0; i < parts_.size(); ++i) {
      if (!ok || !parts_[i].share.is_point())
        linear[i] = false;
      else
        size[i][static_cast<std::size_t>(k)] = parts_[i].share.lower();
    }
  }
  u.value.reset();
  struct SizeLine {  // size = a + b * unknown, on a part this long
    double a, b, length;
    bool relative;
  };
  std::vector<SizeLine> lines;
  for (std::size_t i = 0; i < parts_.size(); ++i) {
    const Placement& pl = placement_[i];
    if (!linear[i] || !pl.filled || pl.floating) continue;
    const auto& v = size[i];
    const double b = (v[1] - v[0]) / step;
    if (std::abs((v[2] - v[1]) - (v[1] - v[0])) > 1e-9 * std::max(1.0, std::abs(v[2]))) continue;
    lines.push_back({v[0] - b * u0, b, at(pl.to) - at(pl.from), parts_[i].relative});
  }
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const SizeLine& p = lines[i];
    if (!p.relative) {
      if (p.b != 0) out.push_back((p.length - p.a) / p.b);
      continue;
    }
    // Two relative parts: their lengths in the ratio of their sizes.
    for (std::size_t j = i + 1; j < lines.size(); ++j) {
      const SizeLine& q = lines[j];
      if (!q.relative) continue;
      const double d = p.length * q.b - q.length * p.b;
      if (d != 0) out.push_back((q.length * p.a - p.length * q.a) / d);
    }
  }
  // Every size a point on a line: the relative parts share what the
  // absolute ones leave of the scope, so one part holding boxes is
  // enough (a tower of share s1 under air of share 77 - s1).
  if (std::ranges::all_of(linear, [](bool l) { return l; })) {
    double sum_a = 0, sum_b = 0, fixed = 0;
    bool absolute_move = false;
    for (std::size_t i = 0; i < parts_.size(); ++i) {
      const auto& v = size[i];
      const double b = (v[1] - v[0]) / step;
      if (parts_[i].relative) {
        sum_a += v[0] - b * u0;
        sum_b += b;
      } else {
        fixed += v[0];
        absolute_move = absolute_move || b != 0;
      }
    }
    const double rest = length_ - fixed;
    if (!absolute_move && rest > 0)
      for (const SizeLine& p : lines) {
        if (!p.relative) continue;
        // length * (sum_a + sum_b u) = (a + b u) * rest
        const double d = p.length * sum_b - p.b * rest;
        if (d != 0) out.push_back((p.a * rest - p.length * sum_a) / d);
      }
  }
  std::erase_if(out, [&](double v) { return !(v >= lo && v <= hi); });
  return out;
}

template <typename Fits>
double SplitSearch::centre(double v, Fits& fits) const {
  const Unknown& u = m_.vars_.unknown(st_.solve_for);
  double lo_bound = u.support.lower(), hi_bound = u.support.upper();
  for (const auto& [lo, hi] : u.support.intervals)
    if (v >= lo && v <= hi) lo_bound = lo, hi_bound = hi;
  auto edge = [&](double bound) {
    if (fits(bound)) return bound;
    double in = v, out = bound;
    for (int k = 0; k < 12; ++k) {  // to 2.4e-4 of the stretch: plenty for a middle
      const double mid = (in + out) / 2;
      (fits(mid) ? in : out) = mid;
    }
    return in;
  };
  if (lo_bound == hi_bound) return v;
  return (edge(lo_bound) + edge(hi_bound)) / 2;
}

std::optional<double> SplitSearch::solve() {
  Unknown& u = m_.vars_.unknown(st_.solve_for);
  auto misfit = [&](double v) {
    u.value = v;
    const double r = refresh_shares() ? violation(replay(false)) : kInf;
    u.value.reset();
    return r;
  };
  auto fits = [&](double v) {
    u.value = v;
    const bool ok = refresh_shares() && replay().ok();
    u.value.reset();
    return ok;
  };
  std::optional<double> found;
  // A guess that fits leaves the sizes evaluated at it.
  if (!u.support.values(256) && u.support.bounded())
    for (double v : linear_guesses(u))
      if (fits(v)) return v;
  if (auto values = u.support.values(256)) {
    for (double v : *values)
      if (fits(v)) {
        found = v;
        break;
      }
  } else if (u.support.bounded()) {
    std::vector<double> xs;
    for (const auto& [lo, hi] : u.support.intervals)
      for (int k = 0; k <= 32; ++k) xs.push_back(lo + (hi - lo) * k / 32.0);
    std::vector<double> fs;
    for (double x : xs) {
      m_.budget_.step();
      fs.push_back(misfit(x));
      if (fs.back() == 0 && fits(x)) {
        found = x;
        break;
      }
    }
    if (found) xs.clear();
    // Refine around the lowest few local minima of the scan: the misfit
    // mixes terms that jump where a share reaches 0, so the lowest
    // sample need not lie in the basin of the solution.
    std::vector<std::size_t> minima;
    for (std::size_t i = 0; i < xs.size(); ++i)
      if ((i == 0 || fs[i] <= fs[i - 1]) && (i + 1 == xs.size() || fs[i] <= fs[i + 1])) minima.push_back(i);
    std::sort(minima.begin(), minima.end(), [&](std::size_t p, std::size_t q) { return fs[p] < fs[q]; });
    if (minima.size() > 6) minima.resize(6);
    for (std::size_t best : minima) {
      double a = std::max(xs[best > 0 ? best - 1 : best], u.support.lower());
      double b = std::min(xs[best + 1 < xs.size() ? best + 1 : best], u.support.upper());
      const double phi = (std::sqrt(5.0) - 1) / 2;
      double c = b - phi * (b - a), d = a + phi * (b - a);
      double fc = misfit(c), fd = misfit(d);
      // Until the bracket is float noise or a point fits (misfit 0).
      for (int k = 0; k < 80 && fc > 0 && fd > 0 && b - a > 1e-15 * std::max(1.0, std::abs(b)); ++k) {
        m_.budget_.step();
        if (fc <= fd) {
          b = d;
          d = c;
          fd = fc;
          c = b - phi * (b - a);
          fc = misfit(c);
        } else {
          a = c;
          c = d;
          fc = fd;
          d = a + phi * (b - a);
          fd = misfit(d);
        }
      }
      for (double v : {fc == 0 ? c : d, xs[best], (a + b) / 2, c, d})
        if (u.support.contains(v, 0) && fits(v)) {
          found = v;
          break;
        }
      if (found) break;
    }
  }
  if (found) {
    auto zero = [&](double v) { return misfit(v) == 0; };
    const double mid = centre(*found, zero);
    if (fits(mid)) found = mid;
  }
  if (found) u.value = *found;
  refresh_shares();
  u.value.reset();
  return found;
}

}  // namespace vern::check_detail
