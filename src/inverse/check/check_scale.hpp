// The scale of a split's placement while checking (check.hpp): which
// scales the lengths found in the example leave possible.
//
// A split's relative parts get k * r_i metres for one common scale k
// (Fill); when the absolute parts alone exceed the scope they shrink by a
// common factor 1/c and the relative parts get nothing (Overflow,
// docs/grammar.md, split). Each part placed on the example's cuts narrows the
// scales still possible; a fixed length that misses its size adds to a
// penalty instead, so a search for a random value can see how far off a
// placement is, not only that it is.
#pragma once

#include <algorithm>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "inverse/sizes/support.hpp"

namespace vern::check_detail {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

enum class Mode {
  Fill,      // sum(abs) < L: relative parts share the rest with a scale k
  Overflow,  // sum(abs) >= L: absolute parts shrink by 1/c, relative parts get 0
  NoFill,    // every relative share is 0 and sum(abs) < L: space left at the end
};

// The scale of a placement (k in Fill, c in Overflow) as the exact set
// still possible, its hull bounds as a continuous measure for solving, and
// how far fixed lengths miss their supports.
struct ScaleState {
  double lo = -kInf, hi = kInf;  // the hull of the scales still possible
  std::optional<Support> holes;  // the exact set, once it is more than one interval
  double penalty = 0;            // metres
  bool track_set = true;         // false: the hull and penalty only (a cheap measure for solving)
  bool ok() const { return penalty == 0 && lo <= hi && (!holes || !holes->empty()); }
  void limit(double a, double b) {
    lo = std::max(lo, a);
    hi = std::min(hi, b);
    if (holes) *holes = holes->clamp(a, b);
  }
  void limit(const Support& s) {
    if (s.intervals.size() == 1 || !track_set || lo > hi) return limit(s.lower(), s.upper());
    if (!holes) holes = Support::range(lo, hi);
    *holes = holes->intersect(s);
    lo = std::max(lo, s.lower());
    hi = std::min(hi, s.upper());
  }
  void require(double miss) { penalty += std::max(0.0, miss); }
  // The scales still possible.
  Support set() const {
    if (holes) return *holes;
    return lo <= hi ? Support::range(lo, hi) : Support{};
  }
};

// How far v lies from the nearest value of s (inf when s is empty).
inline double distance_to(const Support& s, double v) {
  double best = kInf;
  for (const auto& [lo, hi] : s.intervals) best = std::min(best, v < lo ? lo - v : (v > hi ? v - hi : 0.0));
  return best;
}

// slope * k + offset: a bound on a length as a function of the scale k.
struct Line {
  double slope = 0, offset = 0;
};

// The k in [lo, hi] at which every lower line is below every upper line
// (within tol): an interval, empty when lo > hi.
std::pair<double, double> feasible_scales(const std::vector<Line>& lowers, const std::vector<Line>& uppers, double lo,
                                          double hi, double tol);

// How far from feasible the best k in [lo, hi] is: the least, over k, of
// the largest excess of a lower line over an upper one.
double least_excess(const std::vector<Line>& lowers, const std::vector<Line>& uppers, double lo, double hi);

}  // namespace vern::check_detail
