#include "inverse/sizes/drawn_sizes.hpp"

#include <algorithm>
#include <optional>
#include <map>
#include <unordered_map>
#include <unordered_set>

#include "graph/nodes_below.hpp"
#include "inverse/merge/merge.hpp"
#include "inverse/merge/nested_split.hpp"
#include "inverse/merge/substitute.hpp"
#include "inverse/sizes/size_plan.hpp"

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
  auto run = find_nested_run(lengths, whole, tolerance);
  if (!run) run = find_fixed_run_leading_on(lengths, whole, tolerance);
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
  // The outer split may hold another run (a house's door bay and window
  // bay, each three parts, halves of the house): nested in turn while
  // that draws fewer sizes still.
  const std::vector<std::vector<double>> outer_rows = outer_lengths(lengths, *run);
  if (auto again = nested_split(g, outer, rows, outer_rows, plan_sizes(outer_rows, tolerance), book, tolerance))
    return again;
  return drawn_split(std::move(outer), run->outer, rows, tolerance);
}

// A member's plan from its siblings' (sibling_plans), and its rows.
struct SiblingPlan {
  std::vector<PartSizes> sizes;
  std::vector<LengthRow> rows;
};

// Alternatives of one choice that are splits of one axis and part count
// are one place seen in their examples together: a door bay after one,
// two or three bays, each an alternative seen in a few examples, whose
// split round it is the same. Planned apart, each alternative's few rows
// decide on their own which parts are metres (the ground floor in one,
// the roof in another), and joint_sizes can no longer size them as one
// slot. Planned together, where that draws no more sizes than the most
// any member draws alone (alternatives of different fixed proportions,
// a roof of two kinds, stay apart), each member takes the plan, with its
// own rows' values. By member node.
std::unordered_map<NodeId, SiblingPlan> sibling_plans(const Grammar& g, NodeId root, const RowBook& rows,
                                                    double tolerance) {
  std::unordered_map<NodeId, SiblingPlan> out;
  // Members seen at two lengths at least: an alternative seen once is
  // alternative_lengths.hpp's, read across its siblings' lengths there.
  auto rows_of = [&](NodeId id) -> const std::vector<LengthRow>* {
    const auto it = rows.find(id);
    return it == rows.end() || it->second.size() < 2 ? nullptr : &it->second;
  };
  for (const NodeId id : nodes_below(g, root)) {
    const auto* choose = std::get_if<Choose>(&g.op(id));
    if (!choose) continue;
    std::map<std::pair<int, std::size_t>, std::vector<NodeId>> groups;  // by axis and part count
    for (const auto& o : choose->options) {
      const auto* s = std::get_if<Split>(&g.op(o.child));
      if (!s || !s->axis.literal_axis() || !rows_of(o.child)) continue;
      auto& members = groups[{*s->axis.literal_axis(), s->parts.size()}];
      if (std::find(members.begin(), members.end(), o.child) == members.end()) members.push_back(o.child);
    }
    for (const auto& [shape, members] : groups) {
      if (members.size() < 2) continue;
      std::vector<std::vector<LengthRow>> member_rows;
      std::vector<std::vector<double>> all;
      std::size_t most = 0;
      bool known = true, planned_alone = false;
      for (const NodeId m : members) {
        const std::vector<LengthRow>* r = rows_of(m);
        if (r->front().lengths.size() != shape.second) {
          known = false;
          break;
        }
        std::vector<std::vector<double>> own;
        for (const LengthRow& row : *r) own.push_back(row.lengths);
        if (const auto alone = planned_sizes(own, tolerance)) {
          most = std::max(most, draws_of(*alone));
          planned_alone = true;
        }
        all.insert(all.end(), own.begin(), own.end());
        member_rows.push_back(*r);
      }
      if (!known || !planned_alone) continue;
      const auto together = planned_sizes(all, tolerance);
      if (!together || draws_of(*together) > most) continue;
      std::size_t next = 0;  // the first of a member's rows in `all`
      for (std::size_t k = 0; k < members.size(); ++k) {
        SiblingPlan plan{*together, member_rows[k]};
        for (PartSizes& p : plan.sizes)
          if (!p.fixed)
            p.values = std::vector<double>(p.values.begin() + static_cast<std::ptrdiff_t>(next),
                                           p.values.begin() + static_cast<std::ptrdiff_t>(next + member_rows[k].size()));
        next += member_rows[k].size();
        out.emplace(members[k], std::move(plan));
      }
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
  const std::unordered_map<NodeId, SiblingPlan> siblings = sibling_plans(g, root, rows, tolerance);
  while (!stack.empty()) {
    const NodeId id = stack.back();
    stack.pop_back();
    if (!seen.insert(id).second) continue;
    for_each_child(g.op(id), [&](NodeId c) { stack.push_back(c); });
    if (const auto sibling = siblings.find(id); sibling != siblings.end()) {
      DrawnSplit drawn = drawn_split(std::get<Split>(g.op(id)), sibling->second.sizes, sibling->second.rows, tolerance);
      const NodeId out = g.intern({std::move(drawn.split), g.node(id).loc});
      if (out == id) continue;
      book[out] = std::move(drawn.values);
      if (replace.size() < g.node_count()) replace.resize(g.node_count(), kNoReplacement);
      replace[id] = out;
      any = true;
      continue;
    }
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
