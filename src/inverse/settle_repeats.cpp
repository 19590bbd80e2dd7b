#include "inverse/settle_repeats.hpp"

#include <algorithm>

#include "inverse/merge.hpp"
#include "inverse/substitute.hpp"
#include "inverse/tidy_numbers.hpp"

namespace vern {

NodeId settle_repeats(Grammar& g, NodeId root, const TileCounts& tile_counts, SampleBook& book, double tolerance) {
  std::vector<NodeId> replace(g.node_count(), kNoReplacement);
  bool any = false;
  for (const auto& [id, seen] : tile_counts) {
    if (id >= replace.size() || seen.empty()) continue;
    const auto* r = std::get_if<Repeat>(&g.op(id));
    const auto tile = r ? literal_range(r->size) : std::nullopt;
    if (!tile || tile->hi - tile->lo <= tolerance) continue;
    const std::uint32_t n = seen[0].count;
    if (n >= 2 && std::all_of(seen.begin(), seen.end(), [&](const TileSeen& t) { return t.count == n; })) {
      RepeatN counted{r->axis, Expr::number(n), r->child};
      replace[id] = g.intern({std::move(counted), g.node(id).loc});
      any = true;
      continue;
    }
    if (std::any_of(seen.begin(), seen.end(), [](const TileSeen& t) { return t.count < 2; })) continue;
    // Each middle written as the shortest decimal a quarter of the way to
    // its range's nearer end: tiles of 5 m, not 5.142857 m.
    std::vector<double> middles;
    for (const TileSeen& t : seen) {
      const double k = t.count;
      middles.push_back(shortest_decimal(t.length / (k - 0.5), 0.25 * t.length / (k * (k - 0.5))));
    }
    std::sort(middles.begin(), middles.end());
    middles.erase(std::unique(middles.begin(), middles.end()), middles.end());
    Repeat centred = *r;
    centred.size = range_expr({middles.front(), middles.back()}, tolerance);
    const NodeId out = g.intern({std::move(centred), g.node(id).loc});
    std::vector<Observation> values;
    for (double m : middles) values.push_back({m, 1.0});
    book[out] = {std::move(values)};
    replace[id] = out;
    any = true;
  }
  return any ? substitute_until_settled(g, root, replace) : root;
}

}  // namespace vern
