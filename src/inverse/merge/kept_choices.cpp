#include "inverse/merge/kept_choices.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>

#include "inverse/merge/equal_options.hpp"

namespace vern {

namespace {

// Drawn freely, as many examples as this would show two kinds together
// for their never doing so to say they are kept: e^-3, one chance in 20.
constexpr double kExpectedTogether = 3;

// What the witnesses say of one choice: per example, how often it was
// drawn and which alternatives it took.
struct Taken {
  std::vector<std::size_t> draws;                  // per example
  std::vector<std::vector<std::size_t>> options;   // per example: times each alternative was taken
};

Taken taken_by(const std::vector<CheckResult>& results, NodeId choose, std::size_t options) {
  Taken t;
  for (const CheckResult& r : results) {
    t.draws.push_back(0);
    t.options.emplace_back(options, 0);
    for (const CheckStep& step : r.steps)
      if (step.kind == CheckStep::Kind::Alternative && step.node == choose && step.index < options) {
        ++t.draws.back();
        ++t.options.back()[step.index];
      }
  }
  return t;
}

// The kinds kept per building among a choice's alternatives, if there are
// two or more: pairwise never in one example, each in two or more, and
// expected together in kExpectedTogether examples or more if drawn freely.
std::vector<std::size_t> kept_kinds(const Taken& t, std::size_t options) {
  std::vector<double> share(options, 0);
  double draws = 0;
  for (std::size_t e = 0; e < t.draws.size(); ++e) {
    draws += static_cast<double>(t.draws[e]);
    for (std::size_t i = 0; i < options; ++i) share[i] += static_cast<double>(t.options[e][i]);
  }
  if (!(draws > 0)) return {};
  for (double& s : share) s /= draws;
  auto examples_with = [&](std::size_t i) {
    std::size_t n = 0;
    for (const auto& o : t.options) n += o[i] > 0 ? 1 : 0;
    return n;
  };
  auto exclusive = [&](std::size_t i, std::size_t j) {
    double expected = 0;
    for (std::size_t e = 0; e < t.draws.size(); ++e) {
      if (t.options[e][i] > 0 && t.options[e][j] > 0) return false;
      const double m = static_cast<double>(t.draws[e]);
      expected += 1 - std::pow(1 - share[i], m) - std::pow(1 - share[j], m) + std::pow(std::max(0.0, 1 - share[i] - share[j]), m);
    }
    return expected >= kExpectedTogether;
  };
  std::vector<std::size_t> order(options);
  for (std::size_t i = 0; i < options; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return share[a] > share[b]; });
  std::vector<std::size_t> kinds;
  for (const std::size_t i : order) {
    if (examples_with(i) < 2) continue;
    if (std::all_of(kinds.begin(), kinds.end(), [&](std::size_t k) { return exclusive(i, k); })) kinds.push_back(i);
  }
  if (kinds.size() < 2) return {};
  std::sort(kinds.begin(), kinds.end());
  return kinds;
}

// The rules that lead to `rule` (itself included): it and every rule
// that calls one of them.
std::set<RuleId> leading_to(const Grammar& g, RuleId rule) {
  std::set<RuleId> out{rule};
  for (bool grew = true; grew;) {
    grew = false;
    for (RuleId r = 0; r < g.rules.size(); ++r) {
      if (out.count(r)) continue;
      std::vector<NodeId> stack{g.rules[r].body};
      std::set<NodeId> seen;
      bool calls = false;
      while (!stack.empty() && !calls) {
        const NodeId n = stack.back();
        stack.pop_back();
        if (!seen.insert(n).second) continue;
        if (const auto* c = std::get_if<Call>(&g.op(n)); c && out.count(c->rule)) calls = true;
        for_each_child(g.op(n), [&](NodeId child) { stack.push_back(child); });
      }
      if (calls) {
        out.insert(r);
        grew = true;
      }
    }
  }
  return out;
}

// A rule's body with every call of a rule in `chain` given one more
// argument: the rule's own parameter `param`.
NodeId passing_on(Grammar& g, NodeId body, const std::set<RuleId>& chain, std::uint32_t param) {
  std::unordered_map<NodeId, NodeId> done;
  std::function<NodeId(NodeId)> copy = [&](NodeId id) {
    if (const auto it = done.find(id); it != done.end()) return it->second;
    Operation op = g.op(id);  // a copy: interning below may grow the arena
    for (NodeId* child : child_slots(op)) *child = copy(*child);
    if (auto* c = std::get_if<Call>(&op); c && chain.count(c->rule)) c->args.push_back(Expr::param(param));
    const NodeId now = g.intern({std::move(op), g.node(id).loc});
    done.emplace(id, now);
    return now;
  };
  return copy(body);
}

// g with rule `rule`'s choice kept per building: its kinds' alternatives
// under `b == k`, the others under every k.
void keep(Grammar& g, RuleId rule, const std::vector<std::size_t>& kinds) {
  const Choose c = std::get<Choose>(g.op(g.rules[rule].body));
  std::set<RuleId> chain = leading_to(g, rule);
  // The start rule keeps no parameter: a rule of its own takes its body,
  // called with the kind drawn once.
  const RuleId start = g.start_rule;
  std::optional<RuleId> moved;
  if (chain.count(start)) {
    moved = static_cast<RuleId>(g.rules.size());
    Rule kept = g.rules[start];
    kept.label += "Kept";
    g.rules.push_back(kept);
    chain.erase(start);
    chain.insert(*moved);
  }
  for (const RuleId r : chain) {
    const auto param = static_cast<std::uint32_t>(g.rules[r].params.size());
    g.rules[r].params.push_back("b");
    if (r != rule) g.rules[r].body = passing_on(g, g.rules[r].body, chain, param);
  }
  // The choice: each kind under its condition, the rest under each.
  const auto param = static_cast<std::uint32_t>(g.rules[rule].params.size() - 1);
  Choose kept_choice;
  for (std::size_t k = 0; k < kinds.size(); ++k) {
    const Expr is_k = Expr::binary(BinaryOp::Eq, Expr::param(param), Expr::number(static_cast<double>(k)));
    for (std::size_t i = 0; i < c.options.size(); ++i) {
      const bool kind = std::find(kinds.begin(), kinds.end(), i) != kinds.end();
      if (kind && i != kinds[k]) continue;
      kept_choice.options.push_back({is_k, c.options[i].priority, c.options[i].child});
    }
  }
  g.rules[rule].body = g.intern({std::move(kept_choice), g.node(g.rules[rule].body).loc});
  if (moved)
    g.rules[start].body = g.intern(
        {Call{*moved, {Expr::call(Function::RandInt,
                                  {Expr::number(0), Expr::number(static_cast<double>(kinds.size() - 1))})}},
         g.node(g.rules[start].body).loc});
}

}  // namespace

std::size_t keep_choices(Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options,
                         Witnesses& witnesses) {
  std::vector<RuleId> candidates;
  for (RuleId r = 0; r < g.rules.size(); ++r) {
    const auto* c = std::get_if<Choose>(&g.op(g.rules[r].body));
    if (c && plain_choice(*c) && g.rules[r].params.empty() && r != g.start_rule) candidates.push_back(r);
  }
  if (candidates.empty()) return 0;
  if (!witnesses_of(g, examples, options, witnesses)) return 0;
  for (const RuleId r : candidates) {
    const NodeId body = g.rules[r].body;
    const std::size_t count = std::get<Choose>(g.op(body)).options.size();
    const std::vector<std::size_t> kinds = kept_kinds(taken_by(witnesses.results, body, count), count);
    if (kinds.empty()) continue;
    Grammar candidate = g;
    keep(candidate, r, kinds);
    std::vector<CheckResult> results;
    if (!derives_examples(candidate, examples, options, results)) continue;
    g = std::move(candidate);
    witnesses.known = false;
    return 1;
  }
  return 0;
}

}  // namespace vern
