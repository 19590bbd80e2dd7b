// Derivation runs the grammar compiled into a Program (forward/program.hpp):
// flat operation tables and compiled expressions. Errors keep the tree
// evaluator's messages (compiled_expr.hpp) and name the rule chain.
#include "forward/derive.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "base/number_format.hpp"
#include "base/stack_guard.hpp"
#include "forward/evaluate.hpp"
#include "forward/program.hpp"
#include "forward/random_stream.hpp"
#include "forward/rule_chain.hpp"

namespace vern {

namespace {

// The terminal buffer a thread keeps between derivations (about 9 MB);
// larger ones are released after use.
constexpr std::size_t kKeptTerminals = std::size_t{1} << 16;

// The per-part numbers of one split or choose: on the stack for the usual
// handful of parts, on the heap beyond that. (A shared scratch vector cost
// a capacity check per part and a resize per node on the hot path.)
class PartValues {
 public:
  explicit PartValues(std::size_t n) : data_(inline_) {
    if (n > kInline) {
      heap_.resize(n);
      data_ = heap_.data();
    }
  }
  double& operator[](std::size_t i) { return data_[i]; }

 private:
  static constexpr std::size_t kInline = 16;
  double inline_[kInline];
  std::vector<double> heap_;
  double* data_;
};

class Deriver {
 public:
  Deriver(const Program& p, const DeriveOptions& o, Derivation& out, std::vector<Terminal>& terminals)
      : prog_(p), g_(*p.grammar), opt_(o), out_(out), terminals_(terminals) {
    out_.labels = g_.labels();
    auto rect = g_.find_label("rect");
    if (rect) {
      rect_label_ = *rect;
    } else {
      rect_label_ = static_cast<LabelId>(out_.labels.size());
      out_.labels.emplace_back("rect");
    }
    warned_.resize(g_.rules.size(), false);
    params_.resize(64);
  }

  // The start scope's size alone, drawn as run() draws it.
  glm::dvec3 start_only() {
    const std::uint64_t root = seed_key(opt_.seed);
    evaluate_constants(child_key(root, 1));
    return start_size(child_key(root, 2));
  }

  void run() {
    const std::uint64_t root = seed_key(opt_.seed);
    evaluate_constants(child_key(root, 1));
    out_.start.size = start_size(child_key(root, 2));
    if (g_.rules.empty()) return;
    const Rule& start = g_.rules[g_.start_rule];
    if (!start.params.empty())
      fail(ErrorKind::Input, g_.source_name, start.loc, "the start rule '" + start.label + "' takes parameters",
           "the start rule runs with no arguments: name another with @start or --start, or add a rule such as "
           "'plot --> " + start.label + "(...)'");
    if (!within_reach(out_.start))
      fail(ErrorKind::Input, g_.source_name, {},
           "the start scope " + describe_size(out_.start.size) + " reaches beyond " +
               format_number(kMaxDerivedCoordinate) + " m from the origin",
           "give a smaller plot (--scope)");
    chain_.push_back({g_.start_rule, 0});
    node(prog_.nodes[start.body], out_.start, 0, child_key(root, 3));
    chain_.pop_back();
  }

 private:
  struct Frame {
    RuleId rule;
    std::size_t params;  // index of this call's arguments in params_
  };

  // Errors are rare: their text is built out of line, keeping the hot
  // functions small.
  [[noreturn, gnu::cold, gnu::noinline]] void fail_here(ErrorKind kind, SourceLoc loc, const std::string& message,
                                                         const std::string& hint) {
    std::string text = format_message(g_.source_name, loc, message);
    text += "\n  rule chain: " + describe_chain();
    if (!hint.empty()) text += "\n  hint: " + hint;
    throw Error(kind, text);
  }

  SourceLoc loc(NodeId id) const { return g_.node(id).loc; }

