#include "inverse/overflow_splits.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "graph/nodes_below.hpp"
#include "graph/structural.hpp"
#include "inverse/derives_examples.hpp"
#include "inverse/equal_options.hpp"
#include "inverse/substitute.hpp"
#include "inverse/unused_rules.hpp"

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

}  // namespace

std::size_t unify_overflows(Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options) {
  std::vector<NodeId> splits;  // in id order: one order every time
  for (const NodeId id : nodes_of_rules(g))
    if (std::holds_alternative<Split>(g.op(id))) splits.push_back(id);
  std::vector<NodeId> replace(g.node_count(), kNoReplacement);
  std::size_t count = 0;
  for (const NodeId s : splits) {
    for (const NodeId t : splits) {
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
