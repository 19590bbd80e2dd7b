// Random styles' results per class (evaluate --random-styles).
#include "eval/class_means.hpp"

#include <gtest/gtest.h>

namespace vern {
namespace {

std::size_t at(StyleClass c) { return static_cast<std::size_t>(c); }

// Three styles, two example counts (30 listed first: the largest count need
// not be last).
TEST(ClassMeans, MeansPerClassOverTheStylesThatContainIt) {
  const std::vector<std::uint32_t> counts{30, 3};
  const std::vector<StyleScores> styles{
      {{StyleClass::SharedSize, StyleClass::Wings}, {1.0, 0.2}, {0.8, 0.2}},
      {{StyleClass::SharedSize}, {0.2, 0.1}, {0.6, 0.4}},
      {{StyleClass::NilGap}, {0.25, 0.0}, {1.0, 0.0}},  // a failed inference at N = 3 scores 0
  };
  const ClassTable t = class_means(styles, counts);
  ASSERT_EQ(t.classes.size(), kStyleClasses.size());
  const ClassMeans& shared = t.classes[at(StyleClass::SharedSize)];
  EXPECT_EQ(shared.styles, 2u);
  EXPECT_DOUBLE_EQ(shared.precision[0], 0.6);
  EXPECT_DOUBLE_EQ(shared.precision[1], 0.15);
  EXPECT_DOUBLE_EQ(shared.recall[0], 0.7);
  EXPECT_DOUBLE_EQ(shared.recall[1], 0.3);
  const ClassMeans& wings = t.classes[at(StyleClass::Wings)];
  EXPECT_EQ(wings.styles, 1u);
  EXPECT_DOUBLE_EQ(wings.precision[0], 1.0);
  EXPECT_DOUBLE_EQ(wings.recall[1], 0.2);
  const ClassMeans& tiers = t.classes[at(StyleClass::RecursiveTiers)];
  EXPECT_EQ(tiers.styles, 0u);
  EXPECT_DOUBLE_EQ(tiers.precision[0], 0.0);
  EXPECT_EQ(t.all.styles, 3u);
  EXPECT_DOUBLE_EQ(t.all.precision[0], (1.0 + 0.2 + 0.25) / 3);
  EXPECT_DOUBLE_EQ(t.all.recall[1], (0.2 + 0.4 + 0.0) / 3);
  // At N = 30 (the largest): 0.2 and 0.25 are at most 0.25, 1.0 is not
  // (at N = 3 all three are).
  EXPECT_EQ(t.low_precision, 2u);
}

TEST(ClassMeans, NoStylesNoMeans) {
  const ClassTable t = class_means({}, {3, 10});
  EXPECT_EQ(t.all.styles, 0u);
  EXPECT_EQ(t.all.precision, (std::vector<double>{0.0, 0.0}));
  EXPECT_EQ(t.low_precision, 0u);
}

}  // namespace
}  // namespace vern