  void evaluate_constants(std::uint64_t key) {
    constants_.reserve(g_.constants.size());
    for (std::size_t i = 0; i < g_.constants.size(); ++i) {
      RandomStream rng(child_key(key, i));
      EvalContext ctx{nullptr, constants_.data(), &rng};
      try {
        constants_.push_back(evaluate(g_.constants[i].value, ctx));
      } catch (const EvaluationError& e) {
        fail(ErrorKind::Input, g_.source_name, e.loc, e.message + " (in the constant '" + g_.constants[i].name + "')",
             e.hint);
      }
    }
  }

  glm::dvec3 start_size(std::uint64_t key) {
    if (opt_.size) return *opt_.size;
    if (g_.scope[0].empty()) return opt_.default_size;
    RandomStream rng(key);
    EvalContext ctx{nullptr, constants_.data(), &rng};
    glm::dvec3 size(0.0);
    for (int i = 0; i < 3; ++i) {
      try {
        size[i] = evaluate_number(g_.scope[i], ctx, "an @scope size");
      } catch (const EvaluationError& e) {
        fail(ErrorKind::Input, g_.source_name, e.loc, e.message, e.hint);
      }
      if (size[i] < 0)
        fail(ErrorKind::Input, g_.source_name, g_.scope[i].loc(), "@scope size " + format_number(size[i]) + " is negative",
             "sizes are lengths in metres and must be >= 0");
      if (!within_reach(Scope{glm::dvec3(0.0), glm::dmat3(1.0), size}))
        fail(ErrorKind::Input, g_.source_name, g_.scope[i].loc(),
             "the @scope reaches beyond " + format_number(kMaxDerivedCoordinate) + " m from the origin (size " +
                 format_number(size[i]) + ")",
             kBeyondReachHint);
    }
    return size;
  }

  const Value* params() const { return params_.data() + params_base_; }
  EvalContext context(RandomStream& rng) const { return {params(), constants_.data(), &rng, scope_size_}; }

  // Compiled code answers; where it cannot (and on every error) the tree
  // evaluator runs again from the same random state (compiled_expr.hpp).
  bool run_code(const CompiledExpr& e, RandomStream& rng, double& result) const {
    const RandomStream saved = rng;
    if (vern::run(prog_.code.at(e.index), params(), constants_.data(), rng, result)) return true;
    rng = saved;
    return false;
  }

  static bool finite_number(const Value& v) { return v.is_number() && v.number() - v.number() == 0.0; }

  double number(const CompiledExpr& e, RandomStream& rng, const char* what) {
    switch (e.form) {
      case ExprForm::Literal: return e.literal;
      case ExprForm::Param:
        if (const Value& v = params()[e.index]; finite_number(v)) return v.number();
        break;
      case ExprForm::Constant:
        if (const Value& v = constants_[e.index]; finite_number(v)) return v.number();
        break;
      case ExprForm::Code: {
        // NaN and inf fail the comparison and take the slow path's message.
        double r;
        const RandomStream saved = rng;
        if (vern::run(prog_.code.at(e.index), params(), constants_.data(), rng, r) && r - r == 0.0) return r;
        rng = saved;
        break;
      }
      default: break;
    }
    return slow_number(*e.source, rng, what);
  }

  [[gnu::noinline]] double slow_number(const Expr& e, RandomStream& rng, const char* what) {
    try {
      return evaluate_number(e, context(rng), what);
    } catch (const EvaluationError& err) {
      fail_here(ErrorKind::Input, err.loc, err.message, err.hint);
    }
  }

  Axis axis(const CompiledExpr& e, RandomStream& rng, const char* what) {
    if (e.form == ExprForm::Axis) return static_cast<Axis>(e.index);
    if (e.form == ExprForm::Param)
      if (auto a = params()[e.index].to_axis()) return *a;
    return slow_axis(*e.source, rng, what);
  }

