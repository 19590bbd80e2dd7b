#include "inverse/sizes/support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "base/number_format.hpp"
#include "forward/evaluate.hpp"

namespace vern {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// More intervals than this collapse to their hull: supports are for
// pruning and messages, and a product of two 64-point sets need not be
// kept point by point.
constexpr std::size_t kMaxIntervals = 256;
// Integer sets this small are kept as explicit points, so arithmetic on
// them stays exact (randint(1, 4) * 2 is {2, 4, 6, 8}, not [2, 8]).
constexpr double kMaxExpandedIntegers = 64;

using Interval = std::pair<double, double>;

// Sorts, merges overlapping intervals, trims integer sets to whole bounds
// and expands small integer sets to points.
Support normalised(Intervals in, bool integer) {
  // The common case, one plain interval, without sorting or copying.
  if (in.size() == 1 && !integer && !std::isnan(in[0].first) && !std::isnan(in[0].second)) {
    if (in[0].first > in[0].second) std::swap(in[0].first, in[0].second);
    Support s;
    s.intervals = std::move(in);
    return s;
  }
  Intervals v;
  v.reserve(in.size());
  for (auto [lo, hi] : in) {
    if (std::isnan(lo) || std::isnan(hi)) continue;
    if (lo > hi) std::swap(lo, hi);
    if (integer) {
      lo = std::ceil(lo);
      hi = std::floor(hi);
      if (lo > hi) continue;
    }
    v.emplace_back(lo, hi);
  }
  std::sort(v.begin(), v.end());
  Support s;
  for (const auto& iv : v) {
    if (!s.intervals.empty() && iv.first <= s.intervals.back().second)
      s.intervals.back().second = std::max(s.intervals.back().second, iv.second);
    else
      s.intervals.push_back(iv);
  }
  if (integer) {
    double count = 0;
    for (const auto& [lo, hi] : s.intervals) count += hi - lo + 1;
    if (count <= kMaxExpandedIntegers) {
      Intervals points;
      for (const auto& [lo, hi] : s.intervals)
        for (double k = lo; k <= hi; k += 1) points.emplace_back(k, k);
      s.intervals = std::move(points);
      integer = false;
    }
  }
  s.integer = integer;
  if (s.intervals.size() > kMaxIntervals) s.intervals = {{s.intervals.front().first, s.intervals.back().second}};
  return s;
}

// 0 * inf is NaN in IEEE arithmetic; as a bound of a product it means 0.
double product(double a, double b) {
  const double p = a * b;
  return std::isnan(p) ? 0.0 : p;
}

Interval mul(const Interval& a, const Interval& b) {
  const double p[4] = {product(a.first, b.first), product(a.first, b.second), product(a.second, b.first),
                       product(a.second, b.second)};
  return {*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
}

// a / b for b within [lo, hi] not holding 0 in its inside; appends results.
void divide(const Interval& a, double lo, double hi, Intervals& out) {
  if (a.first == 0 && a.second == 0) {
    out.emplace_back(0.0, 0.0);
  } else if (lo > 0 || hi < 0) {
    const double q[4] = {a.first / lo, a.first / hi, a.second / lo, a.second / hi};
    out.emplace_back(*std::min_element(q, q + 4), *std::max_element(q, q + 4));
  } else if (lo == 0 && hi > 0) {  // b in (0, hi]
    if (a.first >= 0)
      out.emplace_back(a.first / hi, kInf);
    else if (a.second <= 0)
      out.emplace_back(-kInf, a.second / hi);
    else
      out.emplace_back(-kInf, kInf);
  } else if (hi == 0 && lo < 0) {  // b in [lo, 0)
    if (a.first >= 0)
      out.emplace_back(-kInf, a.first / lo);
    else if (a.second <= 0)
      out.emplace_back(a.second / lo, kInf);
    else
      out.emplace_back(-kInf, kInf);
  }
}

template <typename F>
Support combine(const Support& x, const Support& y, bool keeps_integer, F op) {
  if (x.empty() || y.empty()) return {};
  // Pairwise on many intervals costs more than it tells: use hulls.
  const bool hull = x.intervals.size() * y.intervals.size() > 4096;
  const Intervals xs = hull ? Intervals{{x.lower(), x.upper()}} : x.intervals;
  const Intervals ys = hull ? Intervals{{y.lower(), y.upper()}} : y.intervals;
  Intervals out;
  for (const auto& a : xs)
    for (const auto& b : ys) op(a, b, out);
  return normalised(std::move(out), keeps_integer && x.integer && y.integer);
}

// Which truth values a number set holds: {0} is false, no 0 is true.
struct Truth {
  bool can_be_false = false;
  bool can_be_true = false;
};

Truth truth(const Support& s) {
  Truth t;
  t.can_be_false = s.contains(0.0);
  t.can_be_true = !s.empty() && !(s.is_point() && s.lower() == 0.0);
  return t;
}

Support from_truth(bool can_be_false, bool can_be_true) {
  std::vector<double> v;
  if (can_be_false) v.push_back(0.0);
  if (can_be_true) v.push_back(1.0);
  return Support::points(v);
}

// Exact values carry no support inside the walk (most of an expression is
// exact, and a support costs an allocation); possible_values() adds it.
Possible exact(Value v) {
  Possible p;
  p.exact = true;
  p.value = v;
  return p;
}

Possible inexact(Support s, bool random) {
  Possible p;
  p.support = std::move(s);
  p.random = random;
  return p;
}

struct Walker {
  const Expr& e;
  const BindingLookup& lookup;

  [[noreturn]] void fail_at(std::size_t i, const std::string& message) const {
    SourceLoc loc = e.loc(i);
    if (!loc.known()) loc = e.loc();
    throw EvaluationError{loc, message, {}};
  }

  // The number a value must be here (derive() fails on an axis).
  double number(std::size_t i, const Possible& p) const {
    if (!p.value.is_number()) fail_at(i, "expected a number here, found " + p.value.describe());
    return p.value.number();
  }

  Support numbers(std::size_t i, const Possible& p) const {
    if (!p.exact) return p.support;
    if (!p.value.is_number()) fail_at(i, "expected a number here, found " + p.value.describe());
    return Support::point(p.value.number());
  }

  Possible at(std::size_t i) const {
    const ExprNode& n = e.node(i);
    switch (n.kind) {
      case ExprKind::Number:
        return exact(Value(n.number));
      case ExprKind::Axis:
        return exact(Value::axis(static_cast<Axis>(n.op)));
      case ExprKind::Param:
      case ExprKind::Constant: {
        const Binding b = lookup(n.kind, n.index);
        if (b.known) return exact(b.value);
        return inexact(b.support, false);
      }
      case ExprKind::Unary:
        return unary(i, static_cast<UnaryOp>(n.op));
      case ExprKind::Binary:
        return binary(i, static_cast<BinaryOp>(n.op));
      case ExprKind::Call:
        return call(i, static_cast<Function>(n.op));
    }
    return {};
  }

  Possible unary(std::size_t i, UnaryOp op) const {
    const Possible c = at(i - 1);
    if (c.exact) {
      const double v = number(i - 1, c);
      return exact(Value(op == UnaryOp::Neg ? -v : (v == 0.0 ? 1.0 : 0.0)));
    }
    if (op == UnaryOp::Neg) return inexact(-c.support, c.random);
    const Truth t = truth(c.support);
    return inexact(from_truth(t.can_be_true, t.can_be_false), c.random);
  }

  Possible binary(std::size_t i, BinaryOp op) const {
    const std::size_t rhs = i - 1;
    const std::size_t lhs = rhs - e.node(rhs).size;
    if (op == BinaryOp::And || op == BinaryOp::Or) return logic(lhs, rhs, op == BinaryOp::And);
    const Possible a = at(lhs);
    const Possible b = at(rhs);
    const bool random = a.random || b.random;
    if (op == BinaryOp::Eq || op == BinaryOp::Ne) {
      // An axis equals the number that writes it, as in evaluate.cpp.
      if (a.exact && b.exact)
        return exact(Value((op == BinaryOp::Eq) == (a.value.number() == b.value.number()) ? 1.0 : 0.0));
      const Support sa = a.exact ? Support::point(a.value.number()) : a.support;
      const Support sb = b.exact ? Support::point(b.value.number()) : b.support;
      bool can_equal = false;
      for (const auto& [lo, hi] : sa.intervals)
        for (const auto& [lo2, hi2] : sb.intervals) can_equal = can_equal || (lo <= hi2 && lo2 <= hi);
      const bool can_differ = !(sa.is_point() && sb.is_point() && sa.lower() == sb.lower());
      return op == BinaryOp::Eq ? inexact(from_truth(can_differ, can_equal), random)
                                : inexact(from_truth(can_equal, can_differ), random);
    }
    if (a.exact && b.exact) {
      const double x = number(lhs, a);
      const double y = number(rhs, b);
      switch (op) {
        case BinaryOp::Add:
          return exact(Value(x + y));
        case BinaryOp::Sub:
          return exact(Value(x - y));
        case BinaryOp::Mul:
          return exact(Value(x * y));
        case BinaryOp::Div:
          if (y == 0.0) fail_at(i, "division by zero (" + format_number(x) + " / 0)");
          return exact(Value(x / y));
        case BinaryOp::Mod:
          if (y == 0.0) fail_at(i, "remainder by zero (" + format_number(x) + " % 0)");
          return exact(Value(std::fmod(x, y)));
        case BinaryOp::Lt:
          return exact(Value(x < y ? 1.0 : 0.0));
        case BinaryOp::Le:
          return exact(Value(x <= y ? 1.0 : 0.0));
        case BinaryOp::Gt:
          return exact(Value(x > y ? 1.0 : 0.0));
        case BinaryOp::Ge:
          return exact(Value(x >= y ? 1.0 : 0.0));
        default:
          break;
      }
    }
    const Support x = numbers(lhs, a);
    const Support y = numbers(rhs, b);
    switch (op) {
      case BinaryOp::Add:
        return inexact(x + y, random);
      case BinaryOp::Sub:
        return inexact(x - y, random);
      case BinaryOp::Mul:
        return inexact(x * y, random);
      case BinaryOp::Div:
        return inexact(x / y, random);
      case BinaryOp::Mod:
        return inexact(remainder(x, y), random);
      case BinaryOp::Lt:
        return inexact(from_truth(x.upper() >= y.lower(), x.lower() < y.upper()), random);
      case BinaryOp::Le:
        return inexact(from_truth(x.upper() > y.lower(), x.lower() <= y.upper()), random);
      case BinaryOp::Gt:
        return inexact(from_truth(x.lower() <= y.upper(), x.upper() > y.lower()), random);
      case BinaryOp::Ge:
        return inexact(from_truth(x.lower() < y.upper(), x.upper() >= y.lower()), random);
      default:
        break;
    }
    return {};
  }

  // && and || short-circuit in evaluate.cpp: a false left side of && draws
  // nothing on the right, so the result is exact.
  Possible logic(std::size_t lhs, std::size_t rhs, bool is_and) const {
    const Possible a = at(lhs);
    if (a.exact) {
      const bool v = number(lhs, a) != 0.0;
      if (v != is_and) return exact(Value(v ? 1.0 : 0.0));
      const Possible b = at(rhs);
      if (b.exact) return exact(Value(number(rhs, b) != 0.0 ? 1.0 : 0.0));
      const Truth t = truth(b.support);
      return inexact(from_truth(t.can_be_false, t.can_be_true), b.random);
    }
    const Possible b = at(rhs);
    const Truth ta = truth(a.support);
    const Truth tb = truth(numbers(rhs, b));
    if (is_and)
      return inexact(from_truth(ta.can_be_false || tb.can_be_false, ta.can_be_true && tb.can_be_true),
                     a.random || b.random);
    return inexact(from_truth(ta.can_be_false && tb.can_be_false, ta.can_be_true || tb.can_be_true),
                   a.random || b.random);
  }

  // size(axis): what the lookup says of the scope's size along the axis.
  Possible scope_size(std::size_t i) const {
    const Possible a = at(i - 1);
    if (!a.exact) throw NotCheckable{"size() of an axis drawn at random"};
    const auto axis = a.value.to_axis();
    if (!axis) fail_at(i, "size() takes an axis, found " + a.value.describe());
    const Binding b = lookup(kScopeSize, static_cast<std::uint32_t>(*axis));
    if (b.known) return exact(b.value);
    return inexact(b.support, false);
  }

  static Support remainder(const Support& x, const Support& y) {
    if (x.empty() || y.empty()) return {};
    const double m = std::max(std::abs(y.lower()), std::abs(y.upper()));
    const double lo = x.lower(), hi = x.upper();
    const double smallest_divisor = y.lower() > 0 ? y.lower() : (y.upper() < 0 ? -y.upper() : 0.0);
    // |a % b| < |b| and has the sign of a; a set already below every
    // divisor is left as it is.
    if (lo >= 0 && hi < smallest_divisor) return x;
    if (lo >= 0) return Support::range(0, std::min(hi, m));
    if (hi <= 0) return Support::range(-std::min(-lo, m), 0);
    return Support::range(-m, m);
  }

  Possible call(std::size_t i, Function f) const {
    if (f == Function::Size) return scope_size(i);
    const std::vector<std::size_t> roots = e.children(i);
    std::vector<Possible> args;
    args.reserve(roots.size());
    bool all_exact = true, random = function_info(f).random;
    for (std::size_t r : roots) {
      args.push_back(at(r));
      all_exact = all_exact && args.back().exact;
      random = random || args.back().random;
    }
    if (!function_info(f).random && all_exact) return exact(Value(deterministic(i, f, roots, args)));
    if (f == Function::Choice)
      for (const Possible& a : args)
        if (a.exact && !a.value.is_number()) throw NotCheckable{"choice() between axes draws an axis at random"};
    std::vector<Support> nums;
    for (std::size_t k = 0; k < args.size(); ++k) nums.push_back(numbers(roots[k], args[k]));
    auto num = [&](std::size_t k) -> const Support& { return nums[k]; };
    switch (f) {
      case Function::Min:
      case Function::Max: {
        double lo = num(0).lower(), hi = num(0).upper();
        for (std::size_t k = 1; k < args.size(); ++k) {
          lo = f == Function::Min ? std::min(lo, num(k).lower()) : std::max(lo, num(k).lower());
          hi = f == Function::Min ? std::min(hi, num(k).upper()) : std::max(hi, num(k).upper());
        }
        return inexact(Support::range(lo, hi), random);
      }
      case Function::Abs: {
        Intervals out;
        for (const auto& [lo, hi] : num(0).intervals) {
          if (lo >= 0)
            out.emplace_back(lo, hi);
          else if (hi <= 0)
            out.emplace_back(-hi, -lo);
          else
            out.emplace_back(0.0, std::max(-lo, hi));
        }
        return inexact(normalised(out, num(0).integer), random);
      }
      case Function::Floor:
      case Function::Ceil:
      case Function::Round: {
        double (*g)(double) = f == Function::Floor  ? static_cast<double (*)(double)>(std::floor)
                              : f == Function::Ceil ? static_cast<double (*)(double)>(std::ceil)
                                                    : static_cast<double (*)(double)>(std::round);
        Intervals out;
        for (const auto& [lo, hi] : num(0).intervals) out.emplace_back(g(lo), g(hi));
        return inexact(normalised(out, true), random);
      }
      case Function::Sqrt: {
        Intervals out;
        for (const auto& [lo, hi] : num(0).clamp(0, kInf).intervals) out.emplace_back(std::sqrt(lo), std::sqrt(hi));
        return inexact(normalised(out, false), random);
      }
      case Function::Sin:
      case Function::Cos:
        return inexact(Support::range(-1, 1), random);
      case Function::Rand: {
        if (args.empty()) return inexact(Support::range(0, 1), true);
        const Support& a = num(0);
        const Support& b = num(1);
        if (a.empty() || b.empty()) return inexact({}, true);
        return inexact(Support::range(std::min(a.lower(), b.lower()), std::max(a.upper(), b.upper())), true);
      }
      case Function::RandInt: {
        const Support& a = num(0);
        const Support& b = num(1);
        if (args[0].exact && args[1].exact && std::floor(b.lower()) < std::ceil(a.lower()))
          fail_at(i, "randint(" + format_number(std::ceil(a.lower())) + ", " + format_number(std::floor(b.lower())) +
                         ") has no whole number in range");
        if (a.empty() || b.empty()) return inexact({}, true);
        return inexact(Support::integers(a.lower(), b.upper()), true);
      }
      case Function::Normal: {
        if (args[1].exact && num(1).lower() < 0)
          fail_at(i, "normal() needs sigma >= 0, got " + format_number(num(1).lower()));
        if (args[1].exact && num(1).lower() == 0) return inexact(num(0), true);
        return inexact(Support::everything(), true);
      }
      case Function::TNormal: {
        const Support& lo = num(2);
        const Support& hi = num(3);
        if (args[2].exact && args[3].exact && hi.lower() < lo.lower())
          fail_at(i, "tnormal() needs lo <= hi, got " + format_number(lo.lower()) + " > " + format_number(hi.lower()));
        if (lo.empty() || hi.empty()) return inexact({}, true);
        return inexact(Support::range(lo.lower(), hi.upper()), true);
      }
      case Function::Choice: {
        Support all;
        for (std::size_t k = 0; k < args.size(); ++k) all = all.unite(num(k));
        return inexact(all, true);
      }
      case Function::Size: break;  // answered above
    }
    return {};
  }

  // The deterministic functions, exactly as evaluate.cpp computes them.
  double deterministic(std::size_t i, Function f, const std::vector<std::size_t>& roots,
                       const std::vector<Possible>& args) const {
    auto v = [&](std::size_t k) { return number(roots[k], args[k]); };
    switch (f) {
      case Function::Min:
      case Function::Max: {
        double best = v(0);
        for (std::size_t k = 1; k < args.size(); ++k)
          best = f == Function::Min ? std::min(best, v(k)) : std::max(best, v(k));
        return best;
      }
      case Function::Abs:
        return std::abs(v(0));
      case Function::Floor:
        return std::floor(v(0));
      case Function::Ceil:
        return std::ceil(v(0));
      case Function::Round:
        return std::round(v(0));
      case Function::Sqrt:
        if (v(0) < 0) fail_at(i, "sqrt of a negative number (" + format_number(v(0)) + ")");
        return std::sqrt(v(0));
      case Function::Sin:
        return std::sin(v(0));
      case Function::Cos:
        return std::cos(v(0));
      default:
        return 0.0;
    }
  }
};

std::string short_number(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

}  // namespace

Support Support::point(double v) { return normalised({{v, v}}, false); }

Support Support::range(double lo, double hi) { return normalised({{lo, hi}}, false); }

Support Support::integers(double lo, double hi) { return normalised({{lo, hi}}, true); }

Support Support::everything() { return normalised({{-kInf, kInf}}, false); }

Support Support::points(const std::vector<double>& values) {
  Intervals v;
  v.reserve(values.size());
  for (double x : values) v.emplace_back(x, x);
  return normalised(std::move(v), false);
}

bool Support::empty() const { return intervals.empty(); }

double Support::lower() const { return intervals.empty() ? kInf : intervals.front().first; }

double Support::upper() const { return intervals.empty() ? -kInf : intervals.back().second; }

bool Support::bounded() const { return !empty() && std::isfinite(lower()) && std::isfinite(upper()); }

bool Support::contains(double v, double tolerance) const {
  for (const auto& [lo, hi] : intervals) {
    if (v < lo - tolerance || v > hi + tolerance) continue;
    if (!integer) return true;
    // A whole number within the interval and within tolerance of v.
    const double k = std::clamp(std::round(v), lo, hi);
    if (std::abs(k - v) <= tolerance) return true;
  }
  return false;
}

std::optional<std::vector<double>> Support::values(std::size_t max_count) const {
  std::vector<double> out;
  for (const auto& [lo, hi] : intervals) {
    if (lo != hi && !integer) return std::nullopt;
    if (!std::isfinite(lo) || !std::isfinite(hi)) return std::nullopt;
    if (hi - lo + 1 > static_cast<double>(max_count)) return std::nullopt;
    for (double k = lo; k <= hi; k += 1) {
      if (out.size() >= max_count) return std::nullopt;
      out.push_back(k);
    }
  }
  return out;
}

Support Support::clamp(double lo, double hi) const {
  Intervals out;
  for (const auto& [a, b] : intervals)
    if (b >= lo && a <= hi) out.emplace_back(std::max(a, lo), std::min(b, hi));
  return normalised(std::move(out), integer);
}

Support Support::unite(const Support& other) const {
  if (empty()) return other;
  if (other.empty()) return *this;
  // Both lists are sorted and disjoint already: one merge pass, joining
  // what overlaps, in linear time (sorting the concatenation again was
  // most of inferring 37 CMP facades, whose checks unite thousands of
  // lengths one by one). A whole-number set joined with a continuous one
  // widens to its intervals; two whole-number sets stay one, and cannot
  // shrink below the expansion size, since neither was expanded.
  Support s;
  s.integer = integer && other.integer;
  s.intervals.reserve(intervals.size() + other.intervals.size());
  std::size_t i = 0, j = 0;
  while (i < intervals.size() || j < other.intervals.size()) {
    const bool mine = j == other.intervals.size() || (i < intervals.size() && intervals[i] < other.intervals[j]);
    const Interval& iv = mine ? intervals[i++] : other.intervals[j++];
    if (!s.intervals.empty() && iv.first <= s.intervals.back().second)
      s.intervals.back().second = std::max(s.intervals.back().second, iv.second);
    else
      s.intervals.push_back(iv);
  }
  if (s.intervals.size() > kMaxIntervals) s.intervals = {{s.intervals.front().first, s.intervals.back().second}};
  return s;
}

Support Support::intersect(const Support& other) const {
  Intervals out;
  std::size_t i = 0, j = 0;
  while (i < intervals.size() && j < other.intervals.size()) {
    const auto& a = intervals[i];
    const auto& b = other.intervals[j];
    const double lo = std::max(a.first, b.first), hi = std::min(a.second, b.second);
    if (lo <= hi) out.emplace_back(lo, hi);
    (a.second < b.second ? i : j) += 1;
  }
  return normalised(std::move(out), integer || other.integer);
}

std::string Support::describe() const {
  if (empty()) return "no value";
  if (is_point()) return short_number(lower());
  if (auto v = values(8)) {
    std::string t = "{";
    for (std::size_t k = 0; k < v->size(); ++k) t += (k ? ", " : "") + short_number((*v)[k]);
    return t + "}";
  }
  std::string t;
  for (std::size_t k = 0; k < intervals.size() && k < 4; ++k) {
    const auto& [lo, hi] = intervals[k];
    t += (k ? " u " : "");
    t += lo == hi ? short_number(lo) : "[" + short_number(lo) + ", " + short_number(hi) + "]";
  }
  if (intervals.size() > 4) t += " u ...";
  return integer ? "whole numbers in " + t : t;
}

Support operator+(const Support& x, const Support& y) {
  return combine(x, y, true, [](const Interval& a, const Interval& b, Intervals& out) {
    out.emplace_back(a.first + b.first, a.second + b.second);
  });
}

Support operator-(const Support& x, const Support& y) {
  return combine(x, y, true, [](const Interval& a, const Interval& b, Intervals& out) {
    out.emplace_back(a.first - b.second, a.second - b.first);
  });
}

Support operator*(const Support& x, const Support& y) {
  return combine(x, y, true,
                 [](const Interval& a, const Interval& b, Intervals& out) { out.push_back(mul(a, b)); });
}

Support operator/(const Support& x, const Support& y) {
  return combine(x, y, false, [](const Interval& a, const Interval& b, Intervals& out) {
    if (b.first < 0 && b.second > 0) {
      divide(a, b.first, 0.0, out);
      divide(a, 0.0, b.second, out);
    } else if (!(b.first == 0 && b.second == 0)) {
      divide(a, b.first, b.second, out);
    }
  });
}

Support operator-(const Support& x) {
  Intervals out;
  for (const auto& [lo, hi] : x.intervals) out.emplace_back(-hi, -lo);
  return normalised(std::move(out), x.integer);
}

Possible possible_values(const Expr& e, const BindingLookup& lookup) {
  if (e.empty()) return {};
  Possible p = Walker{e, lookup}.at(e.root());
  if (p.exact && p.value.is_number()) p.support = Support::point(p.value.number());
  return p;
}

Support expression_support(const Expr& e, const BindingLookup& lookup) { return possible_values(e, lookup).support; }

}  // namespace vern
