#include "inverse/merge/choice_costs.hpp"

#include <cmath>
#include <cstddef>
#include <numeric>

namespace vern {

namespace {

// n times the entropy of the weights, n their sum.
double pick_bits(const std::vector<double>& weights) {
  const double n = std::accumulate(weights.begin(), weights.end(), 0.0);
  double bits = 0;
  for (double w : weights)
    if (w > 0) bits -= w * std::log2(w / n);
  return bits;
}

}  // namespace

double mixed_cost(const std::vector<double>& coupled_combinations, std::size_t coupled,
                  const std::vector<std::vector<double>>& free, std::size_t entries) {
  const double per_entry = std::log2(1.0 + static_cast<double>(entries));
  double bits = 0;
  if (coupled > 0)
    bits += static_cast<double>(coupled_combinations.size() * coupled) * per_entry + pick_bits(coupled_combinations);
  for (const auto& p : free) bits += static_cast<double>(p.size()) * per_entry + pick_bits(p);
  return bits;
}

ChoiceCosts choice_costs(const std::vector<double>& combinations, const std::vector<std::vector<double>>& places) {
  std::size_t entries = 0;
  for (const auto& p : places) entries += p.size();
  return {mixed_cost(combinations, places.size(), {}, entries), mixed_cost({}, 0, places, entries)};
}

}  // namespace vern
