#include "graph/reserved_words.hpp"
#include "graph/writer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string_view>
#include <unordered_set>

#include "base/number_format.hpp"
#include "base/stack_guard.hpp"
#include "base/overload.hpp"
#include "graph/label.hpp"

namespace vern {

namespace {

[[noreturn]] void cannot_write(const std::string& what, const std::string& hint = {}) {
  fail(ErrorKind::Internal, "", {}, "cannot write this grammar: " + what, hint);
}

// ---------------------------------------------------------------------------
// Layout: a small pretty-printing document in the style of Wadler's "prettier
// printer", kept as a flat stream of pieces. A group is laid out flat (every
// line break a space) when it fits the rest of the current line, else its
// own breaks become newlines; the groups inside it decide again for
// themselves. That is exactly "a part goes on one line if it fits".

class Layout {
 public:
  // Texts go into one buffer and pieces are small records: a grammar of a
  // million parts writes tens of millions of pieces.
  void text(std::string_view s) { add(Kind::Text, s); }
  void line() { add(Kind::Line); }
  void open() { add(Kind::Open); }
  void close() { add(Kind::Close); }
  void indent() { add(Kind::Indent); }
  void dedent() { add(Kind::Dedent); }

  // Appends the laid-out text to out: a million-part rule is most of the
  // grammar's text, not worth a copy.
  void render(std::string& out, const WriteOptions& options) const {
    int column = 0;
    bool flat = false;  // outside every group, a line break would be a newline
    std::vector<bool> outer_flat;
    std::vector<int> indents{0};
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
      const Piece& p = pieces_[i];
      switch (p.kind) {
        case Kind::Text:
          out.append(text_, p.begin, p.size);
          column += p.columns;
          break;
        case Kind::Line:
          if (flat) {
            out += ' ';
            ++column;
          } else {
            out += '\n';
            out.append(static_cast<std::size_t>(indents.back()), ' ');
            column = indents.back();
          }
          break;
        case Kind::Open:
          outer_flat.push_back(flat);
          // Inside a flat group everything is flat; otherwise this group
          // decides for itself.
          if (!flat) flat = fits(i, options.width - column);
          break;
        case Kind::Close:
          flat = outer_flat.back();
          outer_flat.pop_back();
          break;
        case Kind::Indent: indents.push_back(indents.back() + std::max(0, options.indent)); break;
        case Kind::Dedent: indents.pop_back(); break;
      }
    }
  }

 private:
  enum class Kind : std::uint8_t { Text, Line, Open, Close, Indent, Dedent };
  struct Piece {
    Kind kind;
    std::uint32_t begin, size;  // a Text's bytes in text_
    int columns;                // ... and the columns they take
  };

  void add(Kind kind, std::string_view s = {}) {
    // Texts in a row lay out as one (fits() only ever subtracts their
    // columns): one piece, a third fewer pieces in all.
    if (kind == Kind::Text && !pieces_.empty() && pieces_.back().kind == Kind::Text) {
      pieces_.back().size += static_cast<std::uint32_t>(s.size());
      pieces_.back().columns += columns(s);
    } else {
      pieces_.push_back({kind, static_cast<std::uint32_t>(text_.size()), static_cast<std::uint32_t>(s.size()), columns(s)});
    }
    text_.append(s);
  }

  // Columns a text takes: UTF-8 continuation bytes take none.
  static int columns(std::string_view s) {
    int n = 0;
    for (const char c : s)
      if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) ++n;
    return n;
  }

  // Does the group opening at `start`, laid out flat, fit in `room` columns
  // together with whatever follows it up to the next newline? What follows
  // counts too, so a closing " }" or a trailing " : 0.5" is not pushed past
  // the width. A break outside the group belongs to an enclosing group,
  // which is broken (else this one would not be deciding): the line ends
  // there. A later sibling group is measured flat, which can only
  // overestimate, never let a line run long.
  bool fits(std::size_t start, int room) const {
    int level = 0;
    for (std::size_t j = start; j < pieces_.size(); ++j) {
      const Piece& p = pieces_[j];
      switch (p.kind) {
        case Kind::Text: room -= p.columns; break;
        case Kind::Line:
          if (level <= 0) return true;
          room -= 1;
          break;
        case Kind::Open: ++level; break;
        case Kind::Close: --level; break;
        case Kind::Indent:
        case Kind::Dedent: break;
      }
      if (room < 0) return false;
    }
    return true;
  }

