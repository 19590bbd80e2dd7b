#include "inverse/check/check_scale.hpp"

#include <cmath>

namespace vern::check_detail {

std::pair<double, double> feasible_scales(const std::vector<Line>& lowers, const std::vector<Line>& uppers, double lo,
                                          double hi, double tol) {
  for (const Line& a : lowers)
    for (const Line& b : uppers) {
      const double d = a.slope - b.slope, r = b.offset - a.offset + tol;
      if (std::abs(d) < 1e-300) {
        if (r < 0) return {1, 0};
      } else if (d > 0) {
        hi = std::min(hi, r / d);
      } else {
        lo = std::max(lo, r / d);
      }
    }
  return {lo, hi};
}

// A convex piecewise linear function of k: its minimum lies at a crossing
// of two of its lines or at an end.
double least_excess(const std::vector<Line>& lowers, const std::vector<Line>& uppers, double lo, double hi) {
  std::vector<Line> h;
  for (const Line& a : lowers)
    for (const Line& b : uppers) h.push_back({a.slope - b.slope, a.offset - b.offset});
  auto g = [&](double k) {
    double m = -kInf;
    for (const Line& l : h) m = std::max(m, l.slope * k + l.offset);
    return m;
  };
  std::vector<double> ks;
  if (std::isfinite(lo)) ks.push_back(lo);
  if (std::isfinite(hi)) ks.push_back(hi);
  for (std::size_t i = 0; i < h.size(); ++i)
    for (std::size_t j = i + 1; j < h.size(); ++j)
      if (h[i].slope != h[j].slope) {
        const double k = (h[j].offset - h[i].offset) / (h[i].slope - h[j].slope);
        if (k >= lo && k <= hi) ks.push_back(k);
      }
  if (ks.empty()) ks.push_back(lo <= hi ? std::clamp(1.0, lo, hi) : lo);
  double best = kInf;
  for (double k : ks) best = std::min(best, g(k));
  return best;
}

}  // namespace vern::check_detail
