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

// The split as a split of fixed sizes holding a split of fixed sizes
// (nested_split.hpp), when its rows are two splits and not one.
std::optional<Split> nested_split(Grammar& g, const Split& split, const std::vector<std::vector<double>>& lengths,
                                  const std::optional<std::vector<PartPlan>>& whole, double tolerance) {
  const auto run = find_nested_run(lengths, whole, tolerance);
  if (!run) return std::nullopt;
  auto size = [](const PartPlan& p) { return Size{Expr::number(p.value), !p.absolute}; };
  Split nested{split.axis, {}};
  for (std::size_t i = run->first; i <= run->last; ++i)
    nested.parts.push_back({size(run->inner[i - run->first]), split.parts[i].child});
  const NodeId child = g.intern({std::move(nested), {}});
  Split out{split.axis, {}};
  for (std::size_t i = 0, k = 0; i < split.parts.size(); ++k) {
    if (i == run->first) {
      out.parts.push_back({size(run->outer[k]), child});
      i = run->last + 1;
    } else {
      out.parts.push_back({size(run->outer[k]), split.parts[i].child});
      ++i;
    }
  }
  return out;
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
    if (const auto nested = nested_split(g, *split, lengths, whole, tolerance)) {
      const NodeId out = g.intern({std::move(*nested), g.node(id).loc});
      if (replace.size() < g.node_count()) replace.resize(g.node_count(), kNoReplacement);
      replace[id] = out;
      any = true;
      continue;
    }
    const auto plan = plan_drawn_sizes(lengths, whole, tolerance);
    if (!plan) continue;
    Split drawn = *split;
    std::vector<std::vector<Observation>> values(drawn.parts.size());
    for (std::size_t i = 0; i < drawn.parts.size(); ++i) {
      const PartSizes& p = (*plan)[i];
      if (p.fixed) {
        drawn.parts[i].size = {Expr::number(p.value), !p.absolute};
        continue;
      }
      const auto [lo, hi] = std::minmax_element(p.values.begin(), p.values.end());
      drawn.parts[i].size = {range_expr({*lo, *hi}, tolerance), !p.absolute};
      for (std::size_t m = 0; m < p.values.size(); ++m) values[i].push_back({p.values[m], known->second[m].weight, known->second[m].example});
    }
    const NodeId out = g.intern({std::move(drawn), g.node(id).loc});
    if (out == id) continue;
    book[out] = std::move(values);
    if (replace.size() < g.node_count()) replace.resize(g.node_count(), kNoReplacement);
    replace[id] = out;
    any = true;
  }
  if (!any) return root;
  // Splits above a rewritten node are rebuilt: their values go with them.
  return substitute_keeping_samples(g, root, replace, book, rebuilt);
}

}  // namespace vern