  std::vector<Piece> pieces_;
  std::string text_;
};

// ---------------------------------------------------------------------------
// Names

bool is_identifier(std::string_view s) {
  if (s.empty()) return false;
  auto start = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  auto rest = [&](char c) { return start(c) || (c >= '0' && c <= '9'); };
  if (!start(s[0])) return false;
  return std::all_of(s.begin() + 1, s.end(), rest);
}

void check_name(const std::string& name, const char* what, bool rule_label) {
  if (!is_identifier(name))
    cannot_write(std::string(what) + " '" + name + "' is not a name",
                 "names are a letter or '_' followed by letters, digits and '_'");
  if (rule_label ? is_operation_word(name) : is_reserved_value_name(name))
    cannot_write(std::string(what) + " '" + name + "' is a word of the grammar language", "rename it");
}

// "text" with the two escapes the lexer knows.
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '\n') cannot_write("a string may not contain a newline: " + s);
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  out += '"';
  return out;
}

// ---------------------------------------------------------------------------
// Expressions

// Binding strength, weakest first; every binary level is left-associative.
enum Precedence : int { kOr = 1, kAnd, kEquality, kComparison, kSum, kProduct, kUnary, kPrimary };

int precedence(BinaryOp op) {
  switch (op) {
    case BinaryOp::Or: return kOr;
    case BinaryOp::And: return kAnd;
    case BinaryOp::Eq:
    case BinaryOp::Ne: return kEquality;
    case BinaryOp::Lt:
    case BinaryOp::Le:
    case BinaryOp::Gt:
    case BinaryOp::Ge: return kComparison;
    case BinaryOp::Add:
    case BinaryOp::Sub: return kSum;
    case BinaryOp::Mul:
    case BinaryOp::Div:
    case BinaryOp::Mod: return kProduct;
  }
  return kPrimary;
}

class ExprWriter {
 public:
  ExprWriter(const Grammar& g, const Expr& e, const std::vector<std::string>& params)
      : g_(g), e_(e), params_(params) {}

  std::string text() {
    if (e_.empty()) return {};
    std::string out;
    write(out, e_.root(), 0);
    return out;
  }

  // Reads as one token or call, so `~e` needs no parentheses around it.
  bool atomic() const {
    if (e_.empty()) return true;
    const ExprNode& n = e_.node(e_.root());
    if (n.kind == ExprKind::Number) return n.number >= 0.0;
    return n.kind != ExprKind::Unary && n.kind != ExprKind::Binary;
  }

 private:
  static int precedence_of(const ExprNode& n) {
    if (n.kind == ExprKind::Binary) return precedence(static_cast<BinaryOp>(n.op));
    if (n.kind == ExprKind::Unary) return kUnary;
    // A negative literal reads as unary minus on a literal, which the parser
    // folds back into the literal; it binds like a unary operator.
    if (n.kind == ExprKind::Number && std::signbit(n.number) && n.number != 0.0) return kUnary;
    return kPrimary;
  }

