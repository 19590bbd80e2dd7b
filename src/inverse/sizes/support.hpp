// The support of a grammar expression: every value it can take.
//
// Checking a grammar against an example (check.hpp) and fitting sizes both
// ask "could this expression have produced that number?" without running
// the random draws. The answer is the expression's support: a literal is
// one value, rand(a, b) the interval [a, b], randint(a, b) the whole numbers
// in it, choice(...) its arguments, and arithmetic combines supports by
// interval arithmetic. That is exact when each random draw appears once in
// the expression (every draw of a grammar expression is a fresh, independent
// one, so `rand() - rand()` is [-1, 1]); a value used twice (a parameter
// that was itself drawn) is treated as two independent values, an
// over-approximation that check.cpp avoids by solving for such values.
//
// Deterministic subexpressions are computed with exactly the operations of
// forward/evaluate.cpp, so a size that derive() computes as 6.666666666666667
// has the same single value here.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/inline_list.hpp"
#include "graph/expr.hpp"
#include "graph/value.hpp"

namespace vern {

// Sorted, disjoint, closed intervals; almost always one, held in place.
using Intervals = InlineList<std::pair<double, double>, 1>;

struct Support {
  // Sorted, disjoint, closed intervals; a single value v is {v, v}.
  // Bounds may be infinite. No intervals: no value at all.
  Intervals intervals;
  // Only the whole numbers within the intervals (randint and what is
  // computed from it). Small integer sets are kept as single points instead.
  bool integer = false;

  static Support point(double v);
  static Support range(double lo, double hi);  // [min(lo, hi), max(lo, hi)]
  static Support integers(double lo, double hi);
  static Support everything();
  static Support none() { return {}; }
  // The union of these values (any order, duplicates allowed).
  static Support points(const std::vector<double>& values);

  bool empty() const;
  double lower() const;  // +inf when empty
  double upper() const;  // -inf when empty
  bool is_point() const { return !empty() && lower() == upper(); }
  bool bounded() const;
  // Is v (within tolerance) one of the values?
  bool contains(double v, double tolerance = 0) const;
  // The values, when there are at most max_count of them (single points or
  // whole numbers of small ranges); nothing when the set is continuous or larger.
  std::optional<std::vector<double>> values(std::size_t max_count = 64) const;
  // The values within [lo, hi].
  Support clamp(double lo, double hi) const;
  Support unite(const Support& other) const;
  // The values in both sets.
  Support intersect(const Support& other) const;
  // "3", "[0.75, 1.25]", "{2, 3, 4}", "whole numbers in [1, 100]": for messages.
  std::string describe() const;

  friend bool operator==(const Support&, const Support&) = default;
};

// Interval arithmetic: the set of a op b for a in x, b in y. Division by a
// set holding 0 leaves 0 out (derive() fails there: no value results).
Support operator+(const Support& x, const Support& y);
Support operator-(const Support& x, const Support& y);
Support operator*(const Support& x, const Support& y);
Support operator/(const Support& x, const Support& y);
Support operator-(const Support& x);

// What a parameter or constant stands for while checking: a known value
// (a number or an axis), or any number of a support.
struct Binding {
  bool known = true;
  Value value;
  Support support;  // when !known
};

// Looks up a name: kind is ExprKind::Param or ExprKind::Constant, index its
// slot; or, kind kScopeSize, the size of the scope the expression stands in
// along axis `index` (size(axis)): known where the scope is, else a support.
using BindingLookup = std::function<Binding(ExprKind kind, std::uint32_t index)>;
inline constexpr ExprKind kScopeSize = ExprKind::Call;

// The values an expression can take. `exact`: no draw and no unknown name
// took part, and `value` is what derive() computes. Otherwise `support`
// holds every possible number (`random` says whether a draw took part).
struct Possible {
  bool exact = false;
  bool random = false;
  Value value;      // when exact
  Support support;  // numbers: always set (a point when exact)
};

// Thrown when an expression cannot be checked this way (a random axis:
// choice(x, y)); the message says what.
struct NotCheckable {
  std::string message;
};

// Throws EvaluationError (forward/evaluate.hpp) where derive() would fail
// whatever the draws (division by a literal zero, a number used as an
// axis...), NotCheckable for what supports cannot express.
Possible possible_values(const Expr& e, const BindingLookup& lookup);

// The numeric support of an expression (the exact value as a point).
Support expression_support(const Expr& e, const BindingLookup& lookup);

}  // namespace vern