  [[gnu::noinline]] Axis slow_axis(const Expr& e, RandomStream& rng, const char* what) {
    try {
      return evaluate_axis(e, context(rng), what);
    } catch (const EvaluationError& err) {
      fail_here(ErrorKind::Input, err.loc, err.message, err.hint);
    }
  }

  Value value(const CompiledExpr& e, RandomStream& rng) {
    switch (e.form) {
      case ExprForm::Literal: return e.literal;
      case ExprForm::Axis: return Value::axis(static_cast<Axis>(e.index));
      case ExprForm::Param: return params()[e.index];
      case ExprForm::Constant: return constants_[e.index];
      case ExprForm::Code: {
        double r;
        if (run_code(e, rng, r)) return r;
        break;
      }
      default: break;
    }
    return slow_value(*e.source, rng);
  }

  [[gnu::noinline]] Value slow_value(const Expr& e, RandomStream& rng) {
    try {
      return evaluate(e, context(rng));
    } catch (const EvaluationError& err) {
      fail_here(ErrorKind::Input, err.loc, err.message, err.hint);
    }
  }

  // A size that cannot be negative or NaN: docs/grammar.md gives them no meaning.
  double size_value(const CompiledExpr& e, RandomStream& rng, const char* what) {
    const double v = number(e, rng, what);
    if (v < 0) negative_size(e, v, what);
    return v;
  }

  // T, S and R are where a scope can leave kMaxDerivedCoordinate's reach
  // (scope.hpp); the parts of a scope in reach are in reach.
  void check_reach(const Scope& s, NodeId id, const char* what) {
    if (!within_reach(s)) beyond_reach(s, id, what);
  }

  [[noreturn, gnu::cold, gnu::noinline]] void beyond_reach(const Scope& s, NodeId id, const char* what) {
    fail_here(ErrorKind::Input, loc(id),
              std::string(what) + " beyond " + format_number(kMaxDerivedCoordinate) + " m from the origin (origin " +
                  describe_size(s.origin) + ", size " + describe_size(s.size) + ")",
              kBeyondReachHint);
  }

  static std::string describe_size(const glm::dvec3& v) {
    return "(" + format_number(v.x) + ", " + format_number(v.y) + ", " + format_number(v.z) + ")";
  }

  static constexpr const char* kBeyondReachHint =
      "outputs hold coordinates as 32-bit floats, which end at 3.4e38: check the offsets and sizes in the rule "
      "chain";

  // Sums of finite sizes or priorities can still overflow to inf, which
  // would silently give every part nothing or pick the last option.
  [[noreturn, gnu::cold, gnu::noinline]] void sum_overflows(NodeId id, const std::string& what) {
    fail_here(ErrorKind::Input, loc(id), what + " add up to more than 1.8e+308, the largest number",
              "shares (~) and priorities count only by their ratios: divide them all by the same number "
              "(absolute sizes this large fit no plot)");
  }

  [[noreturn, gnu::cold, gnu::noinline]] void negative_size(const CompiledExpr& e, double v, const char* what) {
    fail_here(ErrorKind::Input, e.source->loc(), std::string(what) + " is negative (" + format_number(v) + ")",
              "sizes are lengths (or shares, with ~) and must be >= 0");
  }

  void count_operation(NodeId id, std::uint64_t n = 1) {
    operations_ += n;
    if (operations_ > opt_.limits.max_operations) too_many_operations(id);
  }

  [[noreturn, gnu::cold, gnu::noinline]] void too_many_operations(NodeId id) {
    fail_here(ErrorKind::Limit, loc(id),
              "more than " + std::to_string(opt_.limits.max_operations) + " operations in one derivation",
              "raise the limit with --max-operations, or check the grammar for runaway repetition");
  }

  // A new terminal filling s (and its label), the last in the buffer.
  Terminal& emit(LabelId label, const Scope& s, NodeId id) {
    if (terminals_left_ == 0) too_many_terminals(id);
    --terminals_left_;
    if (!opt_.keep_terminals) terminals_.clear();  // the one slot the caller finishes
    if (opt_.trace) [[unlikely]]
      trace(id);
    return terminals_.emplace_back(Terminal{label, false, Rgb{}, s});
  }