  // Writes node i, in parentheses if it binds more loosely than `least`.
  void write(std::string& out, std::size_t i, int least) {
    const ExprNode& n = e_.node(i);
    const bool parens = precedence_of(n) < least;
    if (parens) out += '(';
    switch (n.kind) {
      case ExprKind::Number: number(out, n.number); break;
      case ExprKind::Axis: out += axis_name(static_cast<Axis>(n.op)); break;
      case ExprKind::Constant: constant(out, n.index); break;
      case ExprKind::Param:
        if (n.index >= params_.size())
          cannot_write("parameter slot " + std::to_string(n.index) + " of a rule with " +
                       std::to_string(params_.size()) + " parameters");
        out += params_[n.index];
        break;
      case ExprKind::Unary: {
        std::size_t kid = 0;
        e_.children(i, &kid, 1);
        const auto op = static_cast<UnaryOp>(n.op);
        number_operand(kid, operator_text(op));
        out += operator_text(op);
        // "--x" would read, but "-(-x)" is what a person writes.
        const ExprNode& k = e_.node(kid);
        const bool nested_minus = op == UnaryOp::Neg && precedence_of(k) == kUnary &&
                                  (k.kind == ExprKind::Number || static_cast<UnaryOp>(k.op) == UnaryOp::Neg);
        write(out, kid, nested_minus ? kPrimary : kUnary);
        break;
      }
      case ExprKind::Binary: {
        std::size_t kids[2] = {0, 0};
        e_.children(i, kids, 2);
        const auto op = static_cast<BinaryOp>(n.op);
        if (op != BinaryOp::Eq && op != BinaryOp::Ne) {
          number_operand(kids[0], operator_text(op));
          number_operand(kids[1], operator_text(op));
        }
        const int p = precedence(op);
        write(out, kids[0], p);
        out += ' ';
        out += operator_text(op);
        out += ' ';
        write(out, kids[1], p + 1);  // left-associative: a - (b - c) keeps its parentheses
        break;
      }
      case ExprKind::Call: {
        const FunctionInfo& f = function_info(static_cast<Function>(n.op));
        const int argc = n.argc;
        const bool arity = f.function == Function::Rand
                               ? argc == 0 || argc == 2
                               : argc >= f.min_args && (f.max_args < 0 || argc <= f.max_args);
        if (!arity) cannot_write(std::string(f.name) + " with " + std::to_string(argc) + " arguments");
        out += f.name;
        out += '(';
        const auto kids = e_.children(i);
        for (std::size_t k = 0; k < kids.size(); ++k) {
          if (f.function != Function::Size) number_operand(kids[k], f.name);  // size(x) takes an axis
          if (k > 0) out += ", ";
          write(out, kids[k], 0);
        }
        out += ')';
        break;
      }
    }
    if (parens) out += ')';
  }

  // The parser refuses an axis literal where a number is expected (every
  // operator but == and !=, every function but size), so the writer does too.
  void number_operand(std::size_t i, std::string_view where) const {
    if (e_.node(i).kind == ExprKind::Axis)
      cannot_write(std::string("the axis ") + axis_name(static_cast<Axis>(e_.node(i).op)) + " as an operand of " +
                   std::string(where));
  }

  static void number(std::string& out, double v) {
    if (!std::isfinite(v)) cannot_write("the number " + format_number(v) + " is not finite");
    if (v == std::numbers::pi) {
      out += "pi";
    } else if (v == -std::numbers::pi) {
      out += "-pi";
    } else {
      append_number(out, v);
    }
  }

  void constant(std::string& out, std::uint32_t index) {
    if (index >= g_.constants.size()) cannot_write("constant slot " + std::to_string(index) + " does not exist");
    const std::string& name = g_.constants[index].name;
    // A parameter of the same name would capture the reference on reading.
    if (std::find(params_.begin(), params_.end(), name) != params_.end())
      cannot_write("constant '" + name + "' is hidden by a parameter of the same name", "rename one of them");
    out += name;
  }

  const Grammar& g_;
  const Expr& e_;
  const std::vector<std::string>& params_;
};

// ---------------------------------------------------------------------------
// Operations

class OpWriter {
 public:
  OpWriter(const Grammar& g, const std::vector<std::string>& params) : g_(g), params_(params) {}

  std::string expr(const Expr& e) const {
    if (e.empty()) cannot_write("an operation is missing an expression");
    return ExprWriter(g_, e, params_).text();
  }

