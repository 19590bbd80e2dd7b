#include "forward/compiled_expr.hpp"

#include <algorithm>
#include <cmath>

namespace vern {

namespace {

// The arithmetic of forward/evaluate.cpp, shared by folding and by run() so
// that a folded constant and a computed one cannot differ. False where the
// tree evaluator reports an error. run() names `op` in each of its cases, so
// inlined it is just that case's arithmetic.
[[gnu::always_inline]] inline bool apply(Instr op, double a, double b, double& out) {
  switch (op) {
    case Instr::Add: out = a + b; return true;
    case Instr::Sub: out = a - b; return true;
    case Instr::Mul: out = a * b; return true;
    case Instr::Div:
      if (b == 0.0) return false;
      out = a / b;
      return true;
    case Instr::Mod:
      if (b == 0.0) return false;
      out = std::fmod(a, b);
      return true;
    case Instr::Eq: out = a == b ? 1.0 : 0.0; return true;
    case Instr::Ne: out = a == b ? 0.0 : 1.0; return true;
    case Instr::Lt: out = a < b ? 1.0 : 0.0; return true;
    case Instr::Le: out = a <= b ? 1.0 : 0.0; return true;
    case Instr::Gt: out = a > b ? 1.0 : 0.0; return true;
    case Instr::Ge: out = a >= b ? 1.0 : 0.0; return true;
    default: return false;
  }
}

[[gnu::always_inline]] inline bool apply(Instr op, double v, double& out) {
  switch (op) {
    case Instr::Neg: out = -v; return true;
    case Instr::Not: out = v == 0.0 ? 1.0 : 0.0; return true;
    case Instr::Truth: out = v != 0.0 ? 1.0 : 0.0; return true;
    case Instr::Abs: out = std::abs(v); return true;
    case Instr::Floor: out = std::floor(v); return true;
    case Instr::Ceil: out = std::ceil(v); return true;
    case Instr::Round: out = std::round(v); return true;
    case Instr::Sqrt:
      if (v < 0) return false;
      out = std::sqrt(v);
      return true;
    case Instr::Sin: out = std::sin(v); return true;
    case Instr::Cos: out = std::cos(v); return true;
    default: return false;
  }
}

Instr binary_instr(BinaryOp op) {
  switch (op) {
    case BinaryOp::Add: return Instr::Add;
    case BinaryOp::Sub: return Instr::Sub;
    case BinaryOp::Mul: return Instr::Mul;
    case BinaryOp::Div: return Instr::Div;
    case BinaryOp::Mod: return Instr::Mod;
    case BinaryOp::Eq: return Instr::Eq;
    case BinaryOp::Ne: return Instr::Ne;
    case BinaryOp::Lt: return Instr::Lt;
    case BinaryOp::Le: return Instr::Le;
    case BinaryOp::Gt: return Instr::Gt;
    case BinaryOp::Ge: return Instr::Ge;
    case BinaryOp::And: return Instr::AndJump;
    case BinaryOp::Or: return Instr::OrJump;
  }
  return Instr::End;
}

// What compiling a subtree left: a constant (nothing emitted) or code
// appended to the output.
struct Piece {
  bool constant = false;
  double value = 0.0;
};

// Compiles one Expr's nodes into `out`, mirroring Evaluator::num and
// Evaluator::val of evaluate.cpp case by case. `ok` turns false where only
// the tree evaluator will do.
struct Compiler {
  const Expr& e;
  std::vector<Instruction>& out;
  bool ok = true;

  void emit(Instr op, std::uint32_t index = 0, double number = 0.0) { out.push_back({op, index, number}); }

  // A constant that must become code after all, written at the end. An
  // operand that waits on the next to know whether the two fold is written
  // at once and taken back if they do: put in front of the next one's code
  // afterwards, it moved all of that code (n^2 moves for a list of n).
  void materialise(const Piece& p) {
    if (p.constant) emit(Instr::Number, 0, p.value);
  }

  Piece num(std::size_t i) {
    const ExprNode& x = e.node(i);
    switch (x.kind) {
      case ExprKind::Number: return {true, x.number};
      case ExprKind::Param: emit(Instr::Param, x.index); return {};
      case ExprKind::Constant: emit(Instr::Constant, x.index); return {};
      case ExprKind::Axis: ok = false; return {};  // an error: the tree evaluator says which
      case ExprKind::Unary: {
        const Instr op = static_cast<UnaryOp>(x.op) == UnaryOp::Neg ? Instr::Neg : Instr::Not;
        return unary(op, num(i - 1));
      }
      case ExprKind::Binary: return binary(i, static_cast<BinaryOp>(x.op));
      case ExprKind::Call: return call(i, static_cast<Function>(x.op));
    }
    ok = false;
    return {};
  }

