// Expressions of the grammar language, as small value-semantic trees.
//
// An Expr is a flat vector of nodes in post-order: a node's children come
// right before it, and each node records the size of its subtree, so the
// root is the last node and the whole tree lives in one allocation. That
// makes an Expr cheap to copy, hash and compare (the inverse pipeline
// hash-conses graphs full of them) and quick to evaluate. An Expr of one
// node, what inference builds most (a number, an axis) and most of what a
// grammar's text holds, keeps it and its source location inline and
// allocates nothing: an inferred graph holds millions of plain numbers, a
// read grammar one per size and priority (each an allocation of some 110
// bytes, once), and every node of the graph's arena has room for several
// Exprs, so an Expr is kept to 32 bytes.
//
// Names are resolved when an Expr is built: a parameter is the slot of the
// enclosing rule's parameter list, a constant the index of the grammar's
// constant table. Source locations ride along for messages but take no
// part in equality or hashing.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "base/error.hpp"
#include "base/hashing.hpp"
#include "graph/value.hpp"

namespace vern {

enum class ExprKind : std::uint8_t { Number, Axis, Constant, Param, Unary, Binary, Call };

enum class UnaryOp : std::uint8_t { Neg, Not };

enum class BinaryOp : std::uint8_t { Add, Sub, Mul, Div, Mod, Eq, Ne, Lt, Le, Gt, Ge, And, Or };

enum class Function : std::uint8_t {
  Min, Max, Abs, Floor, Ceil, Round, Sqrt, Sin, Cos,
  Rand, RandInt, Normal, TNormal, Choice,
  Size,  // size(axis): the scope's size along an axis, where the expression stands
};

// One table describes every function: its name, how many arguments it takes
// (max_args < 0: any number from min_args up) and whether it draws.
struct FunctionInfo {
  Function function;
  std::string_view name;
  int min_args;
  int max_args;
  bool random;
};
std::span<const FunctionInfo> function_table();
const FunctionInfo& function_info(Function f);
std::optional<Function> find_function(std::string_view name);

const char* operator_text(UnaryOp op);
const char* operator_text(BinaryOp op);

struct ExprNode {
  ExprKind kind = ExprKind::Number;
  std::uint8_t op = 0;      // UnaryOp, BinaryOp, Function or Axis, by kind
  std::uint16_t argc = 0;   // Call: number of arguments
  std::uint32_t size = 1;   // nodes in this subtree, itself included
  std::uint32_t index = 0;  // Constant or Param: the slot
  double number = 0.0;      // Number: the value

  friend bool operator==(const ExprNode&, const ExprNode&) = default;
};

class Expr {
 public:
  Expr() = default;  // the empty expression: "not given"
  Expr(const Expr& other);
  Expr& operator=(const Expr& other);
  Expr(Expr&& other) noexcept;
  Expr& operator=(Expr&& other) noexcept;
  ~Expr();

  static Expr number(double v, SourceLoc loc = {});
  static Expr axis(Axis a, SourceLoc loc = {});
  static Expr constant(std::uint32_t index, SourceLoc loc = {});
  static Expr param(std::uint32_t index, SourceLoc loc = {});
  static Expr unary(UnaryOp op, Expr operand, SourceLoc loc = {});
  static Expr binary(BinaryOp op, Expr lhs, Expr rhs, SourceLoc loc = {});
  static Expr call(Function f, std::vector<Expr> args, SourceLoc loc = {});

  bool empty() const { return !is_single() && !rest_.many; }
  std::size_t root() const { return nodes().size() - 1; }
  std::span<const ExprNode> nodes() const {
    if (is_single()) return {&single_, 1};
    if (rest_.many) return rest_.many->nodes;
    return {};
  }
  const ExprNode& node(std::size_t i) const { return nodes()[i]; }
  SourceLoc loc(std::size_t i) const {
    if (is_single()) return i == 0 ? rest_.single_loc : SourceLoc{};
    return rest_.many && i < rest_.many->locs.size() ? rest_.many->locs[i] : SourceLoc{};
  }
  SourceLoc loc() const { return empty() ? SourceLoc{} : loc(root()); }

  // Roots of node i's children, in order (at most argc entries written).
  // Returns how many children there are.
  std::size_t children(std::size_t i, std::size_t* roots, std::size_t capacity) const;
  std::vector<std::size_t> children(std::size_t i) const;

  // Leaf i (a node without children) becomes another leaf: the tree keeps
  // its shape, so no subtree size changes.
  void set_leaf(std::size_t i, const ExprNode& leaf);

  // The literal number, if the whole expression is one.
  std::optional<double> literal() const;
  // The axis, if the whole expression is a literal x, y or z (not a
  // parameter or anything computed).
  std::optional<std::uint8_t> literal_axis() const;
  bool draws_random() const;
  // Whether it reads the scope it stands in (size(axis)): its value then
  // depends on where it is evaluated, not only on its names and draws.
  bool reads_scope() const;
  bool uses_params() const;
  // 1 + the highest parameter index read, 0 when none is.
  std::size_t params_read() const;

  std::size_t hash() const;
  friend bool operator==(const Expr& a, const Expr& b) { return std::ranges::equal(a.nodes(), b.nodes()); }

 private:
  void append(const Expr& child);
  void push(ExprNode n, SourceLoc loc);

  struct Many {
    std::vector<ExprNode> nodes;
    std::vector<SourceLoc> locs;  // one per node
  };
  // A subtree size of 0 marks single_ unused (a real node counts itself).
  bool is_single() const { return single_.size != 0; }
  void release();  // frees many's nodes; the Expr is then empty

  ExprNode single_{.size = 0};  // the one node, inline
  // With the one node, its location; else all nodes, when there are any
  // (owned: nullptr when the Expr is empty).
  union Rest {
    Many* many;
    SourceLoc single_loc;
    Rest() : many(nullptr) {}
  } rest_;
};

}  // namespace vern
