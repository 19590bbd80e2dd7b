#include "inverse/merge/twin_rules.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <string>

#include "graph/description_length.hpp"
#include "inverse/merge/substitute.hpp"
#include "inverse/write/rule_naming.hpp"
#include "inverse/write/unused_rules.hpp"

namespace vern {

namespace {

constexpr NodeId kNone = static_cast<NodeId>(-1);
// Each round joins every group it can apart from the others; twins
// inside twins take a round per level of nesting.
constexpr std::size_t kMaxRounds = 64;

bool is_slot(const ExprNode& n) { return n.kind == ExprKind::Number || n.kind == ExprKind::Axis; }

// One number or axis a twin writes, where its twins may write another.
struct Slot {
  ExprNode value;
  friend bool operator==(const Slot&, const Slot&) = default;
};

// Every number becomes 0 and every axis x: what twins share.
void blank(Expr& e) {
  for (std::size_t i = 0; i < e.nodes().size(); ++i) {
    const ExprKind kind = e.node(i).kind;
    if (kind == ExprKind::Number) e.set_leaf(i, {.kind = ExprKind::Number, .number = 0});
    else if (kind == ExprKind::Axis) e.set_leaf(i, {.kind = ExprKind::Axis, .op = 0});
  }
}

// What the grammar writes, node by node, as description_length counts it.
struct Survey {
  std::vector<std::size_t> writes;   // places the node is written (0: unreached)
  std::vector<std::size_t> ops;      // operations written at and below it
  std::vector<std::size_t> numbers;  // number literals written at and below it
  std::vector<NodeId> shape;         // its shape (an id in a scratch grammar; parameters kept); kNone: unreached
  std::vector<bool> reads;           // it or a node below reads a parameter of its rule
};

Survey survey(const Grammar& g) {
  const std::size_t n = g.node_count();
  Survey s{std::vector<std::size_t>(n, 0), std::vector<std::size_t>(n, 0), std::vector<std::size_t>(n, 0),
           std::vector<NodeId>(n, kNone), std::vector<bool>(n, false)};
  for (const Rule& r : g.rules) ++s.writes[r.body];
  // A node's children were added before it, so going down the ids passes
  // every parent before its children.
  for (NodeId id = static_cast<NodeId>(n); id-- > 0;)
    if (s.writes[id] > 0) for_each_child(g.op(id), [&](NodeId c) { s.writes[c] += s.writes[id]; });
  Grammar shapes;  // node ids there name shapes
  for (NodeId id = 0; id < n; ++id) {
    if (s.writes[id] == 0) continue;
    Operation op = g.op(id);
    bool reads_parameter = false;
    s.ops[id] = 1;
    for (Expr* e : expression_slots(op)) {
      reads_parameter = reads_parameter || e->uses_params();
      s.numbers[id] += number_literals(*e);
      blank(*e);
    }
    for (NodeId* c : child_slots(op)) {
      s.ops[id] += s.ops[*c];
      s.numbers[id] += s.numbers[*c];
      reads_parameter = reads_parameter || s.reads[*c];
      *c = s.shape[*c];
    }
    s.reads[id] = reads_parameter;
    s.shape[id] = shapes.intern({std::move(op), {}});
  }
  return s;
}

// The numbers and axes written below id, in writing order: the node's
// expressions, then its children's.
void collect_slots(const Grammar& g, NodeId id, std::vector<Slot>& out) {
  for (const Expr* e : node_expressions(g.op(id)))
    for (const ExprNode& n : e->nodes())
      if (is_slot(n)) out.push_back({n});
  for_each_child(g.op(id), [&](NodeId c) { collect_slots(g, c, out); });
}

// A group of twins and what joining it would do.
struct Plan {
  std::vector<NodeId> members;
  std::vector<std::optional<std::uint32_t>> param_of;  // by slot: its parameter, if it varies
  std::vector<std::vector<Slot>> args;                 // by member: its value of each parameter
  long saving = 0;
  // Twin rules: members are the bodies of these rules (one each), which
  // read their own parameters; the joined rule takes theirs first, then
  // the values they differ in, and their callers pass both.
  std::vector<RuleId> rules;
};

// Twin rules (Plan::rules): rules with parameters whose bodies are twins
// reading those parameters alike (tiers inset by a share s1 of two sizes,
// 4.35 - 2 * s1 and 2.6 - 2 * s1), each body written only as its rule's.
// Keyed by shape and parameter count. A body that calls one of its group's
// rules (recursion) is left out: the joined rule's body is rebuilt from the
// first twin's, calls and all, and calls are given their new arguments by
// node, so a call rebuilt inside it would keep the old, too few.
struct RuleTwin {
  NodeId body;
  RuleId rule;
};

// rules, calls: for twin rules (Plan::rules), the rule of each member and
// how many calls of them the grammar writes.
std::optional<Plan> plan_for(const Grammar& g, const Survey& s, std::vector<NodeId> members, std::size_t max_params,
                             std::vector<RuleId> rules = {}, std::size_t calls = 0) {
  std::vector<std::vector<Slot>> slots(members.size());
  for (std::size_t m = 0; m < members.size(); ++m) collect_slots(g, members[m], slots[m]);
  Plan plan;
  plan.param_of.assign(slots.front().size(), std::nullopt);
  std::vector<std::vector<Slot>> columns;  // one per parameter: each member's value
  std::size_t varying_numbers = 0;
  for (std::size_t j = 0; j < slots.front().size(); ++j) {
    std::vector<Slot> column;
    for (const auto& member : slots) column.push_back(member[j]);
    if (std::ranges::all_of(column, [&](const Slot& v) { return v == column.front(); })) continue;
    varying_numbers += column.front().value.kind == ExprKind::Number ? 1 : 0;
    const auto same = std::ranges::find(columns, column);
    plan.param_of[j] = static_cast<std::uint32_t>(same - columns.begin());
    if (same == columns.end()) columns.push_back(std::move(column));
  }
  const std::size_t p = columns.size();
  if (p == 0 || p > max_params) return std::nullopt;
  // Written before: every copy in full. After: the rule once (its label,
  // its parameters, its body less the numbers that became parameters) and
  // at each place a call with its arguments.
  const NodeId first = members.front();
  const std::size_t each = s.ops[first] + s.numbers[first];
  std::size_t places = 0;
  for (NodeId m : members) places += s.writes[m];
  const long before = static_cast<long>(places * each);
  const long after = static_cast<long>(1 + p + each - varying_numbers + places * (1 + p));
  plan.saving = before - after;
  if (!rules.empty()) {
    // The rules are there already, and so are their calls: one rule and
    // body instead of several, and p more arguments at every call.
    plan.saving = static_cast<long>(members.size() * (1 + each)) -
                  static_cast<long>(1 + p + each - varying_numbers + p * calls);
    plan.rules = std::move(rules);
  }
  if (plan.saving <= 0) return std::nullopt;
  for (std::size_t m = 0; m < members.size(); ++m) {
    std::vector<Slot> values;
    for (const auto& column : columns) values.push_back(column[m]);
    plan.args.push_back(std::move(values));
  }
  plan.members = std::move(members);
  return plan;
}

// The twin below id written with parameters where its slots vary; `next`
// counts the slots in collect_slots' order.
// first: the parameter the plan's first one is (after a twin rule's own).
NodeId with_parameters(Grammar& g, NodeId id, const Plan& plan, std::size_t& next, std::uint32_t first = 0) {
  Operation op = g.op(id);  // a copy: building the children grows the arena
  for (Expr* e : expression_slots(op))
    for (std::size_t i = 0; i < e->nodes().size(); ++i)
      if (is_slot(e->node(i)))
        if (const auto param = plan.param_of[next++])
          e->set_leaf(i, {.kind = ExprKind::Param, .index = first + *param});
  for (NodeId* c : child_slots(op)) *c = with_parameters(g, *c, plan, next, first);
  return g.intern({std::move(op), g.node(id).loc});
}

Expr argument(const Slot& v) {
  return v.value.kind == ExprKind::Axis ? Expr::axis(static_cast<Axis>(v.value.op)) : Expr::number(v.value.number);
}

// Parameter names: a1, a2 ... for axes, v1, v2 ... for numbers, after the
// names a twin rule has already (which they skip).
std::vector<std::string> parameter_names(const std::vector<Slot>& kinds, std::vector<std::string> taken = {}) {
  std::size_t axes = 0, numbers = 0;
  for (const Slot& k : kinds) {
    std::string name;
    do {
      name = k.value.kind == ExprKind::Axis ? "a" + std::to_string(++axes) : "v" + std::to_string(++numbers);
    } while (std::ranges::find(taken, name) != taken.end());
    taken.push_back(std::move(name));
  }
  return taken;
}

// The nodes written below id (itself included), as collect_slots walks them.
template <class F>
void for_each_written(const Grammar& g, NodeId id, F f) {
  f(id);
  for_each_child(g.op(id), [&](NodeId c) { for_each_written(g, c, f); });
}

// The groups of twin rules (RuleTwin), two or more each, members in id order.
std::map<std::pair<NodeId, std::size_t>, std::vector<RuleTwin>> rule_twins(const Grammar& g, const Survey& s) {
  std::map<NodeId, std::vector<RuleId>> rules_of;  // a body -> the rules with parameters it is the body of
  for (RuleId r = 0; r < g.rules.size(); ++r)
    if (r != g.start_rule && !g.rules[r].params.empty()) rules_of[g.rules[r].body].push_back(r);
  std::map<std::pair<NodeId, std::size_t>, std::vector<RuleTwin>> groups;
  for (const auto& [body, rules] : rules_of)
    if (rules.size() == 1 && s.reads[body] && s.writes[body] == 1 && s.ops[body] >= 2)
      groups[{s.shape[body], g.rules[rules[0]].params.size()}].push_back({body, rules[0]});
  for (auto it = groups.begin(); it != groups.end();) {
    std::vector<RuleTwin>& twins = it->second;
    std::vector<RuleId> rules;
    for (const RuleTwin& t : twins) rules.push_back(t.rule);
    std::erase_if(twins, [&](const RuleTwin& t) {
      bool recursive = false;
      for_each_written(g, t.body, [&](NodeId n) {
        if (const auto* c = std::get_if<Call>(&g.op(n)))
          recursive = recursive || std::ranges::find(rules, c->rule) != rules.end();
      });
      return recursive;
    });
    it = twins.size() < 2 ? groups.erase(it) : std::next(it);
  }
  return groups;
}

// The plans, largest saving first, whose twins neither hold nor lie inside
// a twin of a plan taken before: each rewrites a part of the grammar no
// other touches, so all of them are joined in one rewrite. (Twins sharing
// a node below, an I(rect), touch nothing of each other.)
std::vector<Plan> apart_from_each_other(const Grammar& g, std::vector<Plan> plans) {
  std::stable_sort(plans.begin(), plans.end(), [](const Plan& a, const Plan& b) { return a.saving > b.saving; });
  std::vector<bool> below(g.node_count(), false);  // in or below a taken twin
  std::vector<bool> taken(g.node_count(), false);  // a taken twin
  // A twin rule's callers pass more arguments after joining, so no twin
  // taken in the same round may call it: its copy of the call would be
  // rebuilt with the old arguments.
  std::vector<bool> retyped(g.rules.size(), false);  // rules of a taken twin-rule plan
  std::vector<bool> called(g.rules.size(), false);   // rules called in or below a taken twin
  std::vector<Plan> out;
  for (Plan& plan : plans) {
    bool clear = true;
    std::vector<RuleId> calls;
    for (NodeId m : plan.members) {
      clear = clear && !below[m];
      for_each_written(g, m, [&](NodeId n) {
        clear = clear && !taken[n];
        if (const auto* c = std::get_if<Call>(&g.op(n))) calls.push_back(c->rule);
      });
    }
    for (const RuleId r : calls) clear = clear && !retyped[r];
    for (const RuleId r : plan.rules) clear = clear && !called[r];
    if (!clear) continue;
    for (NodeId m : plan.members) {
      taken[m] = true;
      for_each_written(g, m, [&](NodeId n) { below[n] = true; });
    }
    for (const RuleId r : calls) called[r] = true;
    for (const RuleId r : plan.rules) retyped[r] = true;
    out.push_back(std::move(plan));
  }
  return out;
}

void join(Grammar& g, const std::vector<Plan>& plans) {
  // A rule whose body is a twin: the first such takes the parameters.
  std::map<NodeId, std::vector<RuleId>> body_of;
  for (RuleId r = 0; r < g.rules.size(); ++r)
    if (g.rules[r].params.empty() && r != g.start_rule) body_of[g.rules[r].body].push_back(r);
  std::map<RuleId, NodeId> new_body;  // a rule taking parameters -> its body with them
  std::map<NodeId, NodeId> call_of;   // a twin -> the call that stands for it
  std::map<RuleId, NodeId> call_for;  // a rule whose body was a twin -> the call it now is
  std::map<RuleId, std::pair<RuleId, const std::vector<Slot>*>> retarget;  // a twin rule -> the joined one, its values
  for (const Plan& plan : plans) {
    if (!plan.rules.empty()) {
      // The first twin rule takes the values after its own parameters.
      const RuleId rule = *std::ranges::min_element(plan.rules);
      const auto own = static_cast<std::uint32_t>(g.rules[rule].params.size());
      std::size_t next = 0;
      new_body[rule] = with_parameters(g, plan.members.front(), plan, next, own);
      g.rules[rule].params = parameter_names(plan.args.front(), g.rules[rule].params);
      for (std::size_t m = 0; m < plan.rules.size(); ++m) retarget[plan.rules[m]] = {rule, &plan.args[m]};
      continue;
    }
    const NodeId first = plan.members.front();
    std::optional<RuleId> reused;
    for (NodeId m : plan.members)
      if (const auto it = body_of.find(m); it != body_of.end())
        reused = std::min(reused.value_or(it->second.front()), it->second.front());
    std::size_t next = 0;
    const NodeId body = with_parameters(g, first, plan, next);
    const RuleId rule = reused.value_or(static_cast<RuleId>(g.rules.size()));
    if (!reused) {
      g.rules.push_back(Rule{free_label(g, node_name(g, body)), {}, body, g.node(first).loc});
    } else if (const std::string named = node_name(g, body); named != node_name(g, first)) {
      // Its name said which axis; the axis is a parameter now.
      g.rules[rule].label.clear();
      g.rules[rule].label = free_label(g, named);
    }
    g.rules[rule].params = parameter_names(plan.args.front());
    new_body[rule] = body;
    for (std::size_t m = 0; m < plan.members.size(); ++m) {
      std::vector<Expr> args;
      for (const Slot& v : plan.args[m]) args.push_back(argument(v));
      const NodeId member = plan.members[m];
      const NodeId call = g.intern({Call{rule, std::move(args)}, g.node(member).loc});
      call_of[member] = call;
      if (const auto it = body_of.find(member); it != body_of.end())
        for (RuleId r : it->second) call_for[r] = call;
    }
  }
  std::vector<NodeId> replace(g.node_count(), kNoReplacement);
  for (const auto& [member, call] : call_of) replace[member] = call;
  for (NodeId id = 0; id < replace.size(); ++id) {
    const auto* c = std::get_if<Call>(&g.op(id));
    if (!c) continue;
    if (const auto it = call_for.find(c->rule); it != call_for.end() && c->args.empty()) replace[id] = it->second;
    if (const auto it = retarget.find(c->rule); it != retarget.end()) {
      Call joined{it->second.first, c->args};  // copies: interning below may move the arena
      for (const Slot& v : *it->second.second) joined.args.push_back(argument(v));
      replace[id] = g.intern({std::move(joined), g.node(id).loc});
    }
  }
  for (RuleId r = 0; r < g.rules.size(); ++r) {
    const auto own = new_body.find(r);
    g.rules[r].body = substitute(g, own != new_body.end() ? own->second : g.rules[r].body, replace);
  }
  drop_unused_rules(g);
}

}  // namespace

TwinRules parameterise_twins(Grammar& g, const TwinOptions& options) {
  TwinRules out;
  for (std::size_t round = 0; round < kMaxRounds; ++round) {
    const Survey s = survey(g);
    std::map<NodeId, std::vector<NodeId>> groups;  // by shape, members in id order
    for (NodeId id = 0; id < g.node_count(); ++id)
      if (s.shape[id] != kNone && !s.reads[id] && s.ops[id] >= 2) groups[s.shape[id]].push_back(id);
    std::vector<Plan> plans;
    for (auto& [shape, members] : groups) {
      if (members.size() < 2) continue;
      if (auto plan = plan_for(g, s, std::move(members), options.max_params)) plans.push_back(std::move(*plan));
    }
    const auto twin_groups = rule_twins(g, s);
    std::vector<std::size_t> calls_of(twin_groups.empty() ? 0 : g.rules.size(), 0);  // calls written, by rule
    if (!twin_groups.empty())
      for (NodeId id = 0; id < g.node_count(); ++id)
        if (const auto* c = std::get_if<Call>(&g.op(id))) calls_of[c->rule] += s.writes[id];
    for (const auto& [key, twins] : twin_groups) {
      std::vector<NodeId> members;
      std::vector<RuleId> rules;
      std::size_t calls = 0;
      for (const RuleTwin& t : twins) {
        members.push_back(t.body);
        rules.push_back(t.rule);
        calls += calls_of[t.rule];
      }
      if (auto plan = plan_for(g, s, std::move(members), options.max_params, std::move(rules), calls))
        plans.push_back(std::move(*plan));
    }
    plans = apart_from_each_other(g, std::move(plans));
    if (plans.empty()) break;
    join(g, plans);
    for (const Plan& plan : plans) {
      ++out.rules;
      out.copies += plan.members.size();
    }
  }
  return out;
}

}  // namespace vern
