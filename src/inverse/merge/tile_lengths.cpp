#include "inverse/merge/tile_lengths.hpp"

#include <algorithm>
#include <optional>

#include "graph/nodes_below.hpp"
#include "inverse/merge/merge.hpp"

namespace vern {

namespace {

std::optional<std::size_t> axis_of(const Repeat& r) {
  if (r.axis.nodes().size() != 1 || r.axis.node(0).kind != ExprKind::Axis) return std::nullopt;
  return static_cast<std::size_t>(r.axis.node(0).op);
}

}  // namespace

TileLengths::TileLengths(const Grammar& g, NodeId root) {
  std::array<std::vector<Range>, 3> lengths;
  walk_below(g, root, [&](NodeId id) {
    if (const auto* r = std::get_if<Repeat>(&g.op(id)))
      if (const auto axis = axis_of(*r); axis && literal_range(r->size)) lengths[*axis].push_back(*literal_range(r->size));
    return true;
  });
  for (std::size_t a = 0; a < 3; ++a) {
    std::sort(lengths[a].begin(), lengths[a].end(), [](const Range& x, const Range& y) { return x.lo < y.lo; });
    double longest = 0;  // the longest length so far
    for (const Range& r : lengths[a]) {
      if (starts_[a].empty() || r.lo > kLengthGap * longest) starts_[a].push_back(r.lo);
      longest = std::max(longest, r.hi);
    }
  }
}

std::size_t TileLengths::kind(const Repeat& r) const {
  const auto axis = axis_of(r);
  const auto length = literal_range(r.size);
  if (!axis || !length) return 0;
  const auto& starts = starts_[*axis];
  return static_cast<std::size_t>(std::upper_bound(starts.begin(), starts.end(), length->lo) - starts.begin());
}

}  // namespace vern
