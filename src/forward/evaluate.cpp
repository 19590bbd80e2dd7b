#include "forward/evaluate.hpp"

#include <cmath>
#include <vector>

#include "base/number_format.hpp"

namespace vern {

namespace {

// A tree walk over the flat node array. Numbers stay unboxed on the hot
// path (num); Values, which may be axes, appear only where an axis can
// stand: ==, !=, choice() and the top level (val).
//
// Operands are always evaluated left to right, so the random draws of
// `rand() - rand()` happen in one order on every compiler.
struct Evaluator {
  const ExprNode* n;
  const Expr& e;
  const EvalContext& ctx;

  [[noreturn]] void fail_at(std::size_t i, std::string message, std::string hint = {}) const {
    SourceLoc loc = e.loc(i);
    if (!loc.known()) loc = e.loc();
    throw EvaluationError{loc, std::move(message), std::move(hint)};
  }

  [[noreturn]] void not_a_number(std::size_t i, const Value& v) const {
    fail_at(i, "expected a number here, found " + v.describe(), "axes can only be compared with == and !=");
  }

  double num(std::size_t i) const {
    const ExprNode& x = n[i];
    switch (x.kind) {
      case ExprKind::Number: return x.number;
      case ExprKind::Param: {
        const Value& v = ctx.params[x.index];
        if (v.is_number()) return v.number();
        not_a_number(i, v);
      }
      case ExprKind::Constant: {
        const Value& v = ctx.constants[x.index];
        if (v.is_number()) return v.number();
        not_a_number(i, v);
      }
      case ExprKind::Axis: not_a_number(i, Value::axis(static_cast<Axis>(x.op)));
      case ExprKind::Unary: {
        const double v = num(i - 1);
        return static_cast<UnaryOp>(x.op) == UnaryOp::Neg ? -v : (v == 0.0 ? 1.0 : 0.0);
      }
      case ExprKind::Binary: return binary(i, static_cast<BinaryOp>(x.op));
      case ExprKind::Call: {
        if (static_cast<Function>(x.op) == Function::Choice) {
          const Value v = choice(i);
          if (v.is_number()) return v.number();
          not_a_number(i, v);
        }
        if (static_cast<Function>(x.op) == Function::Size) return scope_size(i);
        return call(i, static_cast<Function>(x.op));
      }
    }
    return 0.0;
  }

  Value val(std::size_t i) const {
    const ExprNode& x = n[i];
    switch (x.kind) {
      case ExprKind::Axis: return Value::axis(static_cast<Axis>(x.op));
      case ExprKind::Param: return ctx.params[x.index];
      case ExprKind::Constant: return ctx.constants[x.index];
      case ExprKind::Call:
        if (static_cast<Function>(x.op) == Function::Choice) return choice(i);
        return num(i);
      default: return num(i);
    }
  }

  double binary(std::size_t i, BinaryOp op) const {
    const std::size_t rhs = i - 1;
    const std::size_t lhs = rhs - n[rhs].size;
    switch (op) {
      case BinaryOp::And: return num(lhs) != 0.0 && num(rhs) != 0.0 ? 1.0 : 0.0;
      case BinaryOp::Or: return num(lhs) != 0.0 || num(rhs) != 0.0 ? 1.0 : 0.0;
      case BinaryOp::Eq:
      case BinaryOp::Ne: {
        // An axis equals the number that writes it (x == 0), so parameters
        // passed as 0/1/2 compare as the thesis grammars expect.
        const Value a = val(lhs);
        const Value b = val(rhs);
        return (op == BinaryOp::Eq) == (a.number() == b.number()) ? 1.0 : 0.0;
      }
      default: break;
    }
    const double a = num(lhs);
    const double b = num(rhs);
    switch (op) {
      case BinaryOp::Add: return a + b;
      case BinaryOp::Sub: return a - b;
      case BinaryOp::Mul: return a * b;
      case BinaryOp::Div:
        if (b == 0.0)
          fail_at(i, "division by zero (" + format_number(a) + " / 0)", "guard the divisor, e.g. a / max(b, 0.001)");
        return a / b;
      case BinaryOp::Mod:
        if (b == 0.0)
          fail_at(i, "remainder by zero (" + format_number(a) + " % 0)", "guard the divisor, e.g. a % max(b, 1)");
        return std::fmod(a, b);
      case BinaryOp::Lt: return a < b ? 1.0 : 0.0;
      case BinaryOp::Le: return a <= b ? 1.0 : 0.0;
      case BinaryOp::Gt: return a > b ? 1.0 : 0.0;
      case BinaryOp::Ge: return a >= b ? 1.0 : 0.0;
      default: return 0.0;
    }
  }

  // Roots of node i's children, in order; returns how many (at most 8
  // stored: only min, max and choice take more, and they walk again).
  std::size_t roots(std::size_t i, std::size_t* out) const { return e.children(i, out, 8); }
  std::size_t nth(std::size_t i, std::size_t k, const std::size_t* r) const { return k < 8 ? r[k] : e.children(i)[k]; }

  Value choice(std::size_t i) const {
    std::size_t r[8];
    const std::size_t argc = roots(i, r);
    const auto k = static_cast<std::size_t>(std::floor(ctx.random->uniform() * static_cast<double>(argc)));
    return val(nth(i, std::min(k, argc - 1), r));
  }

