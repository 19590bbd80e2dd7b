#include "inverse/sizes/overflow_splits.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <unordered_map>

#include "graph/nodes_below.hpp"
#include "graph/structural.hpp"
#include "inverse/check/derives_examples.hpp"
#include "inverse/merge/equal_options.hpp"
#include "inverse/merge/substitute.hpp"
#include "inverse/write/unused_rules.hpp"

namespace vern {

namespace {

// Sizes in proportion to each other, to a part in a million.
bool proportional(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size() || a.empty()) return false;
  double ta = 0, tb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ta += a[i];
    tb += b[i];
  }
  if (!(ta > 0) || !(tb > 0)) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::abs(a[i] / ta - b[i] / tb) > 1e-6) return false;
  return true;
}

// One child: one node as inference interns them, or alike as a grammar
// read from text has them.
bool same_child(const Grammar& g, NodeId a, NodeId b) { return a == b || structurally_equal(g, a, g, b); }

// Is s (relative literal sizes) t (absolute and relative literal parts)
// seen overflowing, or t's member kept apart?
bool taken_for(const Grammar& g, const Split& s, const Split& t) {
  if (!(s.axis == t.axis)) return false;
  std::vector<double> s_sizes;
  for (const SplitPart& p : s.parts) {
    const auto v = p.size.value.literal();
    if (!p.size.relative || !v) return false;
    s_sizes.push_back(*v);
  }
  std::vector<double> absolute;
  std::vector<NodeId> absolute_children;
  bool relative = false;
  for (const SplitPart& p : t.parts) {
    if (p.size.relative) {
      relative = true;
      continue;
    }
    const auto v = p.size.value.literal();
    if (!v) return false;
    absolute.push_back(*v);
    absolute_children.push_back(p.child);
  }
  if (!relative || absolute.empty()) return false;
  if (s.parts.size() == absolute.size()) {
    for (std::size_t i = 0; i < absolute.size(); ++i)
      if (!same_child(g, s.parts[i].child, absolute_children[i])) return false;
    return proportional(s_sizes, absolute);
  }
  if (s.parts.size() != t.parts.size()) return false;
  std::vector<double> at_absolute;
  for (std::size_t i = 0; i < t.parts.size(); ++i) {
    if (!same_child(g, s.parts[i].child, t.parts[i].child)) return false;
    if (!t.parts[i].size.relative) at_absolute.push_back(s_sizes[i]);
  }
  return proportional(at_absolute, absolute);
}

// A split's axis and the structure of some of its children, in order:
// equal for structurally equal children (structural_hashes), so that a
// split is compared only with the splits it could be taken for.
std::size_t children_key(const Split& s, const std::vector<std::size_t>& hashes, bool absolute_only) {
  const ExprNode& axis = s.axis.node(s.axis.root());
  std::size_t key = axis.kind == ExprKind::Axis ? axis.op : 3;  // 3: an axis a parameter gives
  for (const SplitPart& p : s.parts)
    if (!absolute_only || !p.size.relative) key = key * 1000003 ^ hashes[p.child];
  return key;
}

}  // namespace

std::size_t unify_overflows(Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options) {
  std::vector<NodeId> splits;  // in id order: one order every time
  for (const NodeId id : nodes_of_rules(g))
    if (std::holds_alternative<Split>(g.op(id))) splits.push_back(id);
  // s is taken for t only where s's children are t's absolute ones, or all
  // of t's: each t is filed under both keys, and each s looks up its own,
  // instead of trying every pair (1,000 examples of other structures made
  // this pass a fifth of infer's time).
  const std::vector<std::size_t> hashes = structural_hashes(g);
  std::unordered_map<std::size_t, std::vector<std::size_t>> by_children;  // key -> indices into splits
  for (std::size_t k = 0; k < splits.size(); ++k) {
    const Split& t = std::get<Split>(g.op(splits[k]));
    const std::size_t absolute = children_key(t, hashes, true), all = children_key(t, hashes, false);
    by_children[absolute].push_back(k);
    if (all != absolute) by_children[all].push_back(k);
  }
  std::vector<NodeId> replace(g.node_count(), kNoReplacement);
  std::size_t count = 0;
  std::vector<std::size_t> candidates;
  for (const NodeId s : splits) {
    const auto found = by_children.find(children_key(std::get<Split>(g.op(s)), hashes, false));
    if (found == by_children.end()) continue;
    // The first in id order, as trying every split in order would find.
    candidates = found->second;
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    for (const std::size_t k : candidates) {
      const NodeId t = splits[k];
      if (s == t || !taken_for(g, std::get<Split>(g.op(s)), std::get<Split>(g.op(t)))) continue;
      replace[s] = t;
      ++count;
      break;
    }
  }
  if (count == 0) return 0;
  const Grammar before = g;
  for (Rule& rule : g.rules) rule.body = substitute_until_settled(g, rule.body, replace);
  // Alternatives now alike are one.
  std::vector<NodeId> joined(g.node_count(), kNoReplacement);
  bool any = false;
  for (NodeId id = 0; id < g.node_count(); ++id) {
    const auto* c = std::get_if<Choose>(&g.op(id));
    if (!c) continue;
    Choose copy = *c;
    if (!join_equal_options(copy)) continue;
    joined[id] = copy.options.size() == 1 ? copy.options[0].child : g.intern({std::move(copy), g.node(id).loc});
    if (joined.size() < g.node_count()) joined.resize(g.node_count(), kNoReplacement);
    any = true;
  }
  if (any)
    for (Rule& rule : g.rules) rule.body = substitute_until_settled(g, rule.body, joined);
  drop_unused_rules(g);
  std::vector<CheckResult> results;
  if (!derives_examples(g, examples, options, results)) {
    g = before;
    return 0;
  }
  return count;
}

}  // namespace vern
