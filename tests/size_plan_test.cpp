// Which parts of a split keep metres and which share the rest, from the
// lengths examples of different sizes gave them.
#include "inverse/sizes/size_plan.hpp"

#include <gtest/gtest.h>

namespace vern {
namespace {

TEST(SizePlan, WallsOfOneThicknessAreAbsoluteTheMiddleShares) {
  // Plots of 10, 14 and 20 m: 0.6 m walls, bays and a door in 2 : 1.
  const std::vector<std::vector<double>> lengths = {
      {0.6, 5.867, 2.933, 0.6}, {0.6, 8.533, 4.267, 0.6}, {0.6, 12.533, 6.267, 0.6}};
  const auto plan = plan_sizes(lengths, 1e-3);
  ASSERT_TRUE(plan.has_value());
  EXPECT_TRUE((*plan)[0].absolute && (*plan)[0].fixed);
  EXPECT_NEAR((*plan)[0].value, 0.6, 1e-12);
  EXPECT_TRUE((*plan)[3].absolute);
  EXPECT_FALSE((*plan)[1].absolute);
  EXPECT_TRUE((*plan)[1].fixed);
  EXPECT_NEAR((*plan)[1].value / (*plan)[2].value, 2.0, 1e-3);
}

TEST(SizePlan, SharesThatVaryAreLeftToRanges) {
  const std::vector<std::vector<double>> lengths = {{1, 3, 6}, {1, 5, 5}, {1, 2, 12}};
  const auto plan = plan_sizes(lengths, 1e-6);
  ASSERT_TRUE(plan.has_value());
  EXPECT_TRUE((*plan)[0].absolute);
  EXPECT_FALSE((*plan)[1].fixed);
  EXPECT_FALSE((*plan)[2].fixed);
}

TEST(SizePlan, EqualTotalsTellNothing) {
  EXPECT_FALSE(plan_sizes({{1, 3, 6}, {2, 2, 6}}, 1e-6).has_value());
  EXPECT_FALSE(plan_sizes({{1, 3, 6}}, 1e-6).has_value());
}

TEST(SizePlan, ProportionalSplitsStayRelative) {
  // Everything scales: no part keeps its length.
  const auto plan = plan_sizes({{2, 1}, {4, 2}, {6, 3}}, 1e-6);
  ASSERT_TRUE(plan.has_value());
  EXPECT_FALSE((*plan)[0].absolute);
  EXPECT_FALSE((*plan)[1].absolute);
  EXPECT_TRUE((*plan)[0].fixed);
  EXPECT_NEAR((*plan)[0].value, 6.0, 1e-12);  // the widest member's length
  EXPECT_NEAR((*plan)[1].value, 3.0, 1e-12);
}


TEST(SizePlan, ALengthKeptInMetresOnPlotsOfAnySizeIsDrawnInMetres) {
  // A courtyard's ranges 5 to 8 m deep on plots of 24 to 44 m: the ranges
  // are lengths of their own, the court takes the rest.
  const std::vector<std::vector<double>> lengths = {
      {5, 30, 5}, {8, 10, 8}, {6, 26, 6}, {7.5, 14, 7.5}, {5.5, 20, 5.5}};
  const auto plan = plan_drawn_sizes(lengths, 1e-6);
  ASSERT_TRUE(plan.has_value());
  for (std::size_t side : {0u, 2u}) {
    EXPECT_TRUE((*plan)[side].absolute) << side;
    EXPECT_FALSE((*plan)[side].fixed) << side;
    EXPECT_EQ((*plan)[side].values, (std::vector<double>{5, 8, 6, 7.5, 5.5})) << side;
  }
  EXPECT_FALSE((*plan)[1].absolute);  // one part stays relative: it fills any plot
}

TEST(SizePlan, SharesThatGrowWithThePlotStayShares) {
  // A wing a third of every plot: in metres it spreads as the plots do.
  const auto plan = plan_drawn_sizes({{4, 8}, {6, 12.5}, {5, 9.5}, {7, 14.2}}, 1e-6);
  if (plan) {
    EXPECT_FALSE((*plan)[0].absolute);
    EXPECT_FALSE((*plan)[1].absolute);
  }
}

TEST(SizePlan, PartsInOneRatioBesideADrawnLengthKeepTheirRatio) {
  // A lower half: wall and roof in 1 : 0.6, under air of any height.
  const std::vector<std::vector<double>> lengths = {{2.5, 1.5, 3.1}, {3.75, 2.25, 1.2}, {3, 1.8, 2.4}};
  const auto plan = plan_drawn_sizes(lengths, 1e-6);
  ASSERT_TRUE(plan.has_value());
  EXPECT_TRUE((*plan)[2].absolute);
  EXPECT_FALSE((*plan)[2].fixed);
  ASSERT_TRUE((*plan)[0].fixed && (*plan)[1].fixed);
  EXPECT_NEAR((*plan)[1].value / (*plan)[0].value, 0.6, 1e-9);
}

TEST(SizePlan, NothingVaryingIsNoDrawnPlan) {
  EXPECT_FALSE(plan_drawn_sizes({{0.6, 5.867, 2.933, 0.6}, {0.6, 8.533, 4.267, 0.6}}, 1e-3).has_value());
  EXPECT_FALSE(plan_drawn_sizes({{1, 3, 6}}, 1e-6).has_value());
}


TEST(SizePlan, PartsInOneRatioAmongPartsThatVaryKeepTheirRatio) {
  // A pillar and a wing of fixed proportions (1.43 : 1.14) beside two bays
  // whose shares vary: the two keep their ratio, the bays are drawn as
  // weights beside the pillar.
  const std::vector<std::vector<double>> lengths = {
      {1.43, 1.0, 1.14, 0.9}, {2.86, 2.4, 2.28, 2.6}, {1.43, 1.2, 1.14, 1.3}, {2.145, 1.4, 1.71, 1.5}};
  const auto plan = plan_drawn_sizes(lengths, 1e-9);
  ASSERT_TRUE(plan.has_value());
  EXPECT_FALSE((*plan)[0].absolute);
  ASSERT_TRUE((*plan)[0].fixed && (*plan)[2].fixed);
  EXPECT_NEAR((*plan)[2].value / (*plan)[0].value, 1.14 / 1.43, 1e-12);
  ASSERT_FALSE((*plan)[1].fixed);
  // Each row's bay, as a weight beside the pillar's fixed one.
  for (std::size_t m = 0; m < lengths.size(); ++m)
    EXPECT_NEAR((*plan)[1].values[m] / (*plan)[0].value, lengths[m][1] / lengths[m][0], 1e-12) << m;
}

TEST(SizePlan, WholeBaysBeforeADoorAreDrawnInMetres) {
  // Shop bays of 4.3 m before a door bay (1.4 | 1.5 | 1.4), one to four of
  // them, then the rest of plots of any width: the run before the door is
  // a whole number of bays, a point of an evenly spaced row in metres,
  // while its share of each plot spreads.
  const std::vector<std::vector<double>> lengths = {
      {4.3, 1.4, 1.5, 1.4, 12.1}, {8.6, 1.4, 1.5, 1.4, 6.3},  {4.3, 1.4, 1.5, 1.4, 17},
      {17.2, 1.4, 1.5, 1.4, 2.9}, {8.6, 1.4, 1.5, 1.4, 10.4}, {4.3, 1.4, 1.5, 1.4, 9}};
  const auto plan = plan_drawn_sizes(lengths, 1e-6);
  ASSERT_TRUE(plan.has_value());
  EXPECT_TRUE((*plan)[0].absolute);
  EXPECT_EQ((*plan)[0].values, (std::vector<double>{4.3, 8.6, 4.3, 17.2, 8.6, 4.3}));
  EXPECT_FALSE((*plan)[4].absolute);  // the rest fills the plot
}

TEST(SizePlan, AmongSharesThatAllVaryThePartBesideWhichTheyVaryLeastIsTheScale) {
  // Two aisles of independent widths (0.6 to 1.1) beside a nave of 2.6,
  // on plots of any width: beside the nave the aisles spread least, so the
  // nave is the scale and the aisles are drawn as weights beside it.
  const std::vector<double> left = {0.6, 0.9, 1.1, 0.7, 1.0, 0.8}, right = {1.0, 0.6, 0.8, 1.1, 0.7, 0.9};
  const std::vector<double> plot = {8, 11, 9, 12, 10, 7};
  std::vector<std::vector<double>> lengths;
  for (std::size_t m = 0; m < plot.size(); ++m) lengths.push_back({plot[m] * left[m], plot[m] * 2.6, plot[m] * right[m]});
  const auto plan = plan_drawn_sizes(lengths, 1e-6);
  ASSERT_TRUE(plan.has_value());
  ASSERT_TRUE((*plan)[1].fixed);
  ASSERT_FALSE((*plan)[0].fixed || (*plan)[2].fixed);
  for (std::size_t m = 0; m < plot.size(); ++m) {
    EXPECT_NEAR((*plan)[0].values[m] / (*plan)[1].value, left[m] / 2.6, 1e-12) << m;
    EXPECT_NEAR((*plan)[2].values[m] / (*plan)[1].value, right[m] / 2.6, 1e-12) << m;
  }
}

TEST(SizePlan, LengthsThatFollowOneAnotherAreNoScale) {
  // A podium u, storeys 1.5 * u + 2.5 m above it and tiers taking the rest
  // of plots 30 m high: beside the storeys the podium spreads little, but
  // in metres the storeys follow the podium (joint_sizes draws them from
  // it), which says less: no part is the others' scale.
  const std::vector<double> podium = {4, 4.5, 5, 5.5, 6, 4.2};
  std::vector<std::vector<double>> lengths;
  for (const double u : podium) lengths.push_back({u, 1.5 * u + 2.5, 30 - 2.5 * u - 2.5});
  // No plan leaves the merged lengths as they are, as does a plan of
  // each row's own lengths.
  const auto plan = plan_drawn_sizes(lengths, 1e-6);
  for (std::size_t i = 0; plan && i < 3; ++i) {
    ASSERT_FALSE((*plan)[i].fixed) << i;
    for (std::size_t m = 0; m < podium.size(); ++m) EXPECT_NEAR((*plan)[i].values[m], lengths[m][i], 1e-12);
  }
}

}  // namespace
}  // namespace vern
