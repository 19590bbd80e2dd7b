#include "inverse/sizes/settle_repeats.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <unordered_map>

#include "graph/nodes_below.hpp"
#include "inverse/merge/merge.hpp"
#include "inverse/merge/substitute.hpp"
#include "inverse/merge/tile_lengths.hpp"
#include "inverse/sizes/fit_distribution.hpp"
#include "inverse/sizes/tidy_numbers.hpp"

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

// What a repeat's tiles are made of, for pooling: its axis, and the
// labels and rules below its tile, in order. Storeys of one style that
// merging kept apart (each alternative of a door bay's place holds its
// own) hold the same parts.
std::vector<std::uint64_t> made_of(const Grammar& g, const Repeat& r) {
  std::vector<std::uint64_t> key;
  const auto axis = r.axis.literal_axis();
  key.push_back(axis ? static_cast<std::uint64_t>(*axis) : 99);
  std::vector<std::uint64_t> parts;
  for (const NodeId n : nodes_below(g, r.child)) {
    if (const auto* p = std::get_if<Primitive>(&g.op(n))) parts.push_back(p->label);
    else if (const auto* c = std::get_if<Call>(&g.op(n))) parts.push_back((1ull << 40) + c->rule);
  }
  std::sort(parts.begin(), parts.end());
  parts.erase(std::unique(parts.begin(), parts.end()), parts.end());
  key.insert(key.end(), parts.begin(), parts.end());
  return key;
}

// A repeat's tile's shape, coarser than made_of: the operation it is and
// its axis (a split along x: a row of bays of any kind), or its label (a
// brick course).
std::vector<std::uint64_t> tile_shape(const Grammar& g, const Repeat& r) {
  const auto axis = r.axis.literal_axis();
  std::vector<std::uint64_t> key{axis ? static_cast<std::uint64_t>(*axis) : 99, g.op(r.child).index()};
  if (const auto* s = std::get_if<Split>(&g.op(r.child))) {
    const auto a = s->axis.literal_axis();
    key.push_back(a ? static_cast<std::uint64_t>(*a) : 99);
  } else if (const auto* p = std::get_if<Primitive>(&g.op(r.child))) {
    key.push_back(p->label);
  } else {
    key.push_back(r.child);  // anything else: alike only as one node
  }
  return key;
}

// One tile size for every repeat of a pool that some one size explains:
// by repeat, that size. Repeats of what they are made of (made_of) and of
// one kind of length (tile_lengths.hpp: plots and strips a quarter as wide
// stay apart) are a pool (first by tile_shape, then by made_of) where there are two or more and they differ in
// size; alike in size, each is settled as it is.
std::unordered_map<NodeId, double> pooled_tiles(const Grammar& g, NodeId root, const TileCounts& tile_counts,
                                                double tolerance) {
  // The repeats below root whose counts are known, by axis and kind of
  // length first: what they are made of is looked at only where such a
  // group differs in size (each look walks a repeat's subgraph).
  const TileLengths kinds(g, root);
  std::map<std::pair<std::uint64_t, std::size_t>, std::vector<NodeId>> coarse;
  for (const NodeId id : nodes_below(g, root)) {
    const auto* r = std::get_if<Repeat>(&g.op(id));
    if (!r || !literal_range(r->size)) continue;
    const auto known = tile_counts.find(id);
    if (known == tile_counts.end() || known->second.empty()) continue;
    coarse[{r->axis.literal_axis().value_or(99), kinds.kind(*r)}].push_back(id);
  }
  // Two or more repeats, not all of one size: a pool to settle.
  auto differ = [&](const std::vector<NodeId>& members) {
    if (members.size() < 2) return false;
    const Expr& first = std::get<Repeat>(g.op(members[0])).size;
    return std::any_of(members.begin(), members.end(),
                       [&](NodeId id) { return !(std::get<Repeat>(g.op(id)).size == first); });
  };
  std::unordered_map<NodeId, double> out;
  auto settle_pools = [&](const std::map<std::vector<std::uint64_t>, std::vector<NodeId>>& pools) {
    for (const auto& [key, members] : pools) {
      if (!differ(members)) continue;
      std::vector<TileSeen> all;
      for (NodeId id : members) {
        const auto& seen = tile_counts.at(id);
        all.insert(all.end(), seen.begin(), seen.end());
      }
      const auto one = common_tile(all, tolerance);
      if (!one) continue;
      for (NodeId id : members) out[id] = *one;
    }
  };
  for (auto& [axis_and_kind, candidates] : coarse) {
    if (!differ(candidates)) continue;
    // Repeats whose tiles are of one shape (rows cut along one axis:
    // storeys, whatever bays they hold) take one size where one explains
    // every count they made: each alternative's own examples allowed 3 m
    // in one and 3.5 m in another. Else pools of repeats made alike.
    std::map<std::vector<std::uint64_t>, std::vector<NodeId>> shapes;
    for (const NodeId id : candidates) shapes[tile_shape(g, std::get<Repeat>(g.op(id)))].push_back(id);
    settle_pools(shapes);
    std::map<std::vector<std::uint64_t>, std::vector<NodeId>> pools;
    for (const NodeId id : candidates)
      if (!out.count(id)) pools[made_of(g, std::get<Repeat>(g.op(id)))].push_back(id);
    settle_pools(pools);
  }
  return out;
}

