// Choices seen together, or each on its own: the description length of
// the places of a structure that vary, said as the combinations the
// examples show or as each place's options drawn independently. Joining
// the alternatives of a choice (generalise.hpp) asks it: alternatives
// that differ at several places become one structure with a choice at
// each place only when that costs fewer bits; a roof end seen as two
// gable halves or two hip corners, many times each, stays two fillings.
#pragma once

#include <cstddef>
#include <vector>

namespace vern {

// The two costs, in bits. Each way lists its entries (an entry costs the
// bits to name one of all the places' options) and then the observations'
// picks (their count times the entropy of the weights).
struct ChoiceCosts {
  double coupled = 0;
  double independent = 0;
};

// combinations: the weight of each combination seen; places: for each
// place that varies, the weights of its options as seen.
ChoiceCosts choice_costs(const std::vector<double>& combinations, const std::vector<std::vector<double>>& places);

// The same places said partly each way: the `coupled` ones (count of them)
// as the combinations of their options seen (weights), the `free` ones
// each on its own; `entries`: all places' options, which name an entry.
// choice_costs's two costs are its two ends: all coupled, all free.
double mixed_cost(const std::vector<double>& coupled_combinations, std::size_t coupled,
                  const std::vector<std::vector<double>>& free, std::size_t entries);

}  // namespace vern