  // `~e` or `e`; a relative size that is more than one token gets
  // parentheses, `~(n - 1)`, so the tilde visibly applies to all of it.
  std::string size(const Size& s) const {
    std::string text = expr(s.value);
    if (!s.relative) return text;
    if (ExprWriter(g_, s.value, params_).atomic()) return "~" + text;
    return "~(" + text + ")";
  }

  void op(Layout& out, NodeId id) const {
    if (id >= g_.node_count()) cannot_write("node " + std::to_string(id) + " does not exist");
    // Operations nest in the text as in the graph; one nested deeper than
    // this thread's stack holds is a limit said, not a crash.
    if (stack_.exhausted()) [[unlikely]]
      fail(ErrorKind::Limit, "", {},
           "cannot write this grammar: its operations nest deeper than this thread's " + stack_.size_text() +
               " stack holds",
           "a grammar this deep is a bug of whatever made it; please report it with the input");
    std::visit(
        Overload{
            [&](const Split& s) {
              parts(out, "split(" + axis(s.axis) + ")", s.parts.size(), [&](std::size_t i) {
                return std::pair{size(s.parts[i].size), s.parts[i].child};
              });
            },
            [&](const Repeat& r) {
              wrap(out, "repeat(" + axis(r.axis) + ", " + expr(r.size) + ")", r.child);
            },
            [&](const RepeatN& r) {
              wrap(out, "repeatN(" + axis(r.axis) + ", " + expr(r.count) + ")", r.child);
            },
            [&](const Choose&) {
              cannot_write("a choose inside an operation",
                           "the choose must become a rule first, and the operation call that rule");
            },
            [&](const Call& c) { out.text(call(c)); },
            [&](const Primitive& p) {
              const std::string& name = g_.label(p.label);
              // Every reader refuses other labels, so none reaches here.
              if (const auto fault = label_fault(name))
                cannot_write("a primitive named '" + shown_name(name) + "', which cannot be a label: it " + *fault);
              out.text("I(" + (is_identifier(name) ? name : quoted(name)) + ")");
            },
            [&](const Nil&) { out.text("nil"); },
            [&](const Translate& t) { wrap(out, "T(" + sizes(t.offset) + ")", t.child); },
            [&](const Scale& s) { wrap(out, "S(" + sizes(s.size) + ")", s.child); },
            [&](const Rotate& r) { wrap(out, "R(" + axis(r.axis) + ", " + expr(r.angle) + ")", r.child); },
            [&](const Comp& c) {
              std::vector<std::string> labels;
              std::vector<NodeId> kids;
              for (const auto& p : c.parts) {
                if (std::find(labels.begin(), labels.end(), face_name(p.face)) != labels.end())
                  cannot_write(std::string("comp lists the face ") + face_name(p.face) + " twice");
                labels.emplace_back(face_name(p.face));
                kids.push_back(p.child);
              }
              parts(out, "comp(f)", kids.size(), [&](std::size_t i) { return std::pair{labels[i], kids[i]}; });
            },
            [&](const Colour& c) {
              out.text("colour(" + expr(c.rgb[0]) + ", " + expr(c.rgb[1]) + ", " + expr(c.rgb[2]) + ")");
            },
        },
        g_.op(id));
  }

 private:
  // An axis argument; a literal must name an axis (0, 1 or 2), as the
  // parser checks.
  std::string axis(const Expr& e) const {
    if (auto v = e.literal(); v && !Value(*v).to_axis()) cannot_write("the axis " + format_number(*v));
    return expr(e);
  }

  std::string sizes(const Triple<Size>& s) const {
    return size(s[0]) + ", " + size(s[1]) + ", " + size(s[2]);
  }

