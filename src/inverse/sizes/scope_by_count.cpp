#include "inverse/sizes/scope_by_count.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "graph/nodes_below.hpp"
#include "graph/recursive_rules.hpp"
#include "inverse/merge/substitute.hpp"
#include "inverse/sizes/linear_size.hpp"
#include "inverse/sizes/tidy_numbers.hpp"

namespace vern {

namespace {

// A count drawn from a finite set (randint, choice) with nothing of the
// rule it stands in: it can be drawn once, as a constant, where the call
// stands. Check enumerates such an argument at the call, so each
// derivation's steps hold the value it took there.
bool finite_draw(const Expr& e) {
  if (e.empty() || e.uses_params()) return false;
  const ExprNode& root = e.node(e.root());
  if (root.kind != ExprKind::Call) return false;
  const auto f = static_cast<Function>(root.op);
  return f == Function::RandInt || f == Function::Choice;
}

// The calls a derivation makes exactly once, wherever it goes: reached
// from the start rule's body through splits, choices and transforms, not
// through a repeat or another rule; and of a rule that recurses, so that
// the count is what the recursion runs down (the examples' plots are
// checked only where one could follow it: checking them is a fifth of a
// city's inference).
std::vector<NodeId> calls_made_once(const Grammar& g) {
  std::vector<NodeId> calls;
  walk_below(g, g.rules[g.start_rule].body, [&](NodeId id) {
    const Operation& op = g.op(id);
    if (const auto* call = std::get_if<Call>(&op)) {
      if (std::ranges::any_of(call->args, finite_draw)) calls.push_back(id);
      return false;
    }
    return !std::holds_alternative<Repeat>(op) && !std::holds_alternative<RepeatN>(op);
  });
  if (calls.empty()) return calls;
  const std::vector<bool> recursive = recursive_rules(g);
  std::erase_if(calls, [&](NodeId id) { return !recursive[std::get<Call>(g.op(id)).rule]; });
  std::ranges::sort(calls);
  return calls;
}

// The values the call's drawn arguments took in one derivation, in
// argument order; nothing unless each was drawn there exactly once.
std::vector<double> drawn_at(const CheckResult& r, NodeId call, std::size_t draws) {
  std::vector<double> values;
  for (const CheckStep& s : r.steps)
    if (s.kind == CheckStep::Kind::Value && s.node == call) values.push_back(s.value);
  if (values.size() != draws) values.clear();
  return values;
}

// A name for the count no rule or constant has: the callee's label and
// its parameter's ("tiersN").
std::string count_name(const Grammar& g, const Call& call, std::size_t arg) {
  const Rule& callee = g.rules[call.rule];
  std::string param = arg < callee.params.size() ? callee.params[arg] : "count";
  param[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(param[0])));
  std::string name = callee.label + param;
  for (int k = 2; g.find_constant(name) || g.find_rule(name); ++k) name = callee.label + param + std::to_string(k);
  return name;
}

// a + b v, as a person writes it (2.5 + 3 * v reads 3 * v + 2.5).
Expr line_in(const Fit& f, const Expr& v) {
  Expr out = f.b == 1 ? v : Expr::binary(BinaryOp::Mul, Expr::number(f.b), v);
  if (f.a > 0) return Expr::binary(BinaryOp::Add, std::move(out), Expr::number(f.a));
  if (f.a < 0) return Expr::binary(BinaryOp::Sub, std::move(out), Expr::number(-f.a));
  return out;
}

// The count whose line f gives the plot's size along axis a, read at a
// call whose scope is the plot less `less` metres along a (a base cut
// off below it): round((size(a) - (f.a - less)) / f.b).
Expr count_on_plot(Axis a, const Fit& f, double less) {
  const double at = shortest_decimal(f.a - less, 1e-9 * std::max(1.0, std::abs(f.a)));
  Expr v = Expr::call(Function::Size, {Expr::axis(a)});
  if (at > 0) v = Expr::binary(BinaryOp::Sub, std::move(v), Expr::number(at));
  if (at < 0) v = Expr::binary(BinaryOp::Add, std::move(v), Expr::number(-at));
  if (f.b != 1) v = Expr::binary(BinaryOp::Div, std::move(v), Expr::number(f.b));
  return Expr::call(Function::Round, {std::move(v)});
}

// Per axis, how many metres less than the plot a node's scope is, where
// that is the same on every plot: reached from the start rule through
// choices, and splits whose part on the way is their one relative part
// beside parts of literal metres (a base of 6 m under the tiers); along
// any other split's axis, or below anything else, not known.
using Less = std::array<std::optional<double>, 3>;
std::unordered_map<NodeId, Less> calls_on_plot(const Grammar& g) {
  std::unordered_map<NodeId, Less> out;
  std::vector<std::pair<NodeId, Less>> stack{{g.rules[g.start_rule].body, Less{0.0, 0.0, 0.0}}};
  std::unordered_set<NodeId> seen;
  while (!stack.empty()) {
    const auto [id, less] = stack.back();
    stack.pop_back();
    if (!seen.insert(id).second) {
      if (auto it = out.find(id); it != out.end() && it->second != less) it->second = Less{};  // two ways in
      continue;
    }
    const Operation& op = g.op(id);
    if (std::holds_alternative<Call>(op)) {
      out.emplace(id, less);
    } else if (const auto* c = std::get_if<Choose>(&op)) {
      for (const ChooseOption& o : c->options) stack.emplace_back(o.child, less);
    } else if (const auto* s = std::get_if<Split>(&op)) {
      const auto axis = s->axis.literal_axis();
      double metres = 0;
      std::size_t relative = 0;
      bool literal = true;
      for (const SplitPart& p : s->parts) {
        if (p.size.relative) ++relative;
        else if (const auto v = p.size.value.literal()) metres += *v;
        else literal = false;
      }
      for (const SplitPart& p : s->parts) {
        Less below = less;
        if (!axis) {
          below = Less{};
        } else if (p.size.relative && relative == 1 && literal && below[*axis]) {
          *below[*axis] += metres;
        } else {
          below[*axis].reset();
        }
        stack.emplace_back(p.child, below);
      }
    }
  }
  return out;
}

}  // namespace

