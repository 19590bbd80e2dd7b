#include "inverse/merge/size_clusters.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "inverse/merge/examples_cost.hpp"

namespace vern {

namespace {

constexpr double kMinGap = 1.25;  // lengths within a quarter are never apart
constexpr double kChance = 0.1;   // a gap one kind of lengths shows this rarely parts two kinds

// Each member's kind along one sized part, its sizes read through `scale`.
template <class Scale>
std::vector<std::size_t> clusters_of_part(const std::vector<SizedMember>& members, std::size_t part, Scale scale) {
  std::vector<std::size_t> kind(members.size(), 0);
  std::vector<std::size_t> order;
  double lowest = 0, highest = 0, observations = 0;
  std::vector<std::optional<Range>> scaled(members.size());
  for (std::size_t m = 0; m < members.size(); ++m) {
    if (members[m].sizes[part]) scaled[m] = scale(members[m], *members[m].sizes[part]);
    const auto& r = scaled[m];
    if (!r || !(r->lo > 0)) continue;
    if (order.empty() || r->lo < lowest) lowest = r->lo;
    if (order.empty() || r->hi > highest) highest = r->hi;
    observations += members[m].weight;
    order.push_back(m);
  }
  // Two lengths alone show no gap inside a range: they are its ends.
  if (order.size() < 2 || observations < 3) return kind;
  // Between the shortest and the longest, n - 2 lengths of one kind spread
  // evenly (on a log scale) leave a gap wider than a share g of the range
  // with chance about (n - 1) (1 - g)^(n - 2). A gap that rare parts two
  // kinds. (A fixed multiple of the average spacing, as before, parts one
  // kind in two more often the more examples there are: the widest of n
  // spacings grows like ln n.)
  const double share = 1 - std::pow(kChance / (observations - 1), 1 / (observations - 2));
  const double gap = std::max(kMinGap, std::exp(share * std::log(highest / lowest)));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return scaled[a]->lo < scaled[b]->lo; });
  std::size_t current = 0;
  double longest = scaled[order[0]]->hi;
  for (std::size_t i = 1; i < order.size(); ++i) {
    const Range& r = *scaled[order[i]];
    if (r.lo > gap * longest) ++current;
    longest = std::max(longest, r.hi);
    kind[order[i]] = current;
  }
  return kind;
}

// What it costs to say the members' sizes along one part, read through
// `scale` and parted into `kinds`: each kind's range (two numbers), which
// kind each member is, and each member's size within its kind's range, all
// to a thousandth of the size. Two readings of one part (its metres, its
// shares) are compared by it: a railing and a slab, each one length seen
// again and again, are two kinds in metres however their shares spread;
// wings of one share on plots of many widths are one kind of share however
// their metres clump.
template <class Scale>
double reading_cost(const std::vector<SizedMember>& members, std::size_t part, const std::vector<std::size_t>& kinds,
                    Scale scale) {
  constexpr double kPrecision = 1e-3;
  std::map<std::size_t, Range> range;
  std::map<std::size_t, double> weight;
  double total = 0;
  for (std::size_t m = 0; m < members.size(); ++m) {
    if (!members[m].sizes[part]) continue;
    const auto r = scale(members[m], *members[m].sizes[part]);
    if (!r) continue;
    auto [it, fresh] = range.try_emplace(kinds[m], *r);
    if (!fresh) it->second = Range{std::min(it->second.lo, r->lo), std::max(it->second.hi, r->hi)};
    weight[kinds[m]] += members[m].weight;
    total += members[m].weight;
  }
  double cost = 2 * number_cost(kPrecision) * static_cast<double>(range.size());
  for (const auto& [kind, r] : range) {
    const double mid = (r.lo + r.hi) / 2;
    const double width = mid > 0 ? (r.hi - r.lo) / mid : 0.0;
    cost += weight[kind] * (drawn_value_cost(width, kPrecision) + kind_cost(weight[kind] / total));
  }
  return cost;
}

}  // namespace

std::vector<std::size_t> size_clusters(const std::vector<SizedMember>& members) {
  // Members are one kind where every part agrees: each part's kinds
  // refine the kinds so far, renumbered in order of first member, which
  // numbers the rows of part kinds as a whole. A part of one kind leaves
  // them as they are.
  std::vector<std::size_t> out(members.size(), 0);
  const std::size_t parts = members.empty() ? 0 : members[0].sizes.size();
  const auto metres = [](const SizedMember&, const Range& r) -> std::optional<Range> { return r; };
  const auto shares = [](const SizedMember& m, const Range& r) -> std::optional<Range> {
    if (!(m.total > 0)) return std::nullopt;
    return Range{r.lo / m.total, r.hi / m.total};
  };
  for (std::size_t p = 0; p < parts; ++p) {
    std::vector<std::size_t> kinds = clusters_of_part(members, p, metres);
    const bool all_shares =
        std::all_of(members.begin(), members.end(), [&](const SizedMember& m) { return !m.sizes[p] || m.total > 0; });
    // One kind in metres is one kind however read: nothing to weigh.
    const bool parted = std::any_of(kinds.begin(), kinds.end(), [](std::size_t k) { return k != 0; });
    if (all_shares && parted) {
      const std::vector<std::size_t> by_share = clusters_of_part(members, p, shares);
      if (reading_cost(members, p, by_share, shares) < reading_cost(members, p, kinds, metres)) kinds = by_share;
    }
    if (std::all_of(kinds.begin(), kinds.end(), [](std::size_t k) { return k == 0; })) continue;
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> numbered;  // (kind so far, part's kind) -> kind
    for (std::size_t m = 0; m < members.size(); ++m)
      out[m] = numbered.try_emplace({out[m], kinds[m]}, numbered.size()).first->second;
  }
  return out;
}

}  // namespace vern
