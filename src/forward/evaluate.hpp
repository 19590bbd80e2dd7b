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
};

Value evaluate(const Expr& e, const EvalContext& ctx);

// A number that must be finite; `what` names it in the message ("the size
// of a split part"). Axes and NaN/inf are EvaluationErrors.
double evaluate_number(const Expr& e, const EvalContext& ctx, const char* what);

// An axis (x/y/z or 0/1/2).
Axis evaluate_axis(const Expr& e, const EvalContext& ctx, const char* what);

}  // namespace vern
