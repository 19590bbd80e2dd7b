#include "inverse/share_splits.hpp"

#include <algorithm>
#include <cctype>
#include <unordered_map>
#include <unordered_set>

#include "inverse/fit_distribution.hpp"
#include "inverse/rule_naming.hpp"
#include "inverse/substitute.hpp"
#include "inverse/tidy_numbers.hpp"

namespace vern {

namespace {

// The lines of one run of a split (a repeat runs it once per tile, on one
// path): each starts where the part index does not go up.
struct SplitRun {
  NodeId split = 0;
  std::vector<const MatchedPart*> parts;
};

std::vector<SplitRun> runs_of(const std::vector<MatchedPart>& parts) {
  std::vector<SplitRun> out;
  for (const MatchedPart& m : parts) {
    if (out.empty() || out.back().split != m.split || out.back().parts.back()->path != m.path ||
        out.back().parts.back()->part >= m.part)
      out.push_back({m.split, {}});
    out.back().parts.push_back(&m);
  }
  return out;
}

// Up to three primitive labels below a node and its axis: rectZ.
std::string describe(const Grammar& g, NodeId id) {
  std::vector<std::string> labels;
  std::vector<NodeId> stack{id};
  std::unordered_set<NodeId> seen;
  while (!stack.empty() && labels.size() < 3) {
    const NodeId n = stack.back();
    stack.pop_back();
    if (!seen.insert(n).second) continue;
    const Operation& op = g.op(n);
    if (const auto* p = std::get_if<Primitive>(&op)) {
      if (std::ranges::find(labels, g.label(p->label)) == labels.end()) labels.push_back(g.label(p->label));
      continue;
    }
    if (const auto* c = std::get_if<Call>(&op)) stack.push_back(g.rules[c->rule].body);
    std::vector<NodeId> children;
    for_each_child(op, [&](NodeId child) { children.push_back(child); });
    stack.insert(stack.end(), children.rbegin(), children.rend());
  }
  std::string out;
  for (const std::string& label : labels) {
    bool first = true;  // of a label after the first: upper case
    for (char ch : label) {
      if (!std::isalnum(static_cast<unsigned char>(ch))) continue;
      out += first && !out.empty() ? static_cast<char>(std::toupper(static_cast<unsigned char>(ch))) : ch;
      first = false;
    }
  }
  if (out.empty() || !std::isalpha(static_cast<unsigned char>(out[0]))) out = "part" + out;
  const Expr& axis = std::get<Split>(g.op(id)).axis;
  const ExprNode& a = axis.node(axis.root());
  if (a.kind == ExprKind::Axis) out += static_cast<char>('X' + a.op);
  return out;
}

// The two relative parts of a split whose relative parts are exactly two,
// both drawn, nothing using a parameter.
std::optional<std::pair<std::size_t, std::size_t>> two_shares(const Split& s) {
  std::vector<std::size_t> relative;
  for (std::size_t i = 0; i < s.parts.size(); ++i) {
    if (s.parts[i].size.value.uses_params()) return std::nullopt;
    if (s.parts[i].size.relative) relative.push_back(i);
  }
  if (relative.size() != 2) return std::nullopt;
  for (std::size_t i : relative)
    if (!s.parts[i].size.value.draws_random()) return std::nullopt;
  return std::make_pair(relative[0], relative[1]);
}

}  // namespace

std::size_t share_splits(Grammar& g, const std::vector<CheckResult>& results, const ShareOptions& opt) {
  struct Seen {
    std::vector<std::pair<double, double>> lengths;  // the two parts, per run
    bool lined_up = true;
  };
  std::unordered_map<NodeId, Seen> seen;
  for (const CheckResult& r : results)
    for (const SplitRun& run : runs_of(r.parts)) {
      const auto* split = std::get_if<Split>(&g.op(run.split));
      if (!split) continue;
      const auto pair = two_shares(*split);
      if (!pair) continue;
      Seen& s = seen[run.split];
      double a = -1, b = -1;
      for (const MatchedPart* m : run.parts) {
        if (m->part == pair->first) a = m->length;
        if (m->part == pair->second) b = m->length;
      }
      if (a < 0 || b < 0 || !(a + b > 0)) s.lined_up = false;
      else s.lengths.emplace_back(a, b);
    }

  // The rule each changed split runs as, the call that stands for it.
  std::vector<NodeId> replace(g.node_count(), kNoReplacement);
  std::unordered_map<NodeId, RuleId> rule_of;  // changed split -> its rule
  std::unordered_map<RuleId, NodeId> body_of;  // that rule -> the split with shares
  std::vector<std::vector<RuleId>> bodies(g.node_count());
  for (RuleId r = 0; r < g.rules.size(); ++r)
    if (g.rules[r].params.empty() && r != g.start_rule) bodies[g.rules[r].body].push_back(r);  // the start takes none
  std::vector<NodeId> order;
  for (const auto& [id, s] : seen)
    if (s.lined_up && !s.lengths.empty()) order.push_back(id);
  std::ranges::sort(order);  // the rules come out in one order every time
  for (NodeId id : order) {
    const Seen& s = seen[id];
    double total = 0;
    for (const auto& [a, b] : s.lengths) total += (a + b) / static_cast<double>(s.lengths.size());
    total = shortest_decimal(total, total * 0.01);
    std::vector<Observation> shares;
    for (const auto& [a, b] : s.lengths) shares.push_back({total * a / (a + b), 1});
    FitOptions fit;
    fit.resolution = opt.tolerance;
    fit.floor = 0;
    fit.uniform_only = opt.uniform_distributions;
    Distribution d = fit_distribution(shares, fit);
    if (d.kind == DistributionKind::Uniform || d.kind == DistributionKind::TruncatedNormal) {
      if (d.hi >= total) {
        // The rest must stay a share: keep to the shares seen.
        const auto [lo, hi] = std::ranges::minmax(shares, {}, &Observation::value);
        d = Distribution{DistributionKind::Uniform, {}, lo.value, hi.value};
      }
    }
    Split split = std::get<Split>(g.op(id));
    const auto pair = *two_shares(split);
    split.parts[pair.first].size = Size{Expr::param(0), true};
    split.parts[pair.second].size =
        Size{Expr::binary(BinaryOp::Sub, Expr::number(total), Expr::param(0)), true};
    const SourceLoc loc = g.node(id).loc;
    const NodeId shared = g.intern({std::move(split), loc});
    RuleId rule;
    if (!bodies[id].empty()) {
      rule = bodies[id].front();
    } else {
      rule = static_cast<RuleId>(g.rules.size());
      g.rules.push_back(Rule{free_label(g, describe(g, id)), {}, shared, loc});
    }
    g.rules[rule].params = {"s1"};
    rule_of[id] = rule;
    body_of[rule] = shared;
    d = short_decimals(d, opt.tolerance / 4);
    const NodeId call = g.intern({Call{rule, {distribution_expr(d)}}, loc});
    if (replace.size() < g.node_count()) replace.resize(g.node_count(), kNoReplacement);
    replace[id] = call;
  }
  if (rule_of.empty()) return 0;
  // Calls of a rule that now takes the share: with it.
  for (NodeId id = 0; id < replace.size(); ++id)
    if (const auto* c = std::get_if<Call>(&g.op(id)); c && c->args.empty() && body_of.count(c->rule))
      replace[id] = replace[g.rules[c->rule].body];
  for (RuleId r = 0; r < g.rules.size(); ++r) {
    const auto own = body_of.find(r);
    g.rules[r].body = substitute(g, own != body_of.end() ? own->second : g.rules[r].body, replace);
  }
  return rule_of.size();
}

}  // namespace vern