// The counts seen, where they vary and do not follow the lengths: their
// correlation with the lengths is below kFollows, over kFewestForCounts
// rows or more (fewer correlate by chance). Tiles of one size, or of a
// range of sizes, make counts that grow with the length (storeys of 3 to
// 4 m on buildings 10 to 40 m high: a correlation above 0.9).
constexpr std::size_t kFewestForCounts = 8;
constexpr double kFollows = 0.5;

std::optional<std::vector<double>> counts_apart_from_lengths(const std::vector<TileSeen>& seen) {
  if (seen.size() < kFewestForCounts) return std::nullopt;
  std::vector<double> counts, lengths;
  for (const TileSeen& t : seen) {
    counts.push_back(t.count);
    lengths.push_back(t.length);
  }
  const double n = static_cast<double>(seen.size());
  const double mc = std::accumulate(counts.begin(), counts.end(), 0.0) / n;
  const double ml = std::accumulate(lengths.begin(), lengths.end(), 0.0) / n;
  double sc = 0, sl = 0, scl = 0;
  for (std::size_t i = 0; i < seen.size(); ++i) {
    sc += (counts[i] - mc) * (counts[i] - mc);
    sl += (lengths[i] - ml) * (lengths[i] - ml);
    scl += (counts[i] - mc) * (lengths[i] - ml);
  }
  if (!(sc > 0) || !(sl > 0)) return std::nullopt;  // counts or lengths that do not vary
  if (scl / std::sqrt(sc * sl) >= kFollows) return std::nullopt;
  return counts;
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
    // A tile that divides a length exactly gives its count (the count
    // forgives float noise: repeat_tile_count), so the lowest size is the
    // tile itself less that noise: 3.8 m for a run of six 3.8 m bays
    // measured 22.800000000005 m, not the 3.81 just above.
    const double floor_noise = lo * 1e-10;
    // A length that is whole tiles of a size in centimetres, to the
    // tolerance, is that size where lengths are not all in whole
    // centimetres: lengths drawn at random are not whole tiles of
    // anything short (k bays of 4.5 m before a door, the rest a
    // stretching repeat, whose lengths alone put the tile at 4.6). On a
    // model drawn on a centimetre grid every length is whole centimetres
    // and half of them whole tiles of something by chance: there, only
    // two lengths of two tiles or more tell.
    const double centimetres = std::round(lo * 100) / 100;
    const bool grid = std::ranges::all_of(
        seen, [&](const TileSeen& t) { return std::abs(t.length - std::round(t.length * 100) / 100) <= tolerance; });
    std::vector<double> tiled;  // distinct lengths of whole tiles of it
    for (const TileSeen& t : seen)
      if ((t.count >= 2 || !grid) && std::abs(t.length - t.count * centimetres) <= tolerance &&
          std::none_of(tiled.begin(), tiled.end(), [&](double l) { return std::abs(l - t.length) <= tolerance; }))
        tiled.push_back(t.length);
    if (known == 0 && tiled.size() >= (grid ? 2u : 1u) && centimetres >= lo - floor_noise && centimetres < hi &&
        gives_every_count_firmly(seen, centimetres, tolerance))
      return centimetres;
    const auto t = shortest_decimal_in(lo - floor_noise, hi);
    if (!t) continue;
    if (gives_every_count_firmly(seen, *t, tolerance)) return t;
  }
  return std::nullopt;
}

NodeId settle_repeats(Grammar& g, NodeId root, const TileCounts& tile_counts, SampleBook& book, double tolerance) {
  std::vector<NodeId> replace(g.node_count(), kNoReplacement);
  bool any = false;
  const std::unordered_map<NodeId, double> pooled = pooled_tiles(g, root, tile_counts, tolerance);
  for (const auto& [id, seen] : tile_counts) {
    if (id >= replace.size() || seen.empty()) continue;
    const auto* r = std::get_if<Repeat>(&g.op(id));
    const auto tile = r ? literal_range(r->size) : std::nullopt;
    if (!tile) continue;
    // A size its pool shares, where one explains them all: storeys alike
    // in every alternative are one storey height, not 3.3 m in one and
    // 3.5 m in another (each the middle of what its own examples allow).
    if (const auto it = pooled.find(id); it != pooled.end()) {
      if (tile->hi - tile->lo <= tolerance && tile->lo == it->second) continue;
      Repeat fixed = *r;
      fixed.size = Expr::number(it->second);
      replace[id] = g.intern({std::move(fixed), g.node(id).loc});
      any = true;
      continue;
    }
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
    // Counts that do not follow the lengths (a street of three to six
    // equal houses on plots of any width, a recursion's count): as many
    // tiles as the counts seen, whatever the length. Tiles of a size,
    // even one that varies, make more of them on longer lengths.
    if (const auto counts = counts_apart_from_lengths(seen)) {
      RepeatN counted{r->axis, count_expr(*counts), r->child};
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
