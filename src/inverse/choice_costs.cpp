#include "inverse/choice_costs.hpp"

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

ChoiceCosts choice_costs(const std::vector<double>& combinations, const std::vector<std::vector<double>>& places) {
  std::size_t entries = 0;
  for (const auto& p : places) entries += p.size();
  const double per_entry = std::log2(1.0 + static_cast<double>(entries));
  ChoiceCosts c;
  c.coupled = static_cast<double>(combinations.size() * places.size()) * per_entry + pick_bits(combinations);
  c.independent = static_cast<double>(entries) * per_entry;
  for (const auto& p : places) c.independent += pick_bits(p);
  return c;
}

}  // namespace vern