std::size_t tie_scope_to_counts(Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options) {
  if (examples.size() < 3) return 0;
  const std::vector<NodeId> calls = calls_made_once(g);
  if (calls.empty()) return 0;
  std::vector<CheckResult> results;
  if (!derives_examples(g, examples, options, results)) return 0;
  const double tol = options.tolerance;

  // The calls whose scope is the plot less so many metres.
  const std::unordered_map<NodeId, Less> on_plot = calls_on_plot(g);
  const Grammar before = g;
  std::vector<NodeId> replace(g.node_count(), kNoReplacement);
  std::size_t tied = 0;
  for (const NodeId id : calls) {
    Call call = std::get<Call>(g.op(id));
    std::vector<std::size_t> drawn;
    for (std::size_t k = 0; k < call.args.size(); ++k)
      if (finite_draw(call.args[k])) drawn.push_back(k);
    std::vector<std::vector<double>> values;  // per example
    for (const CheckResult& r : results) values.push_back(drawn_at(r, id, drawn.size()));
    if (std::ranges::any_of(values, [](const auto& v) { return v.empty(); })) continue;
    bool changed = false;
    for (std::size_t m = 0; m < drawn.size(); ++m) {
      std::vector<double> x;
      for (const auto& v : values) x.push_back(v[m]);
      if (std::ranges::max(x) - std::ranges::min(x) < 0.5) continue;  // one count: nothing follows it
      std::vector<std::pair<std::size_t, Fit>> lines;  // the axes that follow the draw
      for (std::size_t axis = 0; axis < 3; ++axis) {
        if (g.scope[axis].uses_params()) continue;
        std::vector<double> y;
        for (const Example& e : examples) y.push_back(example_size(e)[static_cast<glm::length_t>(axis)]);
        Fit f = line_fit(x, y);
        f.worst = worst_miss(x, y, f.a, f.b);
        if (f.worst > tol || std::abs(f.b) <= tol) continue;
        lines.emplace_back(axis, short_line(x, y, f, tol));
      }
      if (lines.empty()) continue;
      changed = true;
      tied += lines.size();
      const Expr draw = call.args[drawn[m]];
      const bool counts = std::ranges::all_of(x, [](double v) { return v == std::round(v); });
      const auto where = on_plot.find(id);
      if (counts && lines.size() == 1 && where != on_plot.end() && where->second[lines[0].first]) {
        // The count read off the scope the call stands on, whatever the
        // plot's size: round((size(z) - 2.5) / 3), or with a 6 m base cut
        // off below, round((size(z) - 2.5) / 3) of the 6 m less; the plot
        // drawn as the line.
        const auto& [axis, f] = lines[0];
        call.args[drawn[m]] = count_on_plot(static_cast<Axis>(axis), f, *where->second[axis]);
        g.scope[axis] = line_in(f, draw);
        continue;
      }
      // Elsewhere (a call whose scope is not the plot less fixed metres,
      // several axes following the draw, sizes rather than counts), the
      // draw becomes a constant the call and the plot share.
      const auto constant = static_cast<std::uint32_t>(g.constants.size());
      g.constants.push_back({count_name(g, call, drawn[m]), draw, {}});
      call.args[drawn[m]] = Expr::constant(constant);
      for (const auto& [axis, f] : lines) g.scope[axis] = line_in(f, Expr::constant(constant));
    }
    if (changed) replace[id] = g.intern({std::move(call), g.node(id).loc});
  }
  if (tied == 0) return 0;
  Rule& start = g.rules[g.start_rule];
  start.body = substitute(g, start.body, replace);
  if (!derives_examples(g, examples, options, results)) {
    g = before;
    return 0;
  }
  return tied;
}

}  // namespace vern
