// Rows of parts that are two splits, one inside the other.
#include "inverse/merge/nested_split.hpp"

#include <gtest/gtest.h>

namespace vern {
namespace {

// site --> split(x){ ~1.2 : lodge | ~1.1 : lodge | ~2.9 : front }
// front --> split(x){ 1 : column | ~1 : mass | 1 : column }
// as the five lengths a site of width w cuts.
std::vector<double> lodges_and_front(double w) {
  const double k = w / 5.2;
  return {1.2 * k, 1.1 * k, 1, 2.9 * k - 2, 1};
}

TEST(NestedSplit, LodgesBesideAFrontOfColumnsAndAMass) {
  const std::vector<std::vector<double>> lengths = {lodges_and_front(21.5), lodges_and_front(25),
                                                    lodges_and_front(29.5)};
  const auto run = find_nested_run(lengths, plan_sizes(lengths, 1e-6), 1e-6);
  ASSERT_TRUE(run.has_value());
  EXPECT_EQ(run->first, 2u);
  EXPECT_EQ(run->last, 4u);
  const auto outer = outer_lengths(lengths, *run);
  ASSERT_EQ(outer[0].size(), 3u);
  EXPECT_NEAR(outer[0][2], 2.9 * 21.5 / 5.2, 1e-12);
  const auto inner = inner_lengths(lengths, *run);
  ASSERT_EQ(inner[1].size(), 3u);
  EXPECT_EQ(inner[1][0], 1);
  EXPECT_NEAR(inner[1][1], 2.9 * 25 / 5.2 - 2, 1e-12);
}

TEST(NestedSplit, ARowThatIsOneSplitIsLeftAsItIs) {
  // 0.6 m walls and bays in 2 : 1: one split of fixed sizes.
  const std::vector<std::vector<double>> lengths = {
      {0.6, 5.867, 2.933, 0.6}, {0.6, 8.533, 4.267, 0.6}, {0.6, 12.533, 6.267, 0.6}};
  EXPECT_FALSE(find_nested_run(lengths, plan_sizes(lengths, 1e-3), 1e-3).has_value());
}

TEST(NestedSplit, SharesThatVaryFreelyAreNoNesting) {
  // No run of these makes fixed sizes: the shares were drawn independently.
  const std::vector<std::vector<double>> lengths = {{1, 3, 6, 2}, {1, 5, 5, 4}, {1, 2, 12, 1}, {1, 7, 3, 3}};
  EXPECT_FALSE(find_nested_run(lengths, plan_sizes(lengths, 1e-6), 1e-6).has_value());
}

TEST(NestedSplit, TwoRowsAreTooFewToTell) {
  const std::vector<std::vector<double>> lengths = {lodges_and_front(21.5), lodges_and_front(29.5)};
  EXPECT_FALSE(find_nested_run(lengths, plan_sizes(lengths, 1e-6), 1e-6).has_value());
}

TEST(NestedSplit, TheShortestRunWins) {
  // A wing of a fixed 1 : 2 inside a margin of 0.5 m: parts 1..2 share
  // the rest of the plot in a ratio to part 0 that the whole row's plan
  // cannot keep because of the margins inside the run.
  std::vector<std::vector<double>> lengths;
  for (const double w : {10.0, 13.0, 17.0, 22.0}) {
    const double k = w / 3;  // ~1 : a | ~2 : split{ 0.5 : m | ~1 : b | 0.5 : m }
    lengths.push_back({k, 0.5, 2 * k - 1, 0.5});
  }
  const auto run = find_nested_run(lengths, plan_sizes(lengths, 1e-6), 1e-6);
  ASSERT_TRUE(run.has_value());
  EXPECT_EQ(run->first, 1u);
  EXPECT_EQ(run->last, 3u);
}

TEST(NestedSplit, ALodgeOfAnyWidthBesideTheFrontLeavesOnlyItsWidthDrawn) {
  // The second lodge drawn anew in each building: the outer split draws
  // that one share, and the front still keeps its columns and mass
  // (drawn as one split, the mass and both lodges would each be drawn).
  std::vector<std::vector<double>> lengths;
  const double widths[] = {21.5, 25, 29.5, 23, 27};
  const double lodges[] = {0.8, 1.3, 1.0, 1.4, 0.9};
  for (int i = 0; i < 5; ++i) {
    const double k = widths[i] / (1.2 + lodges[i] + 2.9);
    lengths.push_back({1.2 * k, lodges[i] * k, 1, 2.9 * k - 2, 1});
  }
  const auto run = find_nested_run(lengths, plan_sizes(lengths, 1e-6), 1e-6);
  ASSERT_TRUE(run.has_value());
  EXPECT_EQ(run->first, 2u);
  EXPECT_EQ(run->last, 4u);
  EXPECT_EQ(draws_of(run->inner), 0u);
  EXPECT_EQ(draws_of(run->outer), 1u);
  ASSERT_EQ(run->outer.size(), 3u);
  EXPECT_FALSE(run->outer[1].fixed);
  EXPECT_TRUE(run->outer[0].fixed && run->outer[2].fixed);
}

// villa --> split(x){ ~1 : wing | ~1.6 : main | ~1 : R(z, pi){ wing } }
// wing --> split(x){ 2.5 : porch | ~1 : body }
// as the five lengths a villa of width w cuts: porch, body, main, body,
// porch.
std::vector<double> mirrored_wings(double w) {
  const double wing = w / 3.6;
  return {2.5, wing - 2.5, 1.6 * wing, wing - 2.5, 2.5};
}

TEST(NestedSplit, TwoWingsNestOnlyTogether) {
  // Either wing nested alone leaves the other's body and porch beside the
  // main block, drawing as many sizes as the row; both nested, the villa
  // is ~1 : ~1.6 : ~1 and nothing is drawn.
  const std::vector<std::vector<double>> lengths = {mirrored_wings(30), mirrored_wings(36), mirrored_wings(43)};
  const auto whole = plan_sizes(lengths, 1e-6);
  EXPECT_FALSE(find_nested_run(lengths, whole, 1e-6).has_value());
  const auto run = find_fixed_run_leading_on(lengths, whole, 1e-6);
  ASSERT_TRUE(run.has_value());
  EXPECT_EQ(run->first, 0u);
  EXPECT_EQ(run->last, 1u);
  const auto second = find_nested_run(outer_lengths(lengths, *run), plan_sizes(outer_lengths(lengths, *run), 1e-6), 1e-6);
  ASSERT_TRUE(second.has_value());
  EXPECT_EQ(second->first, 2u);
  EXPECT_EQ(second->last, 3u);
  EXPECT_EQ(draws_of(second->inner) + draws_of(second->outer), 0u);
}

}  // namespace
}  // namespace vern
