#include "inverse/merge/subsumed_options.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>
#include <unordered_map>
#include <utility>

#include "graph/nodes_below.hpp"
#include "inverse/merge/equal_options.hpp"
#include "inverse/merge/substitute.hpp"
#include "inverse/write/unused_rules.hpp"

namespace vern {

namespace {

// By choice: for each of its options, the examples whose witness takes
// it, ascending. One pass over the witnesses, not one per option: a
// facade dataset's choice has hundreds.
using Takers = std::unordered_map<NodeId, std::vector<std::vector<std::size_t>>>;

Takers examples_taking(const Grammar& g, const std::vector<CheckResult>& results) {
  Takers out;
  for (std::size_t e = 0; e < results.size(); ++e)
    for (const CheckStep& step : results[e].steps) {
      if (step.kind != CheckStep::Kind::Alternative) continue;
      const auto* c = std::get_if<Choose>(&g.op(step.node));
      if (!c || step.index >= c->options.size()) continue;
      auto& options = out.try_emplace(step.node, c->options.size()).first->second;
      if (options[step.index].empty() || options[step.index].back() != e) options[step.index].push_back(e);
    }
  return out;
}

// g with choice `choose` replaced by `now` in every rule; moved, where
// given, gets each node rebuilt above it (old id -> new id).
void replace_choice(Grammar& g, NodeId choose, NodeId now, std::unordered_map<NodeId, NodeId>* moved) {
  std::vector<NodeId> replace(g.node_count(), kNoReplacement);
  replace[choose] = now;
  std::vector<std::pair<NodeId, NodeId>> rebuilt;
  for (Rule& rule : g.rules) rule.body = substitute_until_settled(g, rule.body, replace, &rebuilt);
  if (!moved) return;
  for (const auto& [old, fresh] : rebuilt) (*moved)[old] = fresh;
  // A node rebuilt in one pass and again in the next: its last id.
  for (auto& [old, fresh] : *moved)
    for (auto it = moved->find(fresh); it != moved->end() && it->second != fresh; it = moved->find(fresh))
      fresh = it->second;
}

// Every alternative no example's witness takes, dropped at once (the
// others keep their weights): each example derives by its witness as it
// did, so nothing needs checking. Returns how many were dropped; the
// witnesses are then no longer g's (their choices were rebuilt). Rules
// no longer called stay, for the caller to drop.
std::size_t drop_untaken(Grammar& g, const std::vector<CheckResult>& results) {
  std::vector<NodeId> replace(g.node_count(), kNoReplacement);
  std::size_t dropped = 0;
  const Takers takers = examples_taking(g, results);
  std::map<NodeId, const std::vector<std::vector<std::size_t>>*> in_order;  // one order every time
  for (const auto& [id, taking] : takers) in_order.emplace(id, &taking);
  for (const auto& [id, taking] : in_order) {
    if (!plain_choice(std::get<Choose>(g.op(id)))) continue;
    std::vector<bool> taken;
    for (const auto& examples_of_option : *taking) taken.push_back(!examples_of_option.empty());
    if (std::all_of(taken.begin(), taken.end(), [](bool t) { return t; })) continue;
    Choose kept = std::get<Choose>(g.op(id));  // a copy: interning below may grow the arena
    std::vector<ChooseOption> options_kept;
    for (std::size_t i = 0; i < kept.options.size(); ++i)
      if (taken[i]) options_kept.push_back(kept.options[i]);
    dropped += kept.options.size() - options_kept.size();
    kept.options = std::move(options_kept);
    const NodeId now = kept.options.size() == 1 ? kept.options[0].child : g.intern({std::move(kept), g.node(id).loc});
    if (replace.size() < g.node_count()) replace.resize(g.node_count(), kNoReplacement);
    replace[id] = now;
  }
  if (dropped == 0) return 0;
  for (Rule& rule : g.rules) rule.body = substitute_until_settled(g, rule.body, replace);
  return dropped;
}

// What is left to try: examples to check, and alternatives tried, by
// their node and their choice's size (node ids of options stay as they
// are when a choice above or beside them is rewritten).
struct Budget {
  std::size_t checks = 0;  // examples checked, at most
  std::set<std::pair<NodeId, std::size_t>> needed;
};

// The witnesses of examples a rewrite did not touch, in the rewritten
// grammar's node ids: nodes rebuilt above the rewritten choice are
// renamed (moved), and the choice itself is `now`, the option `removed`
// gone from it (gone: `now` is no choice, its one option left).
void rename_witnesses(std::vector<CheckResult>& results, const std::vector<std::size_t>& untouched,
                      const std::unordered_map<NodeId, NodeId>& moved, NodeId choose, std::size_t removed, NodeId now,
                      bool gone) {
  for (const std::size_t e : untouched) {
    std::vector<CheckStep> steps;
    for (CheckStep step : results[e].steps) {
      if (step.node == choose) {
        if (step.kind == CheckStep::Kind::Alternative) {
          if (gone) continue;
          if (step.index > removed) --step.index;
        }
        step.node = now;
      } else if (const auto it = moved.find(step.node); it != moved.end()) {
        step.node = it->second;
      }
      steps.push_back(step);
    }
    results[e].steps = std::move(steps);
    results[e].parts.clear();  // not kept up: no step reads them
  }
}

// One alternative that examples take dropped, the least used first, if
// those examples derive without it; its weight goes to the alternatives
// they take now. Only a minority alternative (taken by at most half the
// examples that reach its choice) is tried: its examples are few to
// check, and a main alternative another derives is rare. The witnesses
// stay the grammar's: those of the examples it took are found anew, the
// others' renamed.
bool drop_one(Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options,
              std::vector<CheckResult>& results, Budget& budget) {
  const Takers takers = examples_taking(g, results);
  for (const NodeId id : nodes_of_rules(g)) {  // in id order: one order every time
    const auto* found = std::get_if<Choose>(&g.op(id));
    if (!found || !plain_choice(*found)) continue;
    const Choose c = *found;  // a copy: interning below may grow the arena
    std::vector<std::size_t> order(c.options.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return *c.options[a].priority.literal() < *c.options[b].priority.literal();
    });
    const auto found_takers = takers.find(id);
    if (found_takers == takers.end()) continue;
    const std::vector<std::vector<std::size_t>>& taking = found_takers->second;
    std::size_t reaching = 0;
    for (const auto& examples_of_option : taking) reaching += examples_of_option.size();
    for (const std::size_t option : order) {
      if (taking[option].empty() || 2 * taking[option].size() > reaching) continue;
      if (budget.checks < taking[option].size()) return false;
      if (!budget.needed.insert({c.options[option].child, c.options.size()}).second) continue;
      budget.checks -= taking[option].size();
      Choose without = c;
      without.options.erase(without.options.begin() + static_cast<std::ptrdiff_t>(option));
      Grammar candidate = g;
      replace_choice(candidate, id, candidate.intern({without, g.node(id).loc}), nullptr);
      std::vector<Example> asked;
      for (const std::size_t e : taking[option]) asked.push_back(examples[e]);
      std::vector<CheckResult> answers;
      if (!derives_examples(candidate, asked, options, answers)) continue;
      // The dropped alternative's weight, to those its examples take now.
      const NodeId trial = candidate.intern({without, g.node(id).loc});
      std::vector<double> taken(without.options.size(), 0);
      for (const CheckResult& r : answers)
        for (const CheckStep& step : r.steps)
          if (step.kind == CheckStep::Kind::Alternative && step.node == trial) {
            taken[step.index] += 1;
            break;
          }
      const double weight = *c.options[option].priority.literal();
      const double total = std::accumulate(taken.begin(), taken.end(), 0.0);
      for (std::size_t i = 0; i < without.options.size() && total > 0; ++i)
        without.options[i].priority = Expr::number(*without.options[i].priority.literal() + weight * taken[i] / total);
      candidate = g;
      const bool gone = without.options.size() == 1;
      const NodeId now = gone ? without.options[0].child : candidate.intern({std::move(without), g.node(id).loc});
      std::unordered_map<NodeId, NodeId> moved;
      // (Rules no longer called are dropped at the end: dropping them
      // makes every node anew, which the renamed witnesses cannot follow.)
      replace_choice(candidate, id, now, &moved);
      // Its examples' witnesses in the grammar as it now is.
      if (budget.checks < asked.size()) return false;
      budget.checks -= asked.size();
      if (!derives_examples(candidate, asked, options, answers)) continue;
      std::vector<std::size_t> untouched;
      for (std::size_t e = 0; e < examples.size(); ++e)
        if (!std::binary_search(taking[option].begin(), taking[option].end(), e)) untouched.push_back(e);
      rename_witnesses(results, untouched, moved, id, option, now, gone);
      for (std::size_t k = 0; k < asked.size(); ++k) results[taking[option][k]] = std::move(answers[k]);
      g = std::move(candidate);
      return true;
    }
  }
  return false;
}

}  // namespace