  std::string call(const Call& c) const {
    if (c.rule >= g_.rules.size()) cannot_write("a call of rule " + std::to_string(c.rule) + ", which does not exist");
    const Rule& callee = g_.rules[c.rule];
    if (c.args.size() != callee.params.size())
      cannot_write("a call of '" + callee.label + "' with " + std::to_string(c.args.size()) +
                   " arguments, which takes " + std::to_string(callee.params.size()));
    std::string text = callee.label;
    if (c.args.empty()) return text;
    text += '(';
    for (std::size_t i = 0; i < c.args.size(); ++i) {
      if (i > 0) text += ", ";
      text += expr(c.args[i]);
    }
    return text + ')';
  }

  // head{ a : op | b : op }, or broken one part per line:
  //   head{
  //       a : op |
  //       b : op }
  // part(i) gives the i-th part's label and node: no lists of them are
  // made (a million-part grammar has hundreds of thousands of splits).
  template <class Part>
  void parts(Layout& out, const std::string& head, std::size_t count, Part part) const {
    if (count == 0) cannot_write(head + " has no parts");
    out.open();
    out.text(head + "{");
    out.indent();
    for (std::size_t i = 0; i < count; ++i) {
      const auto [label, kid] = part(i);
      out.line();
      out.text(label);
      out.text(" : ");
      op(out, kid);
      if (i + 1 < count) out.text(" |");
    }
    out.dedent();
    out.text(" }");
    out.close();
  }

  // A single-child operation hugs a child that has braces of its own, so
  // the braces stack on one line and only the innermost split or comp
  // breaks: `repeat(x, 2){ split(z){` ... ` } }`. Around a leaf the break,
  // when needed, goes after the brace.
  void wrap(Layout& out, const std::string& head, NodeId child) const {
    if (child >= g_.node_count()) cannot_write("node " + std::to_string(child) + " does not exist");
    const Operation& c = g_.op(child);
    const bool leaf = std::holds_alternative<Call>(c) || std::holds_alternative<Primitive>(c) ||
                      std::holds_alternative<Nil>(c) || std::holds_alternative<Colour>(c);
    if (!leaf) {
      out.text(head + "{ ");
      op(out, child);
      out.text(" }");
      return;
    }
    out.open();
    out.text(head + "{");
    out.indent();
    out.line();
    op(out, child);
    out.dedent();
    out.text(" }");
    out.close();
  }

  const Grammar& g_;
  const std::vector<std::string>& params_;
  const StackGuard& stack_ = StackGuard::for_this_thread();
};

bool is_one(const Expr& e) { return e.literal() == 1.0; }

// Appends the rule's lines to out, without the last line break.
void write_rule(std::string& out, const Grammar& g, const Rule& rule, const WriteOptions& options) {
  check_name(rule.label, "rule", true);
  std::string head = rule.label;
  if (!rule.params.empty()) {
    head += '(';
    for (std::size_t i = 0; i < rule.params.size(); ++i) {
      check_name(rule.params[i], "parameter", false);
      if (std::find(rule.params.begin(), rule.params.begin() + static_cast<std::ptrdiff_t>(i), rule.params[i]) !=
          rule.params.begin() + static_cast<std::ptrdiff_t>(i))
        cannot_write("rule '" + rule.label + "' has two parameters named '" + rule.params[i] + "'");
      if (i > 0) head += ", ";
      head += rule.params[i];
    }
    head += ')';
  }
  if (rule.body >= g.node_count()) cannot_write("rule '" + rule.label + "' has no body");
  const OpWriter w(g, rule.params);

  const auto* choose = std::get_if<Choose>(&g.op(rule.body));
  if (choose == nullptr) {
    Layout line;
    line.text(head + " --> ");
    w.op(line, rule.body);
    line.render(out, options);
    return;
  }

  // One line per alternative. The parser gathers rules sharing a label into
  // one Choose, and makes one for a lone rule only when that rule has a
  // condition or a priority; so a lone option always writes one of them.
  if (choose->options.empty()) cannot_write("rule '" + rule.label + "' chooses among no options");
  const bool lone = choose->options.size() == 1;
  for (const ChooseOption& option : choose->options) {
    Layout line;
    std::string start = head;
    if (!option.condition.empty()) start += " : " + ExprWriter(g, option.condition, rule.params).text();
    line.text(start + " --> ");
    w.op(line, option.child);
    if (option.priority.empty()) cannot_write("an option of rule '" + rule.label + "' has no priority");
    if (!is_one(option.priority) || (lone && option.condition.empty()))
      line.text(" : " + w.expr(option.priority));
    if (&option != &choose->options.front()) out += '\n';
    line.render(out, options);
  }
}

}  // namespace

