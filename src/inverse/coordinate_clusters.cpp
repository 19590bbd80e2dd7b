#include "inverse/coordinate_clusters.hpp"

#include <algorithm>
#include <numeric>

namespace vern {

namespace {

// Splits the chain [from, to) (neighbours within the tolerance, spanning
// more than it) into clusters: gaps are taken smallest first, and a gap is
// closed when the two clusters it lies between span at most the
// tolerance together. Clusters are runs of positions, so each is known by
// its two ends: first_[last] and last_[first] hold them.
void split_chain(std::span<const double> v, std::uint32_t from, std::uint32_t to, double tolerance,
                 std::vector<std::uint32_t>& starts) {
  const std::uint32_t n = to - from;
  std::vector<std::uint32_t> gaps(n - 1);  // gap k lies between from+k and from+k+1
  std::iota(gaps.begin(), gaps.end(), 0u);
  std::stable_sort(gaps.begin(), gaps.end(), [&](std::uint32_t a, std::uint32_t b) {
    return v[from + a + 1] - v[from + a] < v[from + b + 1] - v[from + b];
  });
  std::vector<std::uint32_t> first(n), last(n);  // meaningful at a cluster's ends
  std::iota(first.begin(), first.end(), 0u);
  std::iota(last.begin(), last.end(), 0u);
  std::vector<bool> closed(n - 1, false);
  for (std::uint32_t k : gaps) {
    const std::uint32_t lo = first[k], hi = last[k + 1];
    if (v[from + hi] - v[from + lo] > tolerance) continue;
    closed[k] = true;
    last[lo] = hi;
    first[hi] = lo;
  }
  for (std::uint32_t k = 0; k + 1 < n; ++k)
    if (!closed[k]) starts.push_back(from + k + 1);
}

}  // namespace

std::vector<std::uint32_t> cluster_starts(std::span<const double> sorted, double tolerance) {
  std::vector<std::uint32_t> starts;
  const auto n = static_cast<std::uint32_t>(sorted.size());
  std::uint32_t chain = 0;  // first position of the current run of near neighbours
  for (std::uint32_t i = 0; i <= n; ++i) {
    if (i < n && i > 0 && sorted[i] - sorted[i - 1] <= tolerance) continue;
    // [chain, i) is a run of neighbours within the tolerance.
    if (i > 0) {
      if (sorted[i - 1] - sorted[chain] > tolerance) split_chain(sorted, chain, i, tolerance, starts);
    }
    if (i < n) starts.push_back(i);
    chain = i;
  }
  return starts;
}

}  // namespace vern