  // size(axis): the scope's size along the axis its one argument names.
  double scope_size(std::size_t i) const {
    const Value a = val(i - 1);
    const auto axis = a.to_axis();
    if (!axis) fail_at(i, "size() takes an axis, found " + a.describe(), "write size(x), size(y) or size(z)");
    if (!ctx.scope_size)
      fail_at(i, "size() reads the size of the scope it stands in, and here there is none",
              "constants and @scope are evaluated before any scope: use size() in a rule");
    return ctx.scope_size[static_cast<std::size_t>(*axis)];
  }

  double call(std::size_t i, Function f) const {
    const std::size_t argc = n[i].argc;
    // Fixed-arity functions find their arguments without a walk: the last
    // argument ends right before the call, each one before the next.
    if (argc == 1) {
      const double v = num(i - 1);
      switch (f) {
        case Function::Abs: return std::abs(v);
        case Function::Floor: return std::floor(v);
        case Function::Ceil: return std::ceil(v);
        case Function::Round: return std::round(v);
        case Function::Sqrt:
          if (v < 0) fail_at(i, "sqrt of a negative number (" + format_number(v) + ")", "write sqrt(max(0, v)) or sqrt(abs(v))");
          return std::sqrt(v);
        case Function::Sin: return std::sin(v);
        case Function::Cos: return std::cos(v);
        case Function::Min:
        case Function::Max: return v;
        default: break;
      }
    }
    if (argc == 0) return ctx.random->uniform();  // rand()
    std::size_t r[8];
    roots(i, r);
    switch (f) {
      case Function::Min:
      case Function::Max: {
        // Past 8 arguments, all their roots in one walk: a walk per
        // argument made min() of 65,535 arguments take seconds each time.
        std::vector<std::size_t> all;
        if (argc > 8) all = e.children(i);
        const std::size_t* at = argc > 8 ? all.data() : r;
        double best = num(at[0]);
        for (std::size_t k = 1; k < argc; ++k) {
          const double v = num(at[k]);
          best = f == Function::Min ? std::min(best, v) : std::max(best, v);
        }
        return best;
      }
      case Function::Rand: {
        const double a = num(r[0]);
        const double b = num(r[1]);
        return ctx.random->uniform(a, b);
      }
      case Function::RandInt: {
        const double a = std::ceil(num(r[0]));
        const double b = std::floor(num(r[1]));
        if (b < a)
          fail_at(i, "randint(" + format_number(a) + ", " + format_number(b) + ") has no whole number in range",
                  "randint(a, b) needs a whole number between a and b; for any number use rand(a, b)");
        return std::min(a + std::floor(ctx.random->uniform() * (b - a + 1)), b);
      }
      case Function::Normal: {
        const double mu = num(r[0]);
        const double sigma = num(r[1]);
        if (sigma < 0) fail_at(i, "normal() needs sigma >= 0, got " + format_number(sigma), "write normal(mu, abs(sigma))");
        return mu + sigma * ctx.random->normal();
      }
      case Function::TNormal: {
        const double mu = num(r[0]);
        const double sigma = num(r[1]);
        const double lo = num(r[2]);
        const double hi = num(r[3]);
        if (sigma < 0)
          fail_at(i, "tnormal() needs sigma >= 0, got " + format_number(sigma), "write tnormal(mu, abs(sigma), lo, hi)");
        if (hi < lo)
          fail_at(i, "tnormal() needs lo <= hi, got " + format_number(lo) + " > " + format_number(hi),
                  "swap the bounds: tnormal(mu, sigma, lo, hi)");
        return ctx.random->truncated_normal(mu, sigma, lo, hi);
      }
      default: return 0.0;  // one-argument functions were answered above
    }
  }
};

}  // namespace

Value evaluate(const Expr& e, const EvalContext& ctx) {
  return Evaluator{e.nodes().data(), e, ctx}.val(e.root());
}

double evaluate_number_slow(const Expr& e, const EvalContext& ctx, const char* what) {
  const ExprNode& root = e.node(e.root());
  // Operators and functions other than choice() can only give numbers:
  // evaluate them unboxed. Names and choice() may give an axis.
  const bool surely_number = root.kind == ExprKind::Unary || root.kind == ExprKind::Binary ||
                             (root.kind == ExprKind::Call && static_cast<Function>(root.op) != Function::Choice);
  double v;
  if (surely_number) {
    v = Evaluator{e.nodes().data(), e, ctx}.num(e.root());
  } else {
    const Value value = evaluate(e, ctx);
    if (!value.is_number())
      throw EvaluationError{e.loc(), std::string(what) + " must be a number, found " + value.describe(),
                            "axes can only be compared with == and !="};
    v = value.number();
  }
  if (!std::isfinite(v))
    throw EvaluationError{e.loc(),
                          std::string(what) + " is " + (std::isnan(v) ? std::string("NaN") : format_number(v)) +
                              ", not a finite number",
                          "an operation overflowed (inf) or had no result (NaN, e.g. inf - inf): check the values "
                          "in the chain above"};
  return v;
}

Axis evaluate_axis_slow(const Expr& e, const EvalContext& ctx, const char* what) {
  const Value v = evaluate(e, ctx);
  if (auto a = v.to_axis()) return *a;
  throw EvaluationError{e.loc(), std::string(what) + " must be an axis, found " + v.describe(),
                        "an axis is x, y or z (or 0, 1, 2)"};
}

}  // namespace vern
