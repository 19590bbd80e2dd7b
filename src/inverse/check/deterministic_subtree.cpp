#include "inverse/check/deterministic_subtree.hpp"

#include <algorithm>
#include <cmath>

#include "base/error.hpp"
#include "forward/derive.hpp"

namespace vern {

DeterministicSubtrees::DeterministicSubtrees(const Grammar& g) : g_(g), memo_(g.node_count(), kUnknown) {
  // Constants are evaluated in file order, each from the ones before it.
  for (const Constant& c : g.constants) fixed_constants_.push_back(fixed(c.value));
}

// No draw and no constant that draws. (A parameter is noted apart: it is
// fixed where the call that passes it is.)
bool DeterministicSubtrees::fixed(const Expr& e) const {
  if (e.empty()) return true;
  if (e.draws_random()) return false;
  for (const ExprNode& n : e.nodes())
    if (n.kind == ExprKind::Constant && !(n.index < fixed_constants_.size() && fixed_constants_[n.index])) return false;
  return true;
}

std::int8_t DeterministicSubtrees::classify(NodeId id) {
  if (memo_[id] != kUnknown) return memo_[id];
  // A node met again while it is being classified is recursion: counted
  // as random, so nothing on the cycle is taken for fixed too early.
  memo_[id] = kRandom;
  const Operation& op = g_.op(id);
  std::int8_t out = kFixed;
  if (std::holds_alternative<Translate>(op) || std::holds_alternative<Scale>(op)) out |= kPlaced;
  const auto* choose = std::get_if<Choose>(&op);
  bool one = !(choose && choose->options.size() > 1);
  for (const Expr* e : node_expressions(op)) {
    one = one && fixed(*e);
    if (e->uses_params()) out |= kReadsParams;
  }
  auto below = [&](NodeId child, bool passes_params) {
    if (!one) return;
    const std::int8_t m = classify(child);
    one = m != kRandom;
    out |= m & kPlaced;
    // A rule's body reads the parameters its call passes: the call's own
    // arguments say whether they are fixed.
    if (!passes_params) out |= m & kReadsParams;
  };
  for_each_child(op, [&](NodeId child) { below(child, false); });
  if (const auto* call = std::get_if<Call>(&op)) below(g_.rules[call->rule].body, true);
  memo_[id] = one ? out : kRandom;
  return memo_[id];
}

// A derivation started at the node knows no parameters: only where the
// node reads none (a call passing literals may have a body that reads
// them: the twins of twin_rules.hpp).
bool DeterministicSubtrees::placed(NodeId id) {
  return id < memo_.size() && classify(id) == (kFixed | kPlaced);
}

std::optional<std::string> DeterministicSubtrees::difference(
    NodeId id, const Scope& s, const std::vector<LabelledBox>& boxes, const std::vector<std::uint32_t>& inside,
    double tolerance, const std::function<std::string(const LabelledBox&)>& describe) {
  const std::string said = "derived here (nothing below is random), it ";
  if (!probe_) {
    probe_ = g_;
    probe_->rules.push_back(Rule{"probe", {}, id, {}});
    probe_->start_rule = static_cast<RuleId>(probe_->rules.size() - 1);
  }
  probe_->rules.back().body = id;
  DeriveOptions options;
  options.size = s.size;
  options.limits.max_terminals = inside.size();  // more than the example has here: a difference already
  Derivation d;
  try {
    d = derive(*probe_, options);
  } catch (const Error& e) {
    const std::string what = e.what();
    return said + "fails: " + what.substr(0, what.find('\n'));
  }

  // The example's boxes by label, then min x: each derived box looks for
  // an unused one within the tolerance.
  std::vector<std::uint32_t> order = inside;
  auto before = [&](std::uint32_t a, const std::pair<const std::string*, double>& key) {
    return boxes[a].label != *key.first ? boxes[a].label < *key.first : boxes[a].min.x < key.second;
  };
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return before(a, {&boxes[b].label, boxes[b].min.x});
  });
  std::vector<bool> used(order.size(), false);
  for (const Terminal& t : d.terminals) {
    // The derivation ran on an axis-aligned scope at the origin: into s.
    const Bounds b = world_bounds(Scope{s.origin + s.frame * t.scope.origin, s.frame * t.scope.frame, t.scope.size});
    LabelledBox derived;
    derived.label = d.labels[t.label];
    derived.min = b.min;
    derived.max = b.max;
    auto k = static_cast<std::size_t>(
        std::lower_bound(order.begin(), order.end(), std::pair{&derived.label, b.min.x - tolerance}, before) -
        order.begin());
    bool found = false;
    for (; k < order.size() && !found; ++k) {
      const LabelledBox& e = boxes[order[k]];
      if (e.label != derived.label || e.min.x > b.min.x + tolerance) break;
      bool close = !used[k];
      for (int a = 0; a < 3 && close; ++a)
        close = std::abs(e.min[a] - b.min[a]) <= tolerance && std::abs(e.max[a] - b.max[a]) <= tolerance;
      if (close) used[k] = found = true;
    }
    if (!found) return said + "gives " + describe(derived) + ", which the example does not have";
  }
  for (std::size_t k = 0; k < order.size(); ++k)
    if (!used[k]) return said + "gives nothing for " + describe(boxes[order[k]]);
  return std::nullopt;
}

}  // namespace vern