  // An operand of == or !=: an axis counts as its number.
  Piece val(std::size_t i) {
    const ExprNode& x = e.node(i);
    switch (x.kind) {
      case ExprKind::Axis: return {true, static_cast<double>(x.op)};
      case ExprKind::Param: emit(Instr::ParamValue, x.index); return {};
      case ExprKind::Constant: emit(Instr::ConstantValue, x.index); return {};
      default: return num(i);
    }
  }

  Piece unary(Instr op, Piece operand) {
    double v;
    if (operand.constant) {
      if (apply(op, operand.value, v)) return {true, v};
      materialise(operand);
    }
    emit(op);
    return {};
  }

  Piece binary(std::size_t i, BinaryOp bop) {
    const std::size_t rhs = i - 1;
    const std::size_t lhs = rhs - e.node(rhs).size;
    const Instr op = binary_instr(bop);
    const bool values = bop == BinaryOp::Eq || bop == BinaryOp::Ne;
    const std::size_t start = out.size();
    const Piece a = values ? val(lhs) : num(lhs);
    if (op == Instr::AndJump || op == Instr::OrJump) {
      // Short-circuit: a constant left side decides whether the right side
      // (and its draws) runs at all.
      if (a.constant) {
        const bool truth = a.value != 0.0;
        if (op == Instr::AndJump && !truth) return {true, 0.0};
        if (op == Instr::OrJump && truth) return {true, 1.0};
        return unary(Instr::Truth, num(rhs));
      }
      const std::size_t jump = out.size();
      emit(op);
      const Piece b = num(rhs);
      materialise(b);
      emit(Instr::Truth);
      out[jump].index = static_cast<std::uint32_t>(out.size() - jump - 1);
      return {};
    }
    materialise(a);
    const Piece b = values ? val(rhs) : num(rhs);
    double v;
    if (a.constant && b.constant && apply(op, a.value, b.value, v)) {
      out.resize(start);  // a's number, the only code since start
      return {true, v};
    }
    materialise(b);
    emit(op);
    return {};
  }

