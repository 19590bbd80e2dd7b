#include "inverse/drawn_sizes.hpp"

#include <algorithm>
#include <optional>
#include <unordered_set>

#include "inverse/merge.hpp"
#include "inverse/nested_split.hpp"
#include "inverse/size_plan.hpp"
#include "inverse/substitute.hpp"

namespace vern {

namespace {

// A split with its sizes from a plan, and the values each drawn part
// takes in each row (for fitting).
struct DrawnSplit {
  Split split;
  std::vector<std::vector<Observation>> values;
};

DrawnSplit drawn_split(Split split, const std::vector<PartSizes>& plan, const std::vector<LengthRow>& rows,
                       double tolerance) {
  std::vector<std::vector<Observation>> values(split.parts.size());
  for (std::size_t i = 0; i < split.parts.size(); ++i) {
    const PartSizes& p = plan[i];
    if (p.fixed) {
      split.parts[i].size = {Expr::number(p.value), !p.absolute};
      continue;
    }
    const auto [lo, hi] = std::minmax_element(p.values.begin(), p.values.end());
    split.parts[i].size = {range_expr({*lo, *hi}, tolerance), !p.absolute};
    for (std::size_t m = 0; m < p.values.size(); ++m) values[i].push_back({p.values[m], rows[m].weight, rows[m].example});
  }
  return {std::move(split), std::move(values)};
}

// The split as a split holding a split (nested_split.hpp), when its rows
// are two splits and not one: the inner split is interned (its drawn
// values booked), the outer returned.
std::optional<DrawnSplit> nested_split(Grammar& g, const Split& split, const std::vector<LengthRow>& rows,
                                       const std::vector<std::vector<double>>& lengths,
                                       const std::optional<std::vector<PartPlan>>& whole, SampleBook& book,
                                       double tolerance) {
  const auto run = find_nested_run(lengths, whole, tolerance);
  if (!run) return std::nullopt;
  Split inner{split.axis, {}};
  for (std::size_t i = run->first; i <= run->last; ++i) inner.parts.push_back(split.parts[i]);
  DrawnSplit drawn_inner = drawn_split(std::move(inner), run->inner, rows, tolerance);
  const NodeId child = g.intern({std::move(drawn_inner.split), {}});
  if (draws_of(run->inner) > 0) book[child] = std::move(drawn_inner.values);
  Split outer{split.axis, {}};
  for (std::size_t i = 0; i < split.parts.size(); ++i) {
    if (i == run->first) {
      outer.parts.push_back({{}, child});
      i = run->last;
    } else {
      outer.parts.push_back(split.parts[i]);
    }
  }
  return drawn_split(std::move(outer), run->outer, rows, tolerance);
}

}  // namespace

NodeId draw_sizes(Grammar& g, NodeId root, const RowBook& rows, SampleBook& book, double tolerance,
                  std::vector<std::pair<NodeId, NodeId>>* rebuilt) {
  std::vector<NodeId> replace;
  std::unordered_set<NodeId> seen;
  std::vector<NodeId> stack{root};
  bool any = false;
  while (!stack.empty()) {
    const NodeId id = stack.back();
    stack.pop_back();
    if (!seen.insert(id).second) continue;
    for_each_child(g.op(id), [&](NodeId c) { stack.push_back(c); });
    const auto* split = std::get_if<Split>(&g.op(id));
    const auto known = rows.find(id);
    if (!split || known == rows.end() || known->second.size() < 2) continue;
    std::vector<std::vector<double>> lengths;
    for (const LengthRow& r : known->second) lengths.push_back(r.lengths);
    if (lengths[0].size() != split->parts.size()) continue;
    // One plan of the row as one split, for both questions below.
    const auto whole = plan_sizes(lengths, tolerance);
    // A copy: interning the nested split's child may move g's nodes.
    const Split original = *split;
    std::optional<DrawnSplit> drawn = nested_split(g, original, known->second, lengths, whole, book, tolerance);
    if (!drawn) {
      const auto plan = plan_drawn_sizes(lengths, whole, tolerance);
      if (!plan) continue;
      drawn = drawn_split(original, *plan, known->second, tolerance);
    }
    const NodeId out = g.intern({std::move(drawn->split), g.node(id).loc});
    if (out == id) continue;
    book[out] = std::move(drawn->values);
    if (replace.size() < g.node_count()) replace.resize(g.node_count(), kNoReplacement);
    replace[id] = out;
    any = true;
  }
  if (!any) return root;
  // Splits above a rewritten node are rebuilt: their values go with them.
  return substitute_keeping_samples(g, root, replace, book, rebuilt);
}

}  // namespace vern