std::string write_expression(const Grammar& g, const Expr& e, const std::vector<std::string>& param_names) {
  return ExprWriter(g, e, param_names).text();
}

std::string write_operation(const Grammar& g, NodeId node, const std::vector<std::string>& param_names,
                            const WriteOptions& options) {
  Layout out;
  OpWriter(g, param_names).op(out, node);
  std::string text;
  out.render(text, options);
  return text;
}

std::string write_grammar(const Grammar& g, const WriteOptions& options) {
  const std::vector<std::string> no_params;
  // The parser needs a rule to start from, and one without parameters.
  if (g.rules.empty()) cannot_write("a grammar with no rules");
  if (g.start_rule >= g.rules.size()) cannot_write("the start rule does not exist");
  const Rule& start = g.rules[g.start_rule];

  std::vector<std::string> header;
  // Reading without @start starts at the first rule; a grammar that starts
  // elsewhere says so even if its @start was never written.
  const bool named_start = g.start_written || start.label != g.rules.front().label;
  // The parser lets a default start rule take parameters (generate --start
  // may name another), but not one that @start names.
  if (named_start && !start.params.empty()) cannot_write("the start rule '" + start.label + "' takes parameters");
  if (named_start) header.push_back("@start " + start.label);

  std::string scope;
  if (!g.scope[0].empty()) {
    if (g.scope[1].empty() || g.scope[2].empty()) cannot_write("@scope needs all three sizes");
    scope = "@scope " + write_expression(g, g.scope[0], no_params) + ", " + write_expression(g, g.scope[1], no_params) +
            ", " + write_expression(g, g.scope[2], no_params);
  } else if (!g.scope[1].empty() || !g.scope[2].empty()) {
    cannot_write("@scope needs all three sizes");
  }
  // A name is read in file order, so a @scope that uses constants follows
  // them; otherwise it stays with the other directives at the top.
  const bool scope_uses_constants = std::any_of(g.scope.begin(), g.scope.end(), [](const Expr& e) {
    return std::any_of(e.nodes().begin(), e.nodes().end(),
                       [](const ExprNode& n) { return n.kind == ExprKind::Constant; });
  });
  if (!scope.empty() && !scope_uses_constants) header.push_back(scope);
  if (!g.primitives.empty()) header.push_back("@primitives " + quoted(g.primitives));

  std::unordered_set<std::string_view> seen;
  for (std::size_t i = 0; i < g.constants.size(); ++i) {
    const Constant& c = g.constants[i];
    check_name(c.name, "constant", false);
    if (!seen.insert(c.name).second) cannot_write("two constants are named '" + c.name + "'");
    if (c.value.empty()) cannot_write("constant '" + c.name + "' has no value");
    for (const ExprNode& n : c.value.nodes())
      if (n.kind == ExprKind::Constant && n.index >= i)
        cannot_write("constant '" + c.name + "' uses a constant defined after it");
    header.push_back(c.name + " = " + write_expression(g, c.value, no_params));
  }
  if (!scope.empty() && scope_uses_constants) header.push_back(scope);

  std::string out;
  for (const auto& line : header) out += line + '\n';
  if (!header.empty()) out += '\n';

  seen.clear();
  for (const Rule& rule : g.rules) {
    if (!seen.insert(rule.label).second)
      cannot_write("two rules are labelled '" + rule.label + "'",
                   "alternatives of one label must be one rule whose body is a choose");
    write_rule(out, g, rule, options);
    out += '\n';
  }
  return out;
}

}  // namespace vern
