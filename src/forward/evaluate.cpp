#include "forward/evaluate.hpp"

#include <cmath>

#include "graph/number_format.hpp"

namespace vern {

namespace {

class Evaluator {
 public:
  Evaluator(const Expr& e, const EvalContext& ctx) : e_(e), ctx_(ctx) {}

  Value at(std::size_t i) {
    const ExprNode& n = e_.node(i);
    switch (n.kind) {
      case ExprKind::Number: return n.number;
      case ExprKind::Axis: return Value::axis(static_cast<Axis>(n.op));
      case ExprKind::Constant: return ctx_.constants[n.index];
      case ExprKind::Param: return ctx_.params[n.index];
      case ExprKind::Unary: {
        const double v = number(i - 1, i);
        return static_cast<UnaryOp>(n.op) == UnaryOp::Neg ? -v : (v == 0.0 ? 1.0 : 0.0);
      }
      case ExprKind::Binary: return binary(i, static_cast<BinaryOp>(n.op));
      case ExprKind::Call: return call(i, static_cast<Function>(n.op));
    }
    return 0.0;
  }

 private:
  double number(std::size_t child, std::size_t parent) {
    const Value v = at(child);
    if (!v.is_number()) {
      fail_at(e_.loc(child).known() ? e_.loc(child) : e_.loc(parent),
              "expected a number here, found " + v.describe(), "axes can only be compared with == and !=");
    }
    return v.number();
  }

  [[noreturn]] void fail_at(SourceLoc loc, std::string message, std::string hint = {}) {
    throw EvaluationError{loc.known() ? loc : e_.loc(), std::move(message), std::move(hint)};
  }

  Value binary(std::size_t i, BinaryOp op) {
    const std::size_t rhs = i - 1;
    const std::size_t lhs = rhs - e_.node(rhs).size;
    switch (op) {
      case BinaryOp::And: return number(lhs, i) != 0.0 && number(rhs, i) != 0.0 ? 1.0 : 0.0;
      case BinaryOp::Or: return number(lhs, i) != 0.0 || number(rhs, i) != 0.0 ? 1.0 : 0.0;
      case BinaryOp::Eq:
      case BinaryOp::Ne: {
        // An axis equals the number that writes it (x == 0), so parameters
        // passed as 0/1/2 compare as the thesis grammars expect.
        const Value a = at(lhs);
        const Value b = at(rhs);
        const bool equal = a.number() == b.number();
        return (op == BinaryOp::Eq) == equal ? 1.0 : 0.0;
      }
      default: break;
    }
    const double a = number(lhs, i);
    const double b = number(rhs, i);
    switch (op) {
      case BinaryOp::Add: return a + b;
      case BinaryOp::Sub: return a - b;
      case BinaryOp::Mul: return a * b;
      case BinaryOp::Div:
        if (b == 0.0) fail_at(e_.loc(i), "division by zero (" + format_number(a) + " / 0)");
        return a / b;
      case BinaryOp::Mod:
        if (b == 0.0) fail_at(e_.loc(i), "remainder by zero (" + format_number(a) + " % 0)");
        return std::fmod(a, b);
      case BinaryOp::Lt: return a < b ? 1.0 : 0.0;
      case BinaryOp::Le: return a <= b ? 1.0 : 0.0;
      case BinaryOp::Gt: return a > b ? 1.0 : 0.0;
      case BinaryOp::Ge: return a >= b ? 1.0 : 0.0;
      default: return 0.0;
    }
  }

  Value call(std::size_t i, Function f) {
    std::size_t roots[8];
    const std::size_t argc = e_.children(i, roots, 8);
    auto arg = [&](std::size_t k) { return number(k < 8 ? roots[k] : nth_child(i, k), i); };
    const SourceLoc loc = e_.loc(i);
    switch (f) {
      case Function::Min:
      case Function::Max: {
        double best = arg(0);
        for (std::size_t k = 1; k < argc; ++k) best = f == Function::Min ? std::min(best, arg(k)) : std::max(best, arg(k));
        return best;
      }
      case Function::Abs: return std::abs(arg(0));
      case Function::Floor: return std::floor(arg(0));
      case Function::Ceil: return std::ceil(arg(0));
      case Function::Round: return std::round(arg(0));
      case Function::Sqrt: {
        const double v = arg(0);
        if (v < 0) fail_at(loc, "sqrt of a negative number (" + format_number(v) + ")");
        return std::sqrt(v);
      }
      case Function::Sin: return std::sin(arg(0));
      case Function::Cos: return std::cos(arg(0));
      case Function::Rand: {
        if (argc == 0) return ctx_.random->uniform();
        const double a = arg(0), b = arg(1);
        return ctx_.random->uniform(a, b);
      }
      case Function::RandInt: {
        const double a = std::ceil(arg(0)), b = std::floor(arg(1));
        if (b < a) fail_at(loc, "randint(" + format_number(a) + ", " + format_number(b) + ") has no whole number in range");
        const double n = std::floor(ctx_.random->uniform() * (b - a + 1));
        return std::min(a + n, b);
      }
      case Function::Normal: {
        const double mu = arg(0), sigma = arg(1);
        if (sigma < 0) fail_at(loc, "normal() needs sigma >= 0, got " + format_number(sigma));
        return mu + sigma * ctx_.random->normal();
      }
      case Function::TNormal: {
        const double mu = arg(0), sigma = arg(1), lo = arg(2), hi = arg(3);
        if (sigma < 0) fail_at(loc, "tnormal() needs sigma >= 0, got " + format_number(sigma));
        if (hi < lo) fail_at(loc, "tnormal() needs lo <= hi, got " + format_number(lo) + " > " + format_number(hi));
        return ctx_.random->truncated_normal(mu, sigma, lo, hi);
      }
      case Function::Choice: {
        const auto k = static_cast<std::size_t>(std::floor(ctx_.random->uniform() * static_cast<double>(argc)));
        const std::size_t pick = std::min(k, argc - 1);
        return at(pick < 8 ? roots[pick] : nth_child(i, pick));
      }
    }
    return 0.0;
  }

  std::size_t nth_child(std::size_t i, std::size_t k) const { return e_.children(i)[k]; }

  const Expr& e_;
  const EvalContext& ctx_;
};

}  // namespace

Value evaluate(const Expr& e, const EvalContext& ctx) {
  const ExprNode& root = e.node(e.root());
  switch (root.kind) {  // the common cases, without setting up an Evaluator
    case ExprKind::Number: return root.number;
    case ExprKind::Param: return ctx.params[root.index];
    case ExprKind::Constant: return ctx.constants[root.index];
    default: return Evaluator(e, ctx).at(e.root());
  }
}

double evaluate_number_slow(const Expr& e, const EvalContext& ctx, const char* what) {
  const Value v = evaluate(e, ctx);
  if (!v.is_number())
    throw EvaluationError{e.loc(), std::string(what) + " must be a number, found " + v.describe(), {}};
  if (!std::isfinite(v.number()))
    throw EvaluationError{e.loc(), std::string(what) + " is " + format_number(v.number()) + ", not a finite number", {}};
  return v.number();
}

Axis evaluate_axis_slow(const Expr& e, const EvalContext& ctx, const char* what) {
  const Value v = evaluate(e, ctx);
  if (auto a = v.to_axis()) return *a;
  throw EvaluationError{e.loc(), std::string(what) + " must be an axis, found " + v.describe(),
                        "an axis is x, y or z (or 0, 1, 2)"};
}

}  // namespace vern
