#include "forward/derive.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "forward/evaluate.hpp"
#include "forward/random_stream.hpp"
#include "forward/stack_guard.hpp"
#include "graph/number_format.hpp"

namespace vern {

namespace {

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
  Deriver(const Grammar& g, const DeriveOptions& o, Derivation& out) : g_(g), opt_(o), out_(out) {
    out_.labels = g.labels();
    auto rect = g.find_label("rect");
    if (rect) {
      rect_label_ = *rect;
    } else {
      rect_label_ = static_cast<LabelId>(out_.labels.size());
      out_.labels.emplace_back("rect");
    }
    warned_.resize(g.rules.size(), false);
    params_.reserve(64);
    out_.terminals.reserve(256);
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
    chain_.push_back({g_.start_rule, 0, g_.rules[g_.start_rule].loc});
    node(g_.rules[g_.start_rule].body, out_.start, 0, child_key(root, 3));
    chain_.pop_back();
  }

  [[noreturn]] void fail_here(ErrorKind kind, SourceLoc loc, const std::string& message, const std::string& hint) {
    std::string text = format_message(g_.source_name, loc, message);
    text += "\n  rule chain: " + describe_chain();
    if (!hint.empty()) text += "\n  hint: " + hint;
    throw Error(kind, text);
  }

 private:
  struct Frame {
    RuleId rule;
    std::size_t params;  // index of this call's arguments in params_
    SourceLoc call;
  };

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
    }
    return size;
  }

  EvalContext context(RandomStream& rng) const { return {params_.data() + params_base_, constants_.data(), &rng}; }

  double number(const Expr& e, RandomStream& rng, const char* what) {
    try {
      return evaluate_number(e, context(rng), what);
    } catch (const EvaluationError& err) {
      fail_here(ErrorKind::Input, err.loc, err.message, err.hint);
    }
  }

  Axis axis(const Expr& e, RandomStream& rng, const char* what) {
    try {
      return evaluate_axis(e, context(rng), what);
    } catch (const EvaluationError& err) {
      fail_here(ErrorKind::Input, err.loc, err.message, err.hint);
    }
  }

  Value value(const Expr& e, RandomStream& rng) {
    try {
      return evaluate(e, context(rng));
    } catch (const EvaluationError& err) {
      fail_here(ErrorKind::Input, err.loc, err.message, err.hint);
    }
  }

  // A size that cannot be negative or NaN: GRAMMAR.md gives them no meaning.
  double size_value(const Size& s, RandomStream& rng, const char* what) {
    const double v = number(s.value, rng, what);
    if (v < 0)
      fail_here(ErrorKind::Input, s.value.loc(), std::string(what) + " is negative (" + format_number(v) + ")",
                "sizes are lengths (or shares, with ~) and must be >= 0");
    return v;
  }

  void count_operation(SourceLoc loc, std::uint64_t n = 1) {
    operations_ += n;
    if (operations_ > opt_.limits.max_operations)
      fail_here(ErrorKind::Limit, loc,
                "more than " + std::to_string(opt_.limits.max_operations) + " operations in one derivation",
                "raise the limit with --max-operations, or check the grammar for runaway repetition");
  }

  void emit(LabelId label, const Scope& s, SourceLoc loc, const Rgb* colour = nullptr) {
    if (out_.terminals.size() >= opt_.limits.max_terminals)
      fail_here(ErrorKind::Limit, loc, "more than " + std::to_string(opt_.limits.max_terminals) + " terminals in one derivation",
                "raise the limit with --max-terminals, or check the grammar for runaway recursion");
    // Built in place: the scope is copied once, straight into the vector.
    out_.terminals.push_back(Terminal{label, colour != nullptr, colour ? *colour : Rgb{}, s});
  }

  void node(NodeId id, const Scope& s, std::uint64_t slot_key, std::uint64_t key);

  // Runs a child node. Leaves, the most common children, are handled here
  // without a recursive call: a nil costs one count, a primitive one emit.
  void child(NodeId id, const Scope& s, std::uint64_t slot, std::uint64_t key) {
    const Node& n = g_.node(id);
    if (const auto* p = std::get_if<Primitive>(&n.op)) {
      count_operation(n.loc);
      return emit(p->label, s, n.loc);
    }
    if (std::holds_alternative<Nil>(n.op)) return count_operation(n.loc);
    node(id, s, slot, key);
  }

  void split(const Split& op, const Scope& s, std::uint64_t key, RandomStream& rng) {
    const Axis a = axis(op.axis, rng, "the axis of split");
    const double length = s.size[static_cast<int>(a)];
    PartValues share(op.parts.size());
    double absolute = 0, relative = 0;
    for (std::size_t i = 0; i < op.parts.size(); ++i) {
      const Size& size = op.parts[i].size;
      share[i] = size_value(size, rng, "a split size");
      (size.relative ? relative : absolute) += share[i];
    }
    // Absolute parts take what they ask for; relative parts share the rest.
    // When the absolute parts alone exceed the scope, they shrink in
    // proportion and the relative parts get nothing (GRAMMAR.md, Sizes).
    const double abs_scale = absolute > length ? length / absolute : 1.0;
    const double rel_unit = (absolute < length && relative > 0) ? (length - absolute) / relative : 0.0;
    double from = 0;
    for (std::size_t i = 0; i < op.parts.size(); ++i) {
      const double len = op.parts[i].size.relative ? share[i] * rel_unit : share[i] * abs_scale;
      if (len > 0) child(op.parts[i].child, s.slice(a, from, len), i, key);
      from += len;
    }
  }

  void tiles(Axis a, const Scope& s, std::uint64_t count, NodeId child, SourceLoc loc, std::uint64_t key) {
    count_operation(loc, count);
    const double length = s.size[static_cast<int>(a)];
    const double tile = length / static_cast<double>(count);
    for (std::uint64_t i = 0; i < count; ++i) this->child(child, s.slice(a, tile * static_cast<double>(i), tile), i, key);
  }

  void choose(const Choose& op, const Node& n, const Scope& s, std::uint64_t key, RandomStream& rng) {
    PartValues weight(op.options.size());
    double total = 0;
    for (std::size_t i = 0; i < op.options.size(); ++i) {
      const ChooseOption& o = op.options[i];
      double w = 0;
      if (o.condition.empty() || number(o.condition, rng, "a condition") != 0.0) {
        w = number(o.priority, rng, "a priority");
        if (w < 0) w = 0;  // a priority <= 0 never wins
      }
      weight[i] = w;
      total += w;
    }
    if (total <= 0) {
      no_rule_applies(n);
      return;
    }
    const double target = rng.uniform() * total;
    double running = 0;
    std::size_t pick = op.options.size();
    for (std::size_t i = 0; i < op.options.size(); ++i) {
      if (weight[i] <= 0) continue;
      running += weight[i];
      pick = i;
      if (target < running) break;
    }
    node(op.options[pick].child, s, pick, key);
  }

  void no_rule_applies(const Node& n) {
    // The choose is a rule's body when it is the running rule's.
    const RuleId rule = chain_.back().rule;
    const bool is_body = &g_.node(g_.rules[rule].body) == &n;
    std::string who = is_body ? "'" + g_.rules[rule].label + "'" : "the choice";
    if (opt_.strict)
      fail_here(ErrorKind::Input, n.loc, "no rule of " + who + " applies (every condition is false or priority <= 0)",
                "add a rule without a condition, or run without --strict to derive nothing there");
    if (is_body && warned_[rule]) return;
    if (is_body) warned_[rule] = true;
    out_.warnings.push_back(format_warning(g_.source_name, n.loc,
                                           "no rule of " + who + " applies here; it derives nothing (first seen via " +
                                               describe_chain() + ")"));
  }

  void call(const Call& op, const Node& n, const Scope& s, std::uint64_t key, RandomStream& rng) {
    if (chain_.size() >= opt_.limits.max_depth)
      fail_here(ErrorKind::Limit, n.loc, "rule calls nested deeper than " + std::to_string(opt_.limits.max_depth),
                "raise the limit with --max-depth, or check for recursion that never stops");
    // --max-depth counts calls; the stack holds bytes (stack_guard.hpp).
    if (stack_.exhausted())
      fail_here(ErrorKind::Limit, n.loc,
                "rule calls nested " + std::to_string(chain_.size()) + " deep fill this thread's " +
                    std::to_string(stack_.size() >> 20) + " MB stack (below --max-depth " +
                    std::to_string(opt_.limits.max_depth) + ")",
                "check for recursion that never stops; a grammar this deep needs a larger stack (ulimit -s)");
    // Arguments are evaluated in the caller's scope before the callee's frame exists.
    const std::size_t base = params_.size();
    for (const auto& a : op.args) {
      const Value v = value(a, rng);
      params_.push_back(v);
    }
    chain_.push_back({op.rule, base, n.loc});
    const std::size_t caller_base = params_base_;
    params_base_ = base;
    node(g_.rules[op.rule].body, s, 0, key);
    params_base_ = caller_base;
    chain_.pop_back();
    params_.resize(base);
  }

  std::string describe_chain() const {
    auto frame_text = [&](const Frame& f) {
      const Rule& r = g_.rules[f.rule];
      std::string t = r.label;
      if (!r.params.empty()) {
        t += "(";
        for (std::size_t i = 0; i < r.params.size(); ++i) {
          t += (i ? ", " : "");
          t += f.params + i < params_.size() ? params_[f.params + i].describe() : "?";
        }
        t += ")";
      }
      return t;
    };
    std::string text;
    const std::size_t n = chain_.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (n > 12 && i == 4) {
        text += " > ... (" + std::to_string(n - 10) + " more) ...";
        i = n - 6;
        continue;
      }
      text += (i ? " > " : "") + frame_text(chain_[i]);
    }
    return text.empty() ? "(none)" : text;
  }

  const Grammar& g_;
  const DeriveOptions& opt_;
  Derivation& out_;
  LabelId rect_label_ = 0;
  std::vector<Value> constants_;
  std::vector<Value> params_;
  std::size_t params_base_ = 0;  // the running rule's first argument in params_
  std::vector<Frame> chain_;
  std::vector<bool> warned_;
  std::uint64_t operations_ = 0;
  const StackGuard& stack_ = StackGuard::for_this_thread();
};

