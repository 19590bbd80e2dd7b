// Evaluating expressions during a derivation.
#pragma once

#include <string>

#include "forward/random_stream.hpp"
#include "graph/expr.hpp"

namespace vern {

// Thrown by evaluation; the derivation adds the file name and rule chain
// before it reaches the user as a vern::Error.
struct EvaluationError {
  SourceLoc loc;
  std::string message;
  std::string hint;
};

struct EvalContext {
  const Value* params = nullptr;     // the running rule's arguments
  const Value* constants = nullptr;  // this derivation's constant values
  RandomStream* random = nullptr;    // the running node's stream
  // The size of the scope the expression stands in (x, y, z), for
  // size(axis); none in constants and @scope, evaluated before any scope.
  const double* scope_size = nullptr;
};

Value evaluate(const Expr& e, const EvalContext& ctx);

// The general cases of the two functions below.
double evaluate_number_slow(const Expr& e, const EvalContext& ctx, const char* what);
Axis evaluate_axis_slow(const Expr& e, const EvalContext& ctx, const char* what);

// A number that must be finite; `what` names it in the message ("the size
// of a split part"). Axes and NaN/inf are EvaluationErrors. Literals, most
// of what grammars hold, are answered inline.
inline double evaluate_number(const Expr& e, const EvalContext& ctx, const char* what) {
  const ExprNode& root = e.nodes().back();
  if (root.size == 1) {  // a literal, a parameter or a constant
    if (root.kind == ExprKind::Number) return root.number;
    const Value* v = root.kind == ExprKind::Param ? &ctx.params[root.index]
                     : root.kind == ExprKind::Constant ? &ctx.constants[root.index]
                                                       : nullptr;
    // NaN and inf fail the comparison and take the slow path's message.
    if (v && v->is_number() && v->number() - v->number() == 0.0) return v->number();
  }
  return evaluate_number_slow(e, ctx, what);
}

// An axis (x/y/z or 0/1/2).
inline Axis evaluate_axis(const Expr& e, const EvalContext& ctx, const char* what) {
  const ExprNode& root = e.nodes().back();
  if (root.kind == ExprKind::Axis) return static_cast<Axis>(root.op);
  return evaluate_axis_slow(e, ctx, what);
}

}  // namespace vern
