// The operation graph compiled for derivation.
//
// The Grammar's nodes are a std::variant per node, made to be built,
// compared and hash-consed; walking them costs a variant dispatch and
// get_if per operation, and every expression is evaluated as a tree. A
// Program holds the same graph as flat tables, one per operation kind,
// with each child's kind and table index stored where the parent refers to
// it (leaves need no lookup at all), a call's callee body resolved, split
// sizes that are all literals pre-summed, and expressions compiled
// (forward/compiled_expr.hpp). derive() compiles its grammar once and then
// runs only the Program.
//
// A Program points into the Grammar it was compiled from (expressions, for
// the tree evaluator's messages) and must not outlive it.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "forward/compiled_expr.hpp"
#include "graph/grammar.hpp"

namespace vern {

enum class OpKind : std::uint8_t { Split, Repeat, RepeatN, Choose, Call, Primitive, Nil, Translate, Scale, Rotate, Comp, Colour };

// An operation as its parent refers to it.
struct Target {
  OpKind kind = OpKind::Nil;
  std::uint32_t index = 0;  // into the kind's table; a Primitive's label
  NodeId node = 0;          // the grammar's node: source location, messages
};

struct SplitOp {
  CompiledExpr axis;
  std::uint32_t first = 0, count = 0;  // in Program::parts
  // Every size a literal >= 0: their sums, added in part order as the
  // derivation would, need no evaluation.
  bool literal = false;
  double absolute = 0.0, relative = 0.0;
};

struct PartOp {
  CompiledExpr size;
  bool relative = false;
  Target child;
};

// repeat (amount = tile size) and repeatN (amount = count).
struct RepeatOp {
  CompiledExpr axis, amount;
  Target child;
};

struct ChooseOp {
  std::uint32_t first = 0, count = 0;  // in Program::options
};

struct OptionOp {
  CompiledExpr condition, priority;  // condition Absent: it holds
  Target child;
};

struct CallOp {
  RuleId rule = 0;
  Target body;
  std::uint32_t first = 0, count = 0;  // in Program::args
};

// T (amounts are offsets) and S (amounts are sizes).
struct TransformOp {
  std::array<CompiledExpr, 3> amount;
  std::array<bool, 3> relative{};
  Target child;
};

struct RotateOp {
  CompiledExpr axis, angle;
  Target child;
};

struct CompOp {
  std::uint32_t first = 0, count = 0;  // in Program::faces
};

struct FaceOp {
  Face face = Face::Top;
  Target child;
};

struct ColourOp {
  std::array<CompiledExpr, 3> rgb;
};

struct Program {
  const Grammar* grammar = nullptr;
  std::vector<Target> nodes;  // NodeId -> Target
  std::vector<SplitOp> splits;
  std::vector<PartOp> parts;
  std::vector<RepeatOp> repeats;  // repeat and repeatN
  std::vector<ChooseOp> chooses;
  std::vector<OptionOp> options;
  std::vector<CallOp> calls;
  std::vector<CompiledExpr> args;
  std::vector<TransformOp> transforms;  // T and S
  std::vector<RotateOp> rotates;
  std::vector<CompOp> comps;
  std::vector<FaceOp> faces;
  std::vector<ColourOp> colours;
  ExprCode code;
};

Program compile(const Grammar& grammar);

}  // namespace vern
