// Combinations seen or places on their own (choice_costs.hpp).
#include "inverse/merge/choice_costs.hpp"

#include <gtest/gtest.h>

namespace vern {
namespace {

TEST(ChoiceCosts, TwoFillingsSeenOftenAreCheaperListedThanFourFreePicks) {
  // A roof end: two gable halves ten times, two hip corners ten times.
  const ChoiceCosts c = choice_costs({10, 10}, {{10, 10}, {10, 10}});
  EXPECT_LT(c.coupled, c.independent);
}

TEST(ChoiceCosts, EveryCombinationSeenIsCheaperAsFreePlaces) {
  // Three places of three options each, all nine-odd combinations seen.
  std::vector<double> combinations(9, 1.0);
  const ChoiceCosts c = choice_costs(combinations, {{3, 3, 3}, {3, 3, 3}});
  EXPECT_LT(c.independent, c.coupled);
}

TEST(ChoiceCosts, OnePlaceCostsTheSameEitherWay) {
  const ChoiceCosts c = choice_costs({6, 2, 2}, {{6, 2, 2}});
  EXPECT_DOUBLE_EQ(c.coupled, c.independent);
}

}  // namespace
}  // namespace vern