  [[noreturn, gnu::cold, gnu::noinline]] void too_many_terminals(NodeId id) {
    fail_here(ErrorKind::Limit, loc(id),
              "more than " + std::to_string(opt_.limits.max_terminals) + " terminals in one derivation",
              "raise the limit with --max-terminals, or check the grammar for runaway recursion");
  }

  void node(const Target& t, const Scope& s, std::uint64_t slot_key, std::uint64_t key);

  // Runs a child node on the part [from, from + length) of s along a.
  // Leaves, the most common children, are handled here without a
  // recursive call: a nil costs one count, a primitive one emit, its
  // scope sliced where it is stored.
  void child(const Target& t, const Scope& s, Axis a, double from, double length, std::uint64_t slot,
             std::uint64_t key) {
    if (t.kind == OpKind::Primitive) {
      count_operation(t.node);
      emit(t.index, s, t.node).scope.slice_in_place(a, from, length);
      return;
    }
    if (t.kind == OpKind::Nil) return count_operation(t.node);
    node(t, s.slice(a, from, length), slot, key);
  }

  void split(const SplitOp& op, NodeId id, const Scope& s, std::uint64_t key, RandomStream& rng) {
    const Axis a = axis(op.axis, rng, "the axis of split");
    const double length = s.extent(a);
    const PartOp* parts = prog_.parts.data() + op.first;
    PartValues share(op.literal ? 0 : op.count);
    double absolute = op.absolute, relative = op.relative;
    if (!op.literal) {
      for (std::size_t i = 0; i < op.count; ++i) {
        share[i] = size_value(parts[i].size, rng, "a split size");
        (parts[i].relative ? relative : absolute) += share[i];
      }
    }
    if (!(absolute + relative < std::numeric_limits<double>::infinity())) sum_overflows(id, "the sizes of this split");
    // Absolute parts take what they ask for; relative parts share the rest.
    // When the absolute parts alone exceed the scope, they shrink in
    // proportion and the relative parts get nothing (docs/grammar.md, split).
    const double abs_scale = absolute > length ? length / absolute : 1.0;
    const double rel_unit = (absolute < length && relative > 0) ? (length - absolute) / relative : 0.0;
    double from = 0;
    for (std::size_t i = 0; i < op.count; ++i) {
      const double v = op.literal ? parts[i].size.literal : share[i];
      const double len = parts[i].relative ? v * rel_unit : v * abs_scale;
      if (len > 0) {
        if (opt_.trace) [[unlikely]]
          path_.push_back({id, static_cast<std::uint32_t>(i), a});
        child(parts[i].child, s, a, from, len, i, key);
        if (opt_.trace) [[unlikely]]
          path_.pop_back();
      }
      from += len;
    }
  }

  void repeat(const RepeatOp& op, NodeId id, const Scope& s, std::uint64_t key, RandomStream& rng) {
    const Axis a = axis(op.axis, rng, "the axis of repeat");
    const double tile = number(op.amount, rng, "the tile size of repeat");
    if (!(tile > 0))
      fail_here(ErrorKind::Input, op.amount.source->loc(),
                "the tile size of repeat is " + format_number(tile) + "; it must be > 0",
                "give a tile length in metres, or use repeatN(axis, count) for a number of tiles");
    const double count = repeat_tile_count(s.extent(a), tile);
    if (count > double(opt_.limits.max_operations))
      fail_here(ErrorKind::Limit, loc(id), "repeat would make " + format_number(count) + " tiles",
                "raise the limit with --max-operations, or use a larger tile size");
    tiles(a, s, static_cast<std::uint64_t>(count), op.child, id, key);
  }

