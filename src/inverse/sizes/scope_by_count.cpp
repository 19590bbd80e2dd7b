#include "inverse/sizes/scope_by_count.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <string>

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

}  // namespace

std::size_t tie_scope_to_counts(Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options) {
  if (examples.size() < 3) return 0;
  const std::vector<NodeId> calls = calls_made_once(g);
  if (calls.empty()) return 0;
  std::vector<CheckResult> results;
  if (!derives_examples(g, examples, options, results)) return 0;
  const double tol = options.tolerance;

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
      std::optional<std::uint32_t> constant;
      for (int axis = 0; axis < 3; ++axis) {
        if (g.scope[static_cast<std::size_t>(axis)].uses_params()) continue;
        std::vector<double> y;
        for (const Example& e : examples) y.push_back(example_size(e)[axis]);
        Fit f = line_fit(x, y);
        f.worst = worst_miss(x, y, f.a, f.b);
        if (f.worst > tol || std::abs(f.b) <= tol) continue;
        f = short_line(x, y, f, tol);
        if (!constant) {
          constant = static_cast<std::uint32_t>(g.constants.size());
          g.constants.push_back({count_name(g, call, drawn[m]), call.args[drawn[m]], {}});
          call.args[drawn[m]] = Expr::constant(*constant);
          changed = true;
        }
        // The line as joint sizes write one in a parameter, the parameter
        // then made the constant.
        Linear line;
        line.c0 = f.a;
        line.add(0, f.b);
        Expr size = linear_expr(line);
        for (std::size_t i = 0; i < size.nodes().size(); ++i)
          if (size.node(i).kind == ExprKind::Param) size.set_leaf(i, Expr::constant(*constant).node(0));
        g.scope[static_cast<std::size_t>(axis)] = std::move(size);
        ++tied;
      }
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
