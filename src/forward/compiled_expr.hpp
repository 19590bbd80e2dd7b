// Expressions compiled for derivation: literals answered without a look,
// the rest as straight-line code for a small stack machine.
//
// The tree evaluator (forward/evaluate.hpp) walks an Expr recursively and
// checks every type on the way; derivation evaluates some thirty expression
// nodes per terminal, so that walk was a third of its time. Compiling once
// per grammar folds constant subtrees, resolves which operand may be an
// axis, and leaves typed instructions that a loop runs over a stack of
// doubles.
//
// The compiled code is a fast path only, never a second definition of the
// language: where the tree evaluator would fail (an axis where a number
// belongs, division by zero, a non-finite result, ...) the code stops and
// reports nothing, and the caller runs the tree evaluator again from the
// same random state, which computes the same values and throws its message.
// Expressions the code does not cover (choice()) always take that path.
// Both do the same floating-point operations in the same order, so results
// are bit-identical.
#pragma once

#include <cstdint>
#include <vector>

#include "forward/random_stream.hpp"
#include "graph/expr.hpp"

namespace vern {

enum class Instr : std::uint8_t {
  Number,         // push number
  Param,          // push the parameter's number (stop if it is an axis)
  Constant,       // push the constant's number (stop if it is an axis)
  ParamValue,     // push the parameter's number, axes as 0/1/2 (operands of == and !=)
  ConstantValue,  // the same for a constant
  Neg, Not,
  Add, Sub, Mul, Div, Mod, Eq, Ne, Lt, Le, Gt, Ge,
  AndJump,  // top false: replace by 0 and skip `index` instructions; else pop
  OrJump,   // top true: replace by 1 and skip `index` instructions; else pop
  Truth,    // top != 0 ? 1 : 0
  Abs, Floor, Ceil, Round, Sqrt, Sin, Cos,
  Min, Max,  // reduce the top `index` values, left to right
  Uniform,   // rand()
  Rand, RandInt, Normal, TNormal,
  End,
};

struct Instruction {
  Instr op = Instr::End;
  std::uint32_t index = 0;  // slot, jump length or argument count, by op
  double number = 0.0;      // Number: the value
};

// How a compiled expression is answered.
enum class ExprForm : std::uint8_t {
  Absent,    // no expression (a choose option without a condition)
  Literal,   // `literal`: a finite number known when compiling
  Axis,      // `index` is the Axis (value context only)
  Param,     // the parameter in slot `index`
  Constant,  // the constant in slot `index`
  Code,      // instructions from `index` in the owning ExprCode
  Slow,      // the tree evaluator only
};

struct CompiledExpr {
  ExprForm form = ExprForm::Absent;
  std::uint32_t index = 0;
  double literal = 0.0;
  const Expr* source = nullptr;  // for the tree evaluator and messages
};

// The instructions of many expressions, one after another.
class ExprCode {
 public:
  // Where a number is expected (sizes, counts, conditions, priorities):
  // Literal only for a finite number, as the caller checks nothing more.
  CompiledExpr number(const Expr& e);
  // Where any value may stand (rule arguments): axes pass through and
  // numbers are not checked for finiteness, as evaluate() does.
  CompiledExpr value(const Expr& e);
  // Where an axis is expected: the Axis form when the expression is one
  // (or a literal 0, 1, 2), else Slow.
  static CompiledExpr axis(const Expr& e);

  const Instruction* at(std::uint32_t index) const { return code_.data() + index; }
  std::size_t size() const { return code_.size(); }

 private:
  CompiledExpr code(const Expr& e, bool value_context);
  std::vector<Instruction> code_;
};

// Runs the code at pc. False, with the stream possibly advanced, where the
// tree evaluator must take over (see the top of this file); the result is
// not checked for finiteness.
bool run(const Instruction* pc, const Value* params, const Value* constants, RandomStream& random, double& result);

}  // namespace vern
