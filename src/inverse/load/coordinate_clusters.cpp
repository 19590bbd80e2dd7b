#include "inverse/load/coordinate_clusters.hpp"

#include <algorithm>
#include <numeric>

namespace vern {

// Gaps are taken smallest first, and a gap is closed when the two
// clusters it lies between span at most the tolerance together. Clusters
// are runs of positions, so each is known by its two ends: first[last]
// and last[first] hold them.
void split_chain(std::span<const double> v, std::uint32_t from, double tolerance,
                 std::vector<std::uint32_t>& starts) {
  const auto n = static_cast<std::uint32_t>(v.size());
  std::vector<std::uint32_t> gaps(n - 1);  // gap k lies between k and k + 1
  std::iota(gaps.begin(), gaps.end(), 0u);
  std::stable_sort(gaps.begin(), gaps.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return v[a + 1] - v[a] < v[b + 1] - v[b]; });
  std::vector<std::uint32_t> first(n), last(n);  // meaningful at a cluster's ends
  std::iota(first.begin(), first.end(), 0u);
  std::iota(last.begin(), last.end(), 0u);
  std::vector<bool> closed(n - 1, false);
  for (std::uint32_t k : gaps) {
    const std::uint32_t lo = first[k], hi = last[k + 1];
    if (v[hi] - v[lo] > tolerance) continue;
    closed[k] = true;
    last[lo] = hi;
    first[hi] = lo;
  }
  for (std::uint32_t k = 0; k + 1 < n; ++k)
    if (!closed[k]) starts.push_back(from + k + 1);
}

}  // namespace vern