  void repeat_n(const RepeatOp& op, NodeId id, const Scope& s, std::uint64_t key, RandomStream& rng) {
    const Axis a = axis(op.axis, rng, "the axis of repeatN");
    const double count = std::round(number(op.amount, rng, "the count of repeatN"));
    if (count <= 0) return;
    if (count > double(opt_.limits.max_operations))
      fail_here(ErrorKind::Limit, op.amount.source->loc(), "repeatN asks for " + format_number(count) + " tiles",
                "raise the limit with --max-operations, or ask for fewer tiles");
    tiles(a, s, static_cast<std::uint64_t>(count), op.child, id, key);
  }

  void tiles(Axis a, const Scope& s, std::uint64_t count, const Target& child, NodeId id, std::uint64_t key) {
    count_operation(id, count);
    const double length = s.extent(a);
    const double tile = length / static_cast<double>(count);
    for (std::uint64_t i = 0; i < count; ++i) {
      if (opt_.trace) [[unlikely]]
        path_.push_back({id, static_cast<std::uint32_t>(i), a});
      this->child(child, s, a, tile * static_cast<double>(i), tile, i, key);
      if (opt_.trace) [[unlikely]]
        path_.pop_back();
    }
  }

  void choose(const ChooseOp& op, NodeId id, const Scope& s, std::uint64_t key, RandomStream& rng) {
    const OptionOp* options = prog_.options.data() + op.first;
    PartValues weight(op.count);
    double total = 0;
    for (std::size_t i = 0; i < op.count; ++i) {
      const OptionOp& o = options[i];
      double w = 0;
      if (o.condition.form == ExprForm::Absent || number(o.condition, rng, "a condition") != 0.0) {
        w = number(o.priority, rng, "a priority");
        if (w < 0) w = 0;  // a priority <= 0 never wins
      }
      weight[i] = w;
      total += w;
    }
    if (total == std::numeric_limits<double>::infinity()) priorities_overflow(id);
    if (total <= 0) {
      no_rule_applies(id);
      return;
    }
    const double target = rng.uniform() * total;
    double running = 0;
    std::size_t pick = op.count;
    for (std::size_t i = 0; i < op.count; ++i) {
      if (weight[i] <= 0) continue;
      running += weight[i];
      pick = i;
      if (target < running) break;
    }
    node(options[pick].child, s, pick, key);
  }

  // How messages name a choose: the rules of the running rule's label when
  // it is that rule's body, else a choice inside it.
  std::string who_chooses(NodeId id) const {
    const RuleId rule = chain_.back().rule;
    return g_.rules[rule].body == id ? "'" + g_.rules[rule].label + "'" : "the choice";
  }

  [[noreturn, gnu::cold, gnu::noinline]] void priorities_overflow(NodeId id) {
    sum_overflows(id, "the priorities of the rules of " + who_chooses(id));
  }

  [[gnu::cold, gnu::noinline]] void no_rule_applies(NodeId id) {
    // The choose is a rule's body when it is the running rule's.
    const RuleId rule = chain_.back().rule;
    const bool is_body = g_.rules[rule].body == id;
    std::string who = who_chooses(id);
    if (opt_.strict)
      fail_here(ErrorKind::Input, loc(id), "no rule of " + who + " applies (every condition is false or priority <= 0)",
                "add a rule without a condition, or run without --strict to derive nothing there");
    if (is_body && warned_[rule]) return;
    if (is_body) warned_[rule] = true;
    out_.warnings.push_back(format_warning(g_.source_name, loc(id),
                                           "no rule of " + who + " applies here; it derives nothing (first seen via " +
                                               describe_chain() + ")"));
  }