  Piece call(std::size_t i, Function f) {
    const std::size_t argc = e.node(i).argc;
    if (f == Function::Choice || f == Function::Size) {
      ok = false;  // picks one argument to evaluate, or reads the scope: left to the tree evaluator
      return {};
    }
    if (argc == 0) {
      if (f != Function::Rand) ok = false;
      emit(Instr::Uniform);
      return {};
    }
    std::vector<std::size_t> roots = e.children(i);
    std::vector<Piece> args;
    const std::size_t start = out.size();
    for (std::size_t r : roots) {
      args.push_back(num(r));
      materialise(args.back());
    }
    const bool all_constant = std::all_of(args.begin(), args.end(), [](const Piece& p) { return p.constant; });
    Instr op = Instr::End;
    bool random = false;
    switch (f) {
      case Function::Abs: op = Instr::Abs; break;
      case Function::Floor: op = Instr::Floor; break;
      case Function::Ceil: op = Instr::Ceil; break;
      case Function::Round: op = Instr::Round; break;
      case Function::Sqrt: op = Instr::Sqrt; break;
      case Function::Sin: op = Instr::Sin; break;
      case Function::Cos: op = Instr::Cos; break;
      case Function::Min: op = Instr::Min; break;
      case Function::Max: op = Instr::Max; break;
      case Function::Rand: op = Instr::Rand, random = true; break;
      case Function::RandInt: op = Instr::RandInt, random = true; break;
      case Function::Normal: op = Instr::Normal, random = true; break;
      case Function::TNormal: op = Instr::TNormal, random = true; break;
      case Function::Choice:
      case Function::Size: break;
    }
    const std::size_t want = op == Instr::TNormal ? 4 : random ? 2 : (op == Instr::Min || op == Instr::Max) ? argc : 1;
    if (op == Instr::End || argc != want) {
      ok = false;
      return {};
    }
    if (all_constant && !random) {
      double v = args[0].value;
      if (op == Instr::Min || op == Instr::Max) {
        for (std::size_t k = 1; k < argc; ++k)
          v = op == Instr::Min ? std::min(v, args[k].value) : std::max(v, args[k].value);
        out.resize(start);  // the arguments' numbers, the only code since start
        return {true, v};
      }
      if (apply(op, args[0].value, v)) {
        out.resize(start);
        return {true, v};
      }
    }
    emit(op, static_cast<std::uint32_t>(argc));
    return {};
  }
};

// The deepest the stack gets running code from `begin` (jumps only skip
// forward over code that leaves the depth where it found it).
std::size_t stack_depth(const std::vector<Instruction>& code, std::size_t begin) {
  std::ptrdiff_t depth = 0, deepest = 0;
  for (std::size_t k = begin; k < code.size(); ++k) {
    switch (code[k].op) {
      case Instr::Number:
      case Instr::Param:
      case Instr::Constant:
      case Instr::ParamValue:
      case Instr::ConstantValue:
      case Instr::Uniform: ++depth; break;
      case Instr::Add: case Instr::Sub: case Instr::Mul: case Instr::Div: case Instr::Mod:
      case Instr::Eq: case Instr::Ne: case Instr::Lt: case Instr::Le: case Instr::Gt: case Instr::Ge:
      case Instr::AndJump: case Instr::OrJump:
      case Instr::Rand: case Instr::RandInt: case Instr::Normal: --depth; break;
      case Instr::TNormal: depth -= 3; break;
      case Instr::Min: case Instr::Max: depth -= static_cast<std::ptrdiff_t>(code[k].index) - 1; break;
      default: break;
    }
    deepest = std::max(deepest, depth);
  }
  return static_cast<std::size_t>(deepest);
}

constexpr std::size_t kStack = 32;

}  // namespace

CompiledExpr ExprCode::code(const Expr& e, bool value_context) {
  const std::size_t begin = code_.size();
  Compiler c{e, code_};
  const Piece p = c.num(e.root());
  if (c.ok && p.constant && (value_context || std::isfinite(p.value))) {
    code_.resize(begin);
    return {ExprForm::Literal, 0, p.value, &e};
  }
  c.materialise(p);
  code_.push_back({Instr::End, 0, 0.0});
  if (!c.ok || stack_depth(code_, begin) > kStack) {
    code_.resize(begin);
    return {ExprForm::Slow, 0, 0.0, &e};
  }
  return {ExprForm::Code, static_cast<std::uint32_t>(begin), 0.0, &e};
}

CompiledExpr ExprCode::number(const Expr& e) {
  if (e.empty()) return {ExprForm::Absent, 0, 0.0, &e};
  const ExprNode& root = e.node(e.root());
  if (root.kind == ExprKind::Param) return {ExprForm::Param, root.index, 0.0, &e};
  if (root.kind == ExprKind::Constant) return {ExprForm::Constant, root.index, 0.0, &e};
  // A root that may be an axis (choice()) must be reported as one.
  if (root.kind == ExprKind::Axis || (root.kind == ExprKind::Call && static_cast<Function>(root.op) == Function::Choice))
    return {ExprForm::Slow, 0, 0.0, &e};
  return code(e, false);
}

CompiledExpr ExprCode::value(const Expr& e) {
  if (e.empty()) return {ExprForm::Absent, 0, 0.0, &e};
  const ExprNode& root = e.node(e.root());
  switch (root.kind) {
    case ExprKind::Axis: return {ExprForm::Axis, root.op, 0.0, &e};
    case ExprKind::Param: return {ExprForm::Param, root.index, 0.0, &e};
    case ExprKind::Constant: return {ExprForm::Constant, root.index, 0.0, &e};
    case ExprKind::Call:
      if (static_cast<Function>(root.op) == Function::Choice) return {ExprForm::Slow, 0, 0.0, &e};
      break;
    default: break;
  }
  return code(e, true);
}

CompiledExpr ExprCode::axis(const Expr& e) {
  if (e.empty()) return {ExprForm::Absent, 0, 0.0, &e};
  const ExprNode& root = e.node(e.root());
  if (e.nodes().size() == 1) {
    if (root.kind == ExprKind::Axis) return {ExprForm::Axis, root.op, 0.0, &e};
    if (root.kind == ExprKind::Param) return {ExprForm::Param, root.index, 0.0, &e};
    if (root.kind == ExprKind::Number)
      if (auto a = Value(root.number).to_axis()) return {ExprForm::Axis, static_cast<std::uint32_t>(*a), 0.0, &e};
  }
  return {ExprForm::Slow, 0, 0.0, &e};
}

bool run(const Instruction* pc, const Value* params, const Value* constants, RandomStream& random, double& result) {
  // top points at the topmost value; stack[0] is never used, so the empty
  // stack's top is a pointer into the array (stack - 1 would be UB).
  double stack[kStack + 1];
  double* top = stack;
  for (;; ++pc) {
    switch (pc->op) {
      case Instr::Number: *++top = pc->number; break;
      case Instr::Param: {
        const Value& v = params[pc->index];
        if (!v.is_number()) return false;
        *++top = v.number();
        break;
      }
      case Instr::Constant: {
        const Value& v = constants[pc->index];
        if (!v.is_number()) return false;
        *++top = v.number();
        break;
      }
      case Instr::ParamValue: *++top = params[pc->index].number(); break;
      case Instr::ConstantValue: *++top = constants[pc->index].number(); break;
      case Instr::Add: --top; *top = top[0] + top[1]; break;
      case Instr::Sub: --top; *top = top[0] - top[1]; break;
      case Instr::Mul: --top; *top = top[0] * top[1]; break;
      case Instr::Div:
        --top;
        if (!apply(Instr::Div, top[0], top[1], *top)) return false;
        break;
      case Instr::Mod:
        --top;
        if (!apply(Instr::Mod, top[0], top[1], *top)) return false;
        break;
      case Instr::Eq:
        --top;
        if (!apply(Instr::Eq, top[0], top[1], *top)) return false;
        break;
      case Instr::Ne:
        --top;
        if (!apply(Instr::Ne, top[0], top[1], *top)) return false;
        break;
      case Instr::Lt:
        --top;
        if (!apply(Instr::Lt, top[0], top[1], *top)) return false;
        break;
      case Instr::Le:
        --top;
        if (!apply(Instr::Le, top[0], top[1], *top)) return false;
        break;
      case Instr::Gt:
        --top;
        if (!apply(Instr::Gt, top[0], top[1], *top)) return false;
        break;
      case Instr::Ge:
        --top;
        if (!apply(Instr::Ge, top[0], top[1], *top)) return false;
        break;
      case Instr::AndJump:
        if (!(*top != 0.0)) {
          *top = 0.0;
          pc += pc->index;
        } else {
          --top;
        }
        break;
      case Instr::OrJump:
        if (*top != 0.0) {
          *top = 1.0;
          pc += pc->index;
        } else {
          --top;
        }
        break;
      case Instr::Neg: *top = -*top; break;
      case Instr::Not:
        if (!apply(Instr::Not, *top, *top)) return false;
        break;
      case Instr::Truth:
        if (!apply(Instr::Truth, *top, *top)) return false;
        break;
      case Instr::Abs:
        if (!apply(Instr::Abs, *top, *top)) return false;
        break;
      case Instr::Floor:
        if (!apply(Instr::Floor, *top, *top)) return false;
        break;
      case Instr::Ceil:
        if (!apply(Instr::Ceil, *top, *top)) return false;
        break;
      case Instr::Round:
        if (!apply(Instr::Round, *top, *top)) return false;
        break;
      case Instr::Sqrt:
        if (!apply(Instr::Sqrt, *top, *top)) return false;
        break;
      case Instr::Sin:
        if (!apply(Instr::Sin, *top, *top)) return false;
        break;
      case Instr::Cos:
        if (!apply(Instr::Cos, *top, *top)) return false;
        break;
      case Instr::Min:
      case Instr::Max: {
        const std::uint32_t n = pc->index;
        top -= n - 1;
        double best = top[0];
        for (std::uint32_t k = 1; k < n; ++k)
          best = pc->op == Instr::Min ? std::min(best, top[k]) : std::max(best, top[k]);
        *top = best;
        break;
      }
      case Instr::Uniform: *++top = random.uniform(); break;
      case Instr::Rand: --top; *top = random.uniform(top[0], top[1]); break;
      case Instr::RandInt: {
        --top;
        const double a = std::ceil(top[0]);
        const double b = std::floor(top[1]);
        if (b < a) return false;
        *top = std::min(a + std::floor(random.uniform() * (b - a + 1)), b);
        break;
      }
      case Instr::Normal:
        --top;
        if (top[1] < 0) return false;
        *top = top[0] + top[1] * random.normal();
        break;
      case Instr::TNormal:
        top -= 3;
        if (top[1] < 0 || top[3] < top[2]) return false;
        *top = random.truncated_normal(top[0], top[1], top[2], top[3]);
        break;
      case Instr::End: result = *top; return true;
    }
  }
}

}  // namespace vern
