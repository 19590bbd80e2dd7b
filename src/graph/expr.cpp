#include "graph/expr.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <functional>
#include <memory>

namespace vern {

namespace {

constexpr std::array<FunctionInfo, 15> kFunctions{{
    {Function::Min, "min", 1, -1, false},
    {Function::Max, "max", 1, -1, false},
    {Function::Abs, "abs", 1, 1, false},
    {Function::Floor, "floor", 1, 1, false},
    {Function::Ceil, "ceil", 1, 1, false},
    {Function::Round, "round", 1, 1, false},
    {Function::Sqrt, "sqrt", 1, 1, false},
    {Function::Sin, "sin", 1, 1, false},
    {Function::Cos, "cos", 1, 1, false},
    {Function::Rand, "rand", 0, 2, true},  // 0 or 2: checked by the parser
    {Function::RandInt, "randint", 2, 2, true},
    {Function::Normal, "normal", 2, 2, true},
    {Function::TNormal, "tnormal", 4, 4, true},
    {Function::Choice, "choice", 1, -1, true},
    {Function::Size, "size", 1, 1, false},
}};

}  // namespace

std::span<const FunctionInfo> function_table() { return kFunctions; }

const FunctionInfo& function_info(Function f) { return kFunctions[static_cast<std::size_t>(f)]; }

std::optional<Function> find_function(std::string_view name) {
  for (const auto& info : kFunctions)
    if (info.name == name) return info.function;
  return std::nullopt;
}

const char* operator_text(UnaryOp op) { return op == UnaryOp::Neg ? "-" : "!"; }

const char* operator_text(BinaryOp op) {
  switch (op) {
    case BinaryOp::Add: return "+";
    case BinaryOp::Sub: return "-";
    case BinaryOp::Mul: return "*";
    case BinaryOp::Div: return "/";
    case BinaryOp::Mod: return "%";
    case BinaryOp::Eq: return "==";
    case BinaryOp::Ne: return "!=";
    case BinaryOp::Lt: return "<";
    case BinaryOp::Le: return "<=";
    case BinaryOp::Gt: return ">";
    case BinaryOp::Ge: return ">=";
    case BinaryOp::And: return "&&";
    case BinaryOp::Or: return "||";
  }
  return "?";
}

Expr::Expr(const Expr& other) : single_(other.single_) {
  if (other.is_single()) rest_.single_loc = other.rest_.single_loc;
  else if (other.rest_.many) rest_.many = new Many(*other.rest_.many);
}

Expr& Expr::operator=(const Expr& other) {
  if (this != &other) *this = Expr(other);
  return *this;
}

Expr::Expr(Expr&& other) noexcept : single_(other.single_), rest_(other.rest_) {
  other.single_.size = 0;
  other.rest_.many = nullptr;
}

Expr& Expr::operator=(Expr&& other) noexcept {
  if (this != &other) {
    release();
    single_ = other.single_;
    rest_ = other.rest_;
    other.single_.size = 0;
    other.rest_.many = nullptr;
  }
  return *this;
}

Expr::~Expr() { release(); }

void Expr::release() {
  if (!is_single()) delete rest_.many;
  single_.size = 0;
  rest_.many = nullptr;
}

void Expr::push(ExprNode n, SourceLoc loc) {
  if (empty()) {
    single_ = n;
    rest_.single_loc = loc;
    return;
  }
  if (is_single()) {
    auto many = std::make_unique<Many>();
    many->nodes.push_back(single_);
    many->locs.push_back(rest_.single_loc);
    single_.size = 0;
    rest_.many = many.release();
  }
  rest_.many->nodes.push_back(n);
  rest_.many->locs.push_back(loc);
}

void Expr::append(const Expr& child) {
  const std::span<const ExprNode> added = child.nodes();
  for (std::size_t i = 0; i < added.size(); ++i) push(added[i], child.loc(i));
}

Expr Expr::number(double v, SourceLoc loc) {
  Expr e;
  e.push({.kind = ExprKind::Number, .number = v}, loc);
  return e;
}

Expr Expr::axis(Axis a, SourceLoc loc) {
  Expr e;
  e.push({.kind = ExprKind::Axis, .op = static_cast<std::uint8_t>(a)}, loc);
  return e;
}

Expr Expr::constant(std::uint32_t index, SourceLoc loc) {
  Expr e;
  e.push({.kind = ExprKind::Constant, .index = index}, loc);
  return e;
}

Expr Expr::param(std::uint32_t index, SourceLoc loc) {
  Expr e;
  e.push({.kind = ExprKind::Param, .index = index}, loc);
  return e;
}

Expr Expr::unary(UnaryOp op, Expr operand, SourceLoc loc) {
  // "-2" has one form, the literal -2, whether it was read or built: the
  // writer prints both the same way, so both must be the same tree.
  if (op == UnaryOp::Neg && operand.nodes().size() == 1 && operand.node(0).kind == ExprKind::Number) {
    const double negated = -operand.node(0).number;
    if (operand.is_single()) operand.single_.number = negated;
    else operand.rest_.many->nodes[0].number = negated;
    if (loc.known()) {
      Expr e;
      e.push({.kind = ExprKind::Number, .number = negated}, loc);
      return e;
    }
    return operand;
  }
  Expr e = std::move(operand);
  auto size = static_cast<std::uint32_t>(e.nodes().size() + 1);
  e.push({.kind = ExprKind::Unary, .op = static_cast<std::uint8_t>(op), .argc = 1, .size = size}, loc);
  return e;
}

Expr Expr::binary(BinaryOp op, Expr lhs, Expr rhs, SourceLoc loc) {
  Expr e = std::move(lhs);
  e.append(rhs);
  auto size = static_cast<std::uint32_t>(e.nodes().size() + 1);
  e.push({.kind = ExprKind::Binary, .op = static_cast<std::uint8_t>(op), .argc = 2, .size = size}, loc);
  return e;
}

Expr Expr::call(Function f, std::vector<Expr> args, SourceLoc loc) {
  Expr e;
  for (const auto& a : args) e.append(a);
  auto size = static_cast<std::uint32_t>(e.nodes().size() + 1);
  e.push({.kind = ExprKind::Call,
          .op = static_cast<std::uint8_t>(f),
          .argc = static_cast<std::uint16_t>(args.size()),
          .size = size},
         loc);
  return e;
}

std::size_t Expr::children(std::size_t i, std::size_t* roots, std::size_t capacity) const {
  const std::size_t n = nodes()[i].argc;
  // Walk back from the last child, skipping each child's subtree.
  std::size_t at = i;
  for (std::size_t k = n; k-- > 0;) {
    const std::size_t child = at - 1;
    if (k < capacity) roots[k] = child;
    at = child + 1 - nodes()[child].size;
  }
  return n;
}

std::vector<std::size_t> Expr::children(std::size_t i) const {
  std::vector<std::size_t> roots(nodes()[i].argc);
  children(i, roots.data(), roots.size());
  return roots;
}

void Expr::set_leaf(std::size_t i, const ExprNode& leaf) {
  if (nodes()[i].size != 1 || leaf.size != 1 || leaf.argc != 0)
    throw Error(ErrorKind::Internal, "Expr::set_leaf: only a leaf replaces a leaf");
  if (is_single()) single_ = leaf;
  else rest_.many->nodes[i] = leaf;
}

std::optional<double> Expr::literal() const {
  if (empty()) return std::nullopt;
  const auto& r = nodes().back();
  if (r.kind == ExprKind::Number) return r.number;
  return std::nullopt;
}

std::optional<std::uint8_t> Expr::literal_axis() const {
  if (nodes().size() != 1 || node(0).kind != ExprKind::Axis) return std::nullopt;
  return node(0).op;
}

bool Expr::draws_random() const {
  return std::ranges::any_of(nodes(), [](const ExprNode& n) {
    return n.kind == ExprKind::Call && function_info(static_cast<Function>(n.op)).random;
  });
}

bool Expr::reads_scope() const {
  return std::ranges::any_of(nodes(), [](const ExprNode& n) {
    return n.kind == ExprKind::Call && static_cast<Function>(n.op) == Function::Size;
  });
}

bool Expr::uses_params() const {
  return std::ranges::any_of(nodes(), [](const ExprNode& n) { return n.kind == ExprKind::Param; });
}

std::size_t Expr::params_read() const {
  std::size_t out = 0;
  for (const ExprNode& n : nodes())
    if (n.kind == ExprKind::Param) out = std::max<std::size_t>(out, n.index + 1);
  return out;
}

std::size_t Expr::hash() const {
  std::size_t h = nodes().size();
  for (const auto& n : nodes()) {
    h = hash_combine(h, static_cast<std::size_t>(n.kind) | (std::size_t{n.op} << 8) | (std::size_t{n.argc} << 16));
    h = hash_combine(h, n.index);
    h = hash_combine(h, std::hash<double>{}(n.number));
  }
  return h;
}

}  // namespace vern