  void call(const CallOp& op, NodeId id, const Scope& s, std::uint64_t key, RandomStream& rng) {
    if (chain_.size() >= opt_.limits.max_depth) too_deep(id);
    // --max-depth counts calls; the stack holds bytes (stack_guard.hpp).
    if (stack_.exhausted()) stack_full(id);
    // Arguments are evaluated in the caller's scope before the callee's frame exists.
    const std::size_t base = params_top_;
    if (base + op.count > params_.size()) params_.resize(2 * (base + op.count));
    for (std::uint32_t k = 0; k < op.count; ++k) {
      // Evaluated before it is stored: value() may read the caller's
      // arguments, which the resize above may have moved.
      const Value v = value(prog_.args[op.first + k], rng);
      params_[params_top_++] = v;
    }
    chain_.push_back({op.rule, base});
    const std::size_t caller_base = params_base_;
    params_base_ = base;
    node(op.body, s, 0, key);
    params_base_ = caller_base;
    chain_.pop_back();
    params_top_ = base;
  }

  [[noreturn, gnu::cold, gnu::noinline]] void too_deep(NodeId id) {
    fail_here(ErrorKind::Limit, loc(id), "rule calls nested deeper than " + std::to_string(opt_.limits.max_depth),
              "raise the limit with --max-depth, or check for recursion that never stops");
  }

  [[noreturn, gnu::cold, gnu::noinline]] void stack_full(NodeId id) {
    fail_here(ErrorKind::Limit, loc(id),
              "rule calls nested " + std::to_string(chain_.size()) + " deep fill this thread's " +
                  stack_.size_text() + " stack (below --max-depth " +
                  std::to_string(opt_.limits.max_depth) + ")",
              "check for recursion that never stops; a grammar this deep needs a larger stack (ulimit -s)");
  }

  void translate(const TransformOp& op, NodeId id, const Scope& s, std::uint64_t key, RandomStream& rng) {
    glm::dvec3 d;
    for (int i = 0; i < 3; ++i) {
      const double v = number(op.amount[i], rng, "a T offset");
      d[i] = op.relative[i] ? v * s.size[i] : v;
    }
    Scope moved = s;
    moved.origin += s.frame * d;
    check_reach(moved, id, "T moves the scope");
    node(op.child, moved, 0, key);
  }

  void scale(const TransformOp& op, NodeId id, const Scope& s, std::uint64_t key, RandomStream& rng) {
    Scope resized = s;
    for (int i = 0; i < 3; ++i) {
      const double v = size_value(op.amount[i], rng, "an S size");
      resized.size[i] = op.relative[i] ? v * s.size[i] : v;
    }
    check_reach(resized, id, "S makes the scope reach");
    node(op.child, resized, 0, key);
  }

  void colour(const ColourOp& op, NodeId id, const Scope& s, RandomStream& rng) {
    Rgb c;
    float* component[3] = {&c.red, &c.green, &c.blue};
    for (int i = 0; i < 3; ++i)
      *component[i] = static_cast<float>(std::clamp(number(op.rgb[i], rng, "a colour component"), 0.0, 1.0));
    Terminal& t = emit(rect_label_, s, id);
    t.coloured = true;
    t.colour = c;
  }

  [[gnu::cold, gnu::noinline]] void trace(NodeId id) {
    TerminalTrace t;
    t.at = loc(id);
    for (const Frame& f : chain_) t.rules.push_back(f.rule);
    t.chain = describe_chain();
    t.path = path_;
    out_.traces.push_back(std::move(t));
  }

  std::string describe_chain() const {
    return rule_chain_text(
        g_, chain_.size(), [&](std::size_t i) { return chain_[i].rule; },
        [&](std::size_t i, std::size_t k) {
          const std::size_t at = chain_[i].params + k;
          return at < params_top_ ? params_[at].describe() : std::string("?");
        });
  }

