// Matching alternatives and rule calls (check_matcher.hpp). Alternatives
// are tried in order, those whose condition can hold and whose priority
// can be > 0; a call's random arguments are tried value by value when they
// have few values and become unknowns (check_bindings.hpp) otherwise.
#include "inverse/check/check_matcher.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace vern::check_detail {

std::optional<Matcher::Options> Matcher::options_of(NodeId id, const Choose& op, const Scope& s) {
  Options o;
  o.applicable.assign(op.options.size(), false);
  for (std::size_t i = 0; i < op.options.size(); ++i) {
    const ChooseOption& opt = op.options[i];
    bool can_hold = true, can_fail = false;
    if (!opt.condition.empty()) {
      auto c = evaluate(opt.condition, id, s, "the condition of alternative", i + 1);
      if (!c) return std::nullopt;
      can_hold = !c->support.empty() && !(c->support.is_point() && c->support.lower() == 0.0);
      can_fail = c->support.contains(0.0);
    }
    bool can_win = true, can_lose = false;
    if (can_hold && !opt.priority.empty()) {
      auto p = evaluate(opt.priority, id, s, "the priority of alternative", i + 1);
      if (!p) return std::nullopt;
      can_win = p->support.upper() > 0;
      can_lose = p->support.lower() <= 0;
    }
    o.applicable[i] = can_hold && can_win;
    o.any = o.any || o.applicable[i];
    o.nil_possible = o.nil_possible && (!o.applicable[i] || can_fail || can_lose);
  }
  return o;
}

bool Matcher::match_choose(NodeId id, const Choose& op, const Scope& s, const BoxList& inside) {
  auto o = options_of(id, op, s);
  if (!o) return false;
  // The written order, or (learned_order_) the alternatives that matched
  // most often first, ties in the written order; only a learned order is
  // made into a list (every choose of every check passes here).
  std::vector<std::uint32_t> order;
  std::vector<std::uint32_t>* wins = nullptr;
  if (learned_order_ && op.options.size() > 1) {
    wins = &wins_[id];
    wins->resize(op.options.size(), 0);
    order.resize(op.options.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return (*wins)[a] > (*wins)[b]; });
  }
  for (std::size_t k = 0; k < op.options.size(); ++k) {
    const std::size_t i = wins ? order[k] : k;
    if (!o->applicable[i]) continue;
    const std::size_t mark = witness_.size();
    if (op.options.size() > 1) {
      WitnessLine w = line(WitnessLine::Kind::Alternative, id);
      w.index = i;
      w.count = op.options.size();
      witness_.push_back(std::move(w));
    }
    slot_ = static_cast<std::uint32_t>(i + 1);
    if (match(op.options[i].child, s, inside)) {
      if (wins) ++(*wins)[i];
      return true;
    }
    witness_.resize(mark);
  }
  if (o->nil_possible && inside.empty()) {
    witness_.push_back(line(WitnessLine::Kind::NoAlternative, id));
    return true;
  }
  const std::string name = check_detail::choose_name(g_, id, current_rule());
  if (!o->any)
    return recording() && fail(id, s,
                               "no alternative of '" + name + "' applies here (conditions false or priorities <= 0), " +
                                   "so it derives nothing, but the example has " + list_boxes(inside));
  return recording() && fail(id, s, "no alternative of '" + name + "' matches");
}

std::optional<std::pair<Frame, std::vector<ArgChoice>>> Matcher::setup_call(NodeId id, const Call& op, const Scope& s) {
  const Rule& callee = g_.rules[op.rule];
  if (vars_.depth() >= kMaxDepth) {
    if (recording())
      fail(id, s, "rule calls nested deeper than " + std::to_string(kMaxDepth) + " (derive() stops there)");
    return std::nullopt;
  }
  Frame frame{op.rule, std::vector<Slot>(op.args.size())};
  std::vector<ArgChoice> choices;
  for (std::size_t k = 0; k < op.args.size(); ++k) {
    const Expr& arg = op.args[k];
    const ExprNode& root = arg.node(arg.root());
    // A parameter or constant passed on keeps its identity: a random
    // value used twice stays one value.
    if (arg.nodes().size() == 1 && (root.kind == ExprKind::Param || root.kind == ExprKind::Constant)) {
      frame.params[k] = root.kind == ExprKind::Param ? vars_.param(root.index) : vars_.constant(root.index);
      continue;
    }
    auto p = evaluate(arg, id, s, "argument", k + 1);
    if (!p) return std::nullopt;
    if (p->exact) {
      frame.params[k].value = p->value;
    } else if (auto values = p->support.values(kMaxEnumerated)) {
      if (values->empty()) {
        if (recording())
          fail(id, s,
               "argument " + std::to_string(k + 1) + " of " + callee.label + " (" + expr_text(arg) +
                   ") has no possible value");
        return std::nullopt;
      }
      choices.push_back({k, *values});
    } else {
      // Continuous: an unknown, pinned down by the first split that uses it.
      frame.params[k].unknown = vars_.add({p->support, std::nullopt, k < callee.params.size() ? callee.params[k] : "?",
                                           Origin{&arg, current_rule(), id}});
    }
  }
  return std::make_pair(std::move(frame), std::move(choices));
}

bool Matcher::match_call(NodeId id, const Call& op, const Scope& s, const BoxList& inside) {
  auto setup = setup_call(id, op, s);
  if (!setup) return false;
  const NodeId body_id = g_.rules[op.rule].body;
  auto body = [&] { return match(body_id, s, inside); };
  return each_binding(id, op, setup->first, setup->second, 0, body);
}

}  // namespace vern::check_detail