std::size_t drop_subsumed_options(Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options,
                                  Witnesses& witnesses) {
  const std::vector<NodeId> nodes = nodes_of_rules(g);
  if (std::none_of(nodes.begin(), nodes.end(), [&](NodeId n) {
        const auto* c = std::get_if<Choose>(&g.op(n));
        return c && plain_choice(*c);
      }))
    return 0;
  if (!witnesses_of(g, examples, options, witnesses)) return 0;
  // Alternatives the examples take, the least used first, each tried once
  // while its choice keeps its size, within a budget of examples checked
  // (about a quarter of a check of them all), so that hundreds of
  // one-example alternatives (a facade dataset) cost a bounded number of
  // checks.
  Budget budget{examples.size() / 4 + 4, {}};
  std::size_t dropped = 0;
  while (drop_one(g, examples, options, witnesses.results, budget)) ++dropped;
  // Then those no witness takes, all at once: the examples derive as they
  // did, by their witnesses (found, or renamed above as the choices they
  // pass through were rebuilt; infer checks what it writes in the end).
  const std::size_t untaken = drop_untaken(g, witnesses.results);
  if (dropped + untaken > 0) {
    drop_unused_rules(g);
    witnesses.known = false;  // their nodes were made anew
  }
  return dropped + untaken;
}

}  // namespace vern