  const Program& prog_;
  const Grammar& g_;
  const DeriveOptions& opt_;
  Derivation& out_;
  std::vector<Terminal>& terminals_;
  LabelId rect_label_ = 0;
  std::vector<Value> constants_;
  // The size of the scope of the node being derived, for size(axis); none
  // while constants and @scope are evaluated.
  const double* scope_size_ = nullptr;
  std::vector<Value> params_;     // the arguments of every call in the chain, from 0 to params_top_
  std::size_t params_top_ = 0;
  std::size_t params_base_ = 0;  // the running rule's first argument in params_
  std::vector<Frame> chain_;
  std::vector<bool> warned_;
  std::uint64_t operations_ = 0;
  std::uint64_t terminals_left_ = opt_.limits.max_terminals;
  const StackGuard& stack_ = StackGuard::for_this_thread();
  std::vector<TerminalTrace::Step> path_;  // with DeriveOptions::trace: the parts and tiles entered
};

void Deriver::node(const Target& t, const Scope& s, std::uint64_t slot, std::uint64_t parent_key) {
  count_operation(t.node);
  // Leaves draw nothing and have no children: no key to compute.
  if (t.kind == OpKind::Primitive) {
    emit(t.index, s, t.node);
    return;
  }
  if (t.kind == OpKind::Nil) return;
  const std::uint64_t key = child_key(parent_key, slot);
  RandomStream rng(key);
  // The node's expressions read its scope (size(axis)); its parent's,
  // evaluated after this returns, read the parent's again.
  struct Restore {
    const double*& slot;
    const double* saved;
    ~Restore() { slot = saved; }
  } restore{scope_size_, std::exchange(scope_size_, &s.size[0])};
  switch (t.kind) {
    case OpKind::Split: return split(prog_.splits[t.index], t.node, s, key, rng);
    case OpKind::Repeat: return repeat(prog_.repeats[t.index], t.node, s, key, rng);
    case OpKind::RepeatN: return repeat_n(prog_.repeats[t.index], t.node, s, key, rng);
    case OpKind::Choose: return choose(prog_.chooses[t.index], t.node, s, key, rng);
    case OpKind::Call: return call(prog_.calls[t.index], t.node, s, key, rng);
    case OpKind::Translate: return translate(prog_.transforms[t.index], t.node, s, key, rng);
    case OpKind::Scale: return scale(prog_.transforms[t.index], t.node, s, key, rng);
    case OpKind::Rotate: {
      const RotateOp& op = prog_.rotates[t.index];
      const Axis a = axis(op.axis, rng, "the axis of R");
      const double angle = number(op.angle, rng, "the angle of R");
      const Scope turned = rotated(s, a, angle);
      check_reach(turned, t.node, "R turns the scope to reach");
      return node(op.child, turned, 0, key);
    }
    case OpKind::Comp: {
      const CompOp& op = prog_.comps[t.index];
      for (std::uint32_t i = 0; i < op.count; ++i) {
        const FaceOp& f = prog_.faces[op.first + i];
        node(f.child, face_scope(s, f.face), static_cast<std::uint64_t>(f.face), key);
      }
      return;
    }
    case OpKind::Colour: return colour(prog_.colours[t.index], t.node, s, rng);
    case OpKind::Primitive:
    case OpKind::Nil: break;
  }
}

}  // namespace

Derivation derive(const Program& program, const DeriveOptions& options) {
  // Terminals collect in a buffer this thread keeps from one derivation to
  // the next, and leave as one exact-size copy: no growth on the hot path,
  // and no spare capacity held by callers that keep many derivations.
  thread_local std::vector<Terminal> buffer;
  struct Trim {
    ~Trim() {
      buffer.clear();
      if (buffer.capacity() > kKeptTerminals) std::vector<Terminal>().swap(buffer);
    }
  } trim;
  buffer.clear();
  Derivation out;
  Deriver(program, options, out, buffer).run();
  if (options.keep_terminals) out.terminals.assign(buffer.begin(), buffer.end());
  return out;
}

Derivation derive(const Grammar& grammar, const DeriveOptions& options) { return derive(compile(grammar), options); }

glm::dvec3 derive_start_size(const Program& program, const DeriveOptions& options) {
  std::vector<Terminal> none;
  Derivation out;
  return Deriver(program, options, out, none).start_only();
}

}  // namespace vern