void Deriver::node(NodeId id, const Scope& s, std::uint64_t slot, std::uint64_t parent_key) {
  const Node& n = g_.node(id);
  count_operation(n.loc);
  // Leaves draw nothing and have no children: no key to compute.
  if (const auto* p = std::get_if<Primitive>(&n.op)) return emit(p->label, s, n.loc);
  if (std::holds_alternative<Nil>(n.op)) return;
  const std::uint64_t key = child_key(parent_key, slot);
  RandomStream rng(key);
  switch (n.op.index()) {
    case 0: return split(*std::get_if<Split>(&n.op), s, key, rng);
    case 1: {
      const auto& op = *std::get_if<Repeat>(&n.op);
      const Axis a = axis(op.axis, rng, "the axis of repeat");
      const double tile = number(op.size, rng, "the tile size of repeat");
      if (!(tile > 0))
        fail_here(ErrorKind::Input, op.size.loc(), "the tile size of repeat is " + format_number(tile) + "; it must be > 0",
                  "give a tile length in metres, or use repeatN(axis, count) for a number of tiles");
      const double q = s.size[static_cast<int>(a)] / tile;
      // ceil, forgiving float noise: 0.7 / 0.1 is 7.000000000000001 and means 7.
      const double count = std::max(1.0, std::ceil(q - 1e-9 * std::max(1.0, q)));
      if (count > double(opt_.limits.max_operations))
        fail_here(ErrorKind::Limit, n.loc, "repeat would make " + format_number(count) + " tiles",
                  "raise the limit with --max-operations, or use a larger tile size");
      return tiles(a, s, static_cast<std::uint64_t>(count), op.child, n.loc, key);
    }
    case 2: {
      const auto& op = *std::get_if<RepeatN>(&n.op);
      const Axis a = axis(op.axis, rng, "the axis of repeatN");
      const double count = std::round(number(op.count, rng, "the count of repeatN"));
      if (count <= 0) return;
      if (count > double(opt_.limits.max_operations))
        fail_here(ErrorKind::Limit, op.count.loc(), "repeatN asks for " + format_number(count) + " tiles",
                  "raise the limit with --max-operations, or ask for fewer tiles");
      return tiles(a, s, static_cast<std::uint64_t>(count), op.child, n.loc, key);
    }
    case 3: return choose(*std::get_if<Choose>(&n.op), n, s, key, rng);
    case 4: return call(*std::get_if<Call>(&n.op), n, s, key, rng);
    case 7: {
      const auto& op = *std::get_if<Translate>(&n.op);
      glm::dvec3 d;
      for (int i = 0; i < 3; ++i) {
        const double v = number(op.offset[i].value, rng, "a T offset");
        d[i] = op.offset[i].relative ? v * s.size[i] : v;
      }
      Scope moved = s;
      moved.origin += s.frame * d;
      return node(op.child, moved, 0, key);
    }
    case 8: {
      const auto& op = *std::get_if<Scale>(&n.op);
      Scope resized = s;
      for (int i = 0; i < 3; ++i) {
        const double v = size_value(op.size[i], rng, "an S size");
        resized.size[i] = op.size[i].relative ? v * s.size[i] : v;
      }
      return node(op.child, resized, 0, key);
    }
    case 9: {
      const auto& op = *std::get_if<Rotate>(&n.op);
      const Axis a = axis(op.axis, rng, "the axis of R");
      const double angle = number(op.angle, rng, "the angle of R");
      return node(op.child, rotated(s, a, angle), 0, key);
    }
    case 10: {
      const auto& op = *std::get_if<Comp>(&n.op);
      for (const auto& part : op.parts)
        node(part.child, face_scope(s, part.face), static_cast<std::uint64_t>(part.face), key);
      return;
    }
    case 11: {
      const auto& op = *std::get_if<Colour>(&n.op);
      const Rgb c{static_cast<float>(std::clamp(number(op.red, rng, "a colour component"), 0.0, 1.0)),
                  static_cast<float>(std::clamp(number(op.green, rng, "a colour component"), 0.0, 1.0)),
                  static_cast<float>(std::clamp(number(op.blue, rng, "a colour component"), 0.0, 1.0))};
      return emit(rect_label_, s, n.loc, &c);
    }
    default: break;
  }
}

}  // namespace

Derivation derive(const Grammar& grammar, const DeriveOptions& options) {
  Derivation out;
  Deriver(grammar, options, out).run();
  return out;
}

}  // namespace vern
