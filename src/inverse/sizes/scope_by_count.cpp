#include "inverse/sizes/scope_by_count.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <string>
#include <unordered_set>
#include <utility>

#include "graph/nodes_below.hpp"
#include "inverse/merge/substitute.hpp"
#include "inverse/sizes/linear_size.hpp"

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
// through a repeat or another rule.
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

// The count whose line f gives the plot's size along axis a:
// round((size(a) - f.a) / f.b).
Expr count_on_plot(Axis a, const Fit& f) {
  Expr v = Expr::call(Function::Size, {Expr::axis(a)});
  if (f.a > 0) v = Expr::binary(BinaryOp::Sub, std::move(v), Expr::number(f.a));
  if (f.a < 0) v = Expr::binary(BinaryOp::Add, std::move(v), Expr::number(-f.a));
  if (f.b != 1) v = Expr::binary(BinaryOp::Div, std::move(v), Expr::number(f.b));
  return Expr::call(Function::Round, {std::move(v)});
}

}  // namespace

std::size_t tie_scope_to_counts(Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options) {
  if (examples.size() < 3) return 0;
  const std::vector<NodeId> calls = calls_made_once(g);
  if (calls.empty()) return 0;
  std::vector<CheckResult> results;
  if (!derives_examples(g, examples, options, results)) return 0;
  const double tol = options.tolerance;

  // The calls that stand on the plot itself: reached through choices only.
  std::unordered_set<NodeId> on_plot;
  walk_below(g, g.rules[g.start_rule].body, [&](NodeId id) {
    if (std::holds_alternative<Call>(g.op(id))) on_plot.insert(id);
    return std::holds_alternative<Choose>(g.op(id));
  });
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
      if (counts && lines.size() == 1 && on_plot.contains(id)) {
        // The count read off the plot the call stands on, whatever its
        // size: round((size(z) - 2.5) / 3); the plot drawn as the line.
        const auto& [axis, f] = lines[0];
        call.args[drawn[m]] = count_on_plot(static_cast<Axis>(axis), f);
        g.scope[axis] = line_in(f, draw);
        continue;
      }
      // Elsewhere (the call on a part of the plot, several axes following
      // the draw, sizes rather than counts), the draw becomes a constant
      // the call and the plot share.
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
