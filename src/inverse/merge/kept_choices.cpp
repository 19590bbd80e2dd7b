#include "inverse/merge/kept_choices.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>

#include "inverse/merge/equal_options.hpp"
#include "inverse/merge/substitute.hpp"
#include "inverse/write/unused_rules.hpp"

namespace vern {

namespace {

// Drawn freely, as many examples as this would show two kinds together
// for their never doing so to say they are kept: e^-3, one chance in 20.
constexpr double kExpectedTogether = 3;

// Rounds of pinning calls to one kind (pin_kinds), each one call more.
constexpr std::size_t kMaxPinRounds = 4;

// Rules of a frame passed through on the way to a choice (FlatOption).
constexpr std::size_t kMaxThrough = 2;

// Alternatives of one choice among which kinds are searched (every set of
// them is tried): a choice of more is not read for kinds.
constexpr std::size_t kMaxKindsSearched = 12;

// What the witnesses say of one choice: per example, how often it was
// drawn and which alternatives it took.
struct Taken {
  std::vector<std::size_t> draws;                  // per example
  std::vector<std::vector<std::size_t>> options;   // per example: times each alternative was taken
};

// An alternative as kinds are read: one of the choice's own, or, where
// that alternative holds one call of a rule whose body is a choice of its
// own (bays each a frame around an infill or a window, the frame one
// alternative beside a pair of windows, perhaps a rule of its own), one
// of that rule's alternatives in its frame. Kinds kept per building may lie on both
// levels: houses of pairs and windows, houses of infills and windows.
struct FlatOption {
  std::size_t outer = 0;               // the choice's alternative
  std::optional<RuleId> inner;         // the rule it calls, if read through it
  std::size_t index = 0;               // that rule's alternative
  NodeId call = 0;                     // the call of that rule
  // The calls on the way to it, outermost first: rules of no parameters
  // (a frame written as a rule of its own), each in the body of the one
  // before (the first in the outer alternative).
  std::vector<NodeId> through;
};

// Per example, the draws of the choice and how often each flat option
// was taken. A rule read through may be called elsewhere too: its draw
// counts for an alternative only as the first draw of that rule after the
// choice took the alternative (witness steps follow the derivation, depth
// first), one per draw of the choice.
Taken taken_by(const std::vector<CheckResult>& results, const Grammar& g, NodeId choose,
               const std::vector<FlatOption>& flat, bool by_row = false) {
  const std::size_t outer = std::get<Choose>(g.op(choose)).options.size();
  Taken t;
  for (const CheckResult& r : results) {
    t.draws.push_back(0);
    t.options.emplace_back(flat.size(), 0);
    constexpr std::size_t kNone = static_cast<std::size_t>(-1);
    std::size_t pending = kNone;  // the alternative just taken, if read through a rule
    for (const CheckStep& step : r.steps) {
      // By row: each repeat's tiles (a row of bays) counted apart.
      if (by_row && step.kind == CheckStep::Kind::Tiles) {
        t.draws.push_back(0);
        t.options.emplace_back(flat.size(), 0);
        pending = kNone;
        continue;
      }
      if (step.kind != CheckStep::Kind::Alternative) continue;
      if (step.node == choose && step.index < outer) {
        ++t.draws.back();
        pending = kNone;
        for (std::size_t f = 0; f < flat.size(); ++f) {
          if (flat[f].outer != step.index) continue;
          if (flat[f].inner) pending = step.index;
          else ++t.options.back()[f];
        }
        continue;
      }
      if (pending == kNone) continue;
      for (std::size_t f = 0; f < flat.size(); ++f)
        if (flat[f].outer == pending && flat[f].inner && g.rules[*flat[f].inner].body == step.node &&
            flat[f].index == step.index) {
          ++t.options.back()[f];
          pending = kNone;
          break;
        }
    }
  }
  return t;
}

// The choice's alternatives as kinds are read (FlatOption): each as it
// is, or, where it holds one call of a rule of a plain choice, reached
// through splits, transforms and rules of no parameters only (not a
// repeat: one draw of the alternative, one of the rule), each of that
// rule's alternatives.
// Empty where no alternative reads through.
std::vector<FlatOption> flat_options(const Grammar& g, const Choose& c) {
  std::vector<FlatOption> flat;
  bool through = false;
  for (std::size_t i = 0; i < c.options.size(); ++i) {
    std::optional<NodeId> site;
    std::vector<NodeId> site_through, path;
    std::size_t sites = 0;
    std::function<void(NodeId)> visit = [&](NodeId n) {
      const Operation& op = g.op(n);
      if (const auto* call = std::get_if<Call>(&op)) {
        const Rule& rule = g.rules[call->rule];
        if (!rule.params.empty() || !call->args.empty()) return;
        const auto* inner = std::get_if<Choose>(&g.op(rule.body));
        if (inner && plain_choice(*inner)) {
          site = n;
          site_through = path;
          ++sites;
        } else if (!inner && path.size() < kMaxThrough) {
          path.push_back(n);
          visit(rule.body);
          path.pop_back();
        }
        return;
      }
      if (std::holds_alternative<Repeat>(op) || std::holds_alternative<Choose>(op)) return;
      for_each_child(op, [&](NodeId child) { visit(child); });
    };
    visit(c.options[i].child);
    if (sites != 1) {
      flat.push_back({i, std::nullopt, 0, 0, {}});
      continue;
    }
    const RuleId rule = std::get<Call>(g.op(*site)).rule;
    const std::size_t count = std::get<Choose>(g.op(g.rules[rule].body)).options.size();
    for (std::size_t j = 0; j < count; ++j) flat.push_back({i, rule, j, *site, site_through});
    through = true;
  }
  if (!through) return {};
  return flat;
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
  // The largest set of kinds pairwise exclusive (then the most draws),
  // every set tried: taken greedily by share, the commonest alternative,
  // which houses of either kind take, would shut both kinds out.
  std::vector<std::size_t> kinds;
  if (options > kMaxKindsSearched) return {};
  std::vector<std::uint32_t> apart(options, 0);  // per alternative: those it never shares an example with
  std::uint32_t eligible = 0;
  for (std::size_t i = 0; i < options; ++i) {
    if (examples_with(i) >= 2) eligible |= 1u << i;
    for (std::size_t j = i + 1; j < options; ++j)
      if (exclusive(i, j)) {
        apart[i] |= 1u << j;
        apart[j] |= 1u << i;
      }
  }
  std::uint32_t best = 0;
  double best_share = 0;
  for (std::uint32_t set = 1; set < (1u << options); ++set) {
    if ((set & ~eligible) != 0 || std::popcount(set) < std::max(2, std::popcount(best))) continue;
    bool pairwise = true;
    double total = 0;
    for (std::size_t i = 0; i < options && pairwise; ++i)
      if (set & (1u << i)) {
        pairwise = (set & ~apart[i] & ~(1u << i)) == 0;
        total += share[i];
      }
    if (pairwise && (std::popcount(set) > std::popcount(best) || total > best_share)) {
      best = set;
      best_share = total;
    }
  }
  for (std::size_t i = 0; i < options; ++i)
    if (best & (1u << i)) kinds.push_back(i);
  if (kinds.size() < 2) return {};
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
void keep(Grammar& g, RuleId rule, const std::vector<FlatOption>& flat, const std::vector<std::size_t>& kinds) {
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
  // Each flat option as an alternative: one read through a rule is its
  // outer alternative with the call replaced by the rule's alternative,
  // weighted by both draws.
  std::vector<ChooseOption> options;
  for (const FlatOption& f : flat) {
    const ChooseOption& outer = c.options[f.outer];
    if (!f.inner) {
      options.push_back(outer);
      continue;
    }
    const Choose& inner = std::get<Choose>(g.op(g.rules[*f.inner].body));
    double total = 0;
    for (const ChooseOption& o : inner.options) total += *o.priority.literal();
    const double weight = *outer.priority.literal() * *inner.options[f.index].priority.literal() / total;
    // The rule's alternative in place of its call, in the body holding
    // the call, and that body in place of the call of its rule, out to
    // the outer alternative.
    auto in_place = [&](NodeId body, NodeId call, NodeId by) {
      std::vector<NodeId> replace(call + 1, kNoReplacement);
      replace[call] = by;
      return substitute(g, body, replace);
    };
    std::vector<NodeId> bodies{outer.child};
    for (const NodeId on_way : f.through) bodies.push_back(g.rules[std::get<Call>(g.op(on_way)).rule].body);
    NodeId built = in_place(bodies.back(), f.call, inner.options[f.index].child);
    for (std::size_t k = f.through.size(); k-- > 0;) built = in_place(bodies[k], f.through[k], built);
    options.push_back({Expr{}, Expr::number(weight), built});
  }
  for (std::size_t k = 0; k < kinds.size(); ++k) {
    const Expr is_k = Expr::binary(BinaryOp::Eq, Expr::param(param), Expr::number(static_cast<double>(k)));
    for (std::size_t i = 0; i < options.size(); ++i) {
      const bool kind = std::find(kinds.begin(), kinds.end(), i) != kinds.end();
      if (kind && i != kinds[k]) continue;
      kept_choice.options.push_back({is_k, options[i].priority, options[i].child});
    }
  }
  g.rules[rule].body = g.intern({std::move(kept_choice), g.node(g.rules[rule].body).loc});
  if (moved)
    g.rules[start].body = g.intern(
        {Call{*moved, {Expr::call(Function::RandInt,
                                  {Expr::number(0), Expr::number(static_cast<double>(kinds.size() - 1))})}},
         g.node(g.rules[start].body).loc});
}

// A choice whose kinds are kept per building, as the witnesses show it.
struct Kept {
  RuleId rule = 0;
  std::vector<FlatOption> flat;   // its alternatives as kinds are read
  std::vector<std::size_t> kinds;  // into flat
  bool by_row = false;             // read row by row (taken_by), not per building
};

// Every choice showing kinds kept per building, in rule order: read as
// its alternatives first, then through the rules they call (FlatOption).
// Empty where no choice does, or some example does not derive.
std::vector<Kept> kept_choices(const Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options,
                               Witnesses& witnesses) {
  std::vector<RuleId> candidates;
  for (RuleId r = 0; r < g.rules.size(); ++r) {
    const auto* c = std::get_if<Choose>(&g.op(g.rules[r].body));
    if (c && plain_choice(*c) && r != g.start_rule) candidates.push_back(r);
  }
  if (candidates.empty() || !witnesses_of(g, examples, options, witnesses)) return {};
  std::vector<Kept> out;
  for (const RuleId r : candidates) {
    const NodeId body = g.rules[r].body;
    const Choose& c = std::get<Choose>(g.op(body));
    std::vector<FlatOption> own;
    for (std::size_t i = 0; i < c.options.size(); ++i) own.push_back({i, std::nullopt, 0, 0, {}});
    for (const std::vector<FlatOption>& flat : {own, flat_options(g, c)}) {
      if (flat.empty()) continue;
      std::vector<std::size_t> kinds = kept_kinds(taken_by(witnesses.results, g, body, flat), flat.size());
      if (!kinds.empty()) {
        out.push_back({r, flat, std::move(kinds)});
        continue;
      }
      // Kinds that no row mixes, though a building does: its ground floor
      // always of one kind, its storeys of the kind kept (pinned below).
      kinds = kept_kinds(taken_by(witnesses.results, g, body, flat, true), flat.size());
      if (!kinds.empty()) out.push_back({r, flat, std::move(kinds), true});
    }
  }
  return out;
}

// Calls that pass the kind on (their last argument the caller's own last
// parameter, `b`), by place: the rule whose body holds them, the node
// holding them (kNoParent: the call is the body) and which of its
// children they are (a ground floor's row cut around its door bay calls
// the row twice). A node written alike in two rules is two places, each
// of which may pass a kind of its own.
struct PassingCalls {
  RuleId rule = 0;
  NodeId parent = 0;
  std::vector<std::size_t> slots;
};
constexpr NodeId kNoParent = static_cast<NodeId>(-1);

std::vector<PassingCalls> passing_calls(const Grammar& g) {
  std::vector<PassingCalls> out;
  for (RuleId r = 0; r < g.rules.size(); ++r) {
    const Rule& rule = g.rules[r];
    if (rule.params.empty() || rule.params.back() != "b") continue;
    const Expr own = Expr::param(static_cast<std::uint32_t>(rule.params.size() - 1));
    auto passes = [&](NodeId n) {
      const auto* c = std::get_if<Call>(&g.op(n));
      return c != nullptr && !c->args.empty() && c->args.back() == own;
    };
    if (passes(rule.body)) out.push_back({r, kNoParent, {0}});
    std::set<NodeId> seen;
    std::vector<NodeId> stack{rule.body};
    while (!stack.empty()) {
      const NodeId n = stack.back();
      stack.pop_back();
      if (!seen.insert(n).second) continue;
      const std::vector<NodeId> children = node_children(g.op(n));
      PassingCalls here{r, n, {}};
      for (std::size_t i = 0; i < children.size(); ++i) {
        if (passes(children[i])) here.slots.push_back(i);
        stack.push_back(children[i]);
      }
      if (!here.slots.empty()) out.push_back(std::move(here));
    }
  }
  return out;
}

// g with the calls at one place made to pass `kind` instead.
void pin(Grammar& g, const PassingCalls& site, std::size_t kind) {
  auto pinned = [&](NodeId call) {
    Call c = std::get<Call>(g.op(call));
    c.args.back() = Expr::number(static_cast<double>(kind));
    return g.intern({std::move(c), g.node(call).loc});
  };
  if (site.parent == kNoParent) {
    g.rules[site.rule].body = pinned(g.rules[site.rule].body);
    return;
  }
  Operation op = g.op(site.parent);  // a copy: interning may move the arena
  const std::vector<NodeId*> slots = child_slots(op);
  for (const std::size_t i : site.slots) *slots[i] = pinned(*slots[i]);
  const NodeId parent = g.intern({std::move(op), g.node(site.parent).loc});
  std::vector<NodeId> replace(site.parent + 1, kNoReplacement);
  replace[site.parent] = parent;
  g.rules[site.rule].body = substitute(g, g.rules[site.rule].body, replace);
}

// Where a kind kept per building does not derive every example, calls
// that pass the kind on may pass one kind always instead (a ground floor
// of kind 0 under storeys of the kind kept): tried call by call, each
// pinned to each kind, the one where most examples derive kept, until
// all do.
// Whether all do; g as far as it got.
bool pin_kinds(Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options, std::size_t kinds,
               std::vector<CheckResult>& results) {
  auto derived = [](const std::vector<CheckResult>& r) {
    return static_cast<std::size_t>(std::ranges::count_if(r, [](const CheckResult& c) { return c.derivable; }));
  };
  std::size_t best = derived(results);
  for (std::size_t round = 0; round < kMaxPinRounds && best < examples.size(); ++round) {
    // Of every place and kind, the pin that derives the most examples: the
    // first that derives more may pin a ground floor to the wrong kind
    // (one example more by chance) and shut the right one out.
    std::optional<Grammar> chosen;
    std::vector<CheckResult> chosen_results;
    std::size_t chosen_derived = best;
    for (const PassingCalls& site : passing_calls(g)) {
      for (std::size_t kind = 0; kind < kinds && chosen_derived < examples.size(); ++kind) {
        Grammar pinned = g;
        pin(pinned, site, kind);
        std::vector<CheckResult> now;
        const bool all = derives_examples(pinned, examples, options, now);
        const std::size_t count = all ? examples.size() : derived(now);
        if (count > chosen_derived) {
          chosen = std::move(pinned);
          chosen_results = std::move(now);
          chosen_derived = count;
        }
      }
    }
    if (!chosen) break;
    g = std::move(*chosen);
    results = std::move(chosen_results);
    best = chosen_derived;
  }
  return best == examples.size();
}

}  // namespace

bool shows_kept_choices(const Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options,
                        Witnesses& witnesses) {
  return !kept_choices(g, examples, options, witnesses).empty();
}

std::size_t keep_choices(Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options,
                         Witnesses& witnesses) {
  for (const Kept& k : kept_choices(g, examples, options, witnesses)) {
    Grammar candidate = g;
    keep(candidate, k.rule, k.flat, k.kinds);
    // A rule read through is called no more (its alternatives stand in
    // the kept choice).
    if (k.flat.size() != std::get<Choose>(g.op(g.rules[k.rule].body)).options.size()) drop_unused_rules(candidate);
    std::vector<CheckResult> results;
    if (!derives_examples(candidate, examples, options, results) &&
        !(k.by_row && pin_kinds(candidate, examples, options, k.kinds.size(), results)))
      continue;
    g = std::move(candidate);
    witnesses.known = false;
    return 1;
  }
  return 0;
}

}  // namespace vern
