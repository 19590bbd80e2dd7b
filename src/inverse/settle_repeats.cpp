#include "inverse/settle_repeats.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "inverse/merge.hpp"
#include "inverse/substitute.hpp"
#include "inverse/tidy_numbers.hpp"

namespace vern {

namespace {

// The shortest decimal in [lo, hi), nearest the middle among those as
// short: 4 in [3.99, 4.5), 3.5 in [3.47, 3.52).
std::optional<double> shortest_decimal_in(double lo, double hi) {
  const double middle = 0.5 * (lo + hi);
  for (double scale = 1; scale <= 1e9; scale *= 10) {
    const double first = std::ceil(lo * scale), last = std::ceil(hi * scale) - 1;
    if (first > last) continue;
    const double k = std::clamp(std::round(middle * scale), first, last);
    return k / scale;
  }
  return std::nullopt;
}

// Whether tiles of size t give every count seen on its length, and still
// do on a length a tolerance longer. A tile at the very end of a length's
// range gives its count only on that length: a length known to the
// tolerance (an example far from the origin, in single precision) may
// come out a hair longer where the grammar derives it, and so one tile
// more. Only a length the tile divides exactly (4 m tiles on 8 m) may be
// at the end.
bool gives_every_count_firmly(const std::vector<TileSeen>& seen, double t, double tolerance) {
  return std::ranges::all_of(seen, [&](const TileSeen& s) {
    const double n = s.count;
    if (repeat_tile_count(s.length, t) != n) return false;
    const double q = s.length / t;
    return std::abs(q - std::round(q)) <= 1e-9 * std::max(1.0, q) || repeat_tile_count(s.length + tolerance, t) == n;
  });
}

}  // namespace

std::optional<double> common_tile(const std::vector<TileSeen>& seen, double tolerance) {
  if (seen.empty()) return std::nullopt;
  // The sizes that give n tiles on every L seen: [L/n, L/(n-1)). Tried as
  // the lengths are (a tile of exactly 4 m makes one tile on 4 m), then
  // with every length known only to the tolerance.
  for (const double known : {0.0, tolerance}) {
    double lo = 0, hi = std::numeric_limits<double>::infinity();
    for (const TileSeen& t : seen) {
      if (t.count == 0 || !(t.length > 0)) return std::nullopt;
      const double n = t.count;
      lo = std::max(lo, (t.length + known) / n);
      if (t.count >= 2) hi = std::min(hi, (t.length - tolerance) / (n - 1));
    }
    if (!std::isfinite(hi)) hi = 2 * lo;  // one tile everywhere: any size from the longest up
    if (!(hi > lo)) continue;
    const auto t = shortest_decimal_in(lo, hi);
    if (!t) continue;
    if (gives_every_count_firmly(seen, *t, tolerance)) return t;
  }
  return std::nullopt;
}

NodeId settle_repeats(Grammar& g, NodeId root, const TileCounts& tile_counts, SampleBook& book, double tolerance) {
  std::vector<NodeId> replace(g.node_count(), kNoReplacement);
  bool any = false;
  for (const auto& [id, seen] : tile_counts) {
    if (id >= replace.size() || seen.empty()) continue;
    const auto* r = std::get_if<Repeat>(&g.op(id));
    const auto tile = r ? literal_range(r->size) : std::nullopt;
    if (!tile) continue;
    // One size already: kept where it gives the counts firmly, else moved
    // into their ranges (below).
    const bool one_size = tile->hi - tile->lo <= tolerance;
    if (one_size && gives_every_count_firmly(seen, tile->lo, tolerance)) continue;
    // One tile size that makes every count seen on its length explains the
    // examples in one number, where a range needs two and draws counts the
    // examples never had: the tile of the source, or as near as the
    // examples tell (issue 15: a 4 m tile came back as rand(3.44, 4.56)).
    if (const auto one = common_tile(seen, tolerance)) {
      Repeat fixed = *r;
      fixed.size = Expr::number(*one);
      replace[id] = g.intern({std::move(fixed), g.node(id).loc});
      any = true;
      continue;
    }
    if (one_size) continue;  // no firmer size: as it was
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
  if (!any) return root;
  // Splits above a rewritten node are rebuilt: their values go with them.
  return substitute_keeping_samples(g, root, replace, book);
}

}  // namespace vern
