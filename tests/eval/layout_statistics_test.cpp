// Comparing samples of buildings: Wasserstein distance, style distance,
// and telling a copy of an example from a new building.
#include "eval/layout_statistics.hpp"

#include <gtest/gtest.h>

#include "forward/variants.hpp"
#include "graph/parser.hpp"
#include "support/derive_helpers.hpp"

namespace vern {
namespace {

TEST(Wasserstein, IsTheAreaBetweenTheDistributionFunctions) {
  EXPECT_DOUBLE_EQ(wasserstein1({1, 2, 3}, {1, 2, 3}), 0.0);
  EXPECT_DOUBLE_EQ(wasserstein1({0}, {5}), 5.0);
  EXPECT_DOUBLE_EQ(wasserstein1({0, 1}, {0}), 0.5);          // half the mass moves 1
  EXPECT_DOUBLE_EQ(wasserstein1({1, 3}, {2, 2, 2, 2}), 1.0);  // each half moves 1
  EXPECT_DOUBLE_EQ(wasserstein1({}, {-2, 4}), 3.0);
}

std::vector<Derivation> sample(const std::string& text, std::uint64_t seed, std::uint32_t n = 200) {
  VariantOptions o;
  o.derive.seed = seed;
  o.derive.size = glm::dvec3(10, 10, 10);
  o.count = n;
  return derive_variants(parse_grammar(text), o);
}

TEST(StyleDistance, SmallForTheSameGrammarLargeForAnother) {
  const std::string a = "a --> split(x){ ~rand(1, 2) : I(rect) | ~1 : repeat(y, 2){ I(window) } }\n";
  const std::string b = "a --> split(x){ ~rand(3, 4) : I(rect) | ~1 : repeat(y, 5){ I(window) } }\n";
  const StyleDistance same = style_distance(sample(a, 1), sample(a, 1001));
  const StyleDistance other = style_distance(sample(a, 1), sample(b, 1001));
  EXPECT_LT(same.sizes, 0.03);
  EXPECT_EQ(same.structure, 0.0);  // always 1 rect and 5 windows
  EXPECT_GT(other.sizes, 0.2);
  // rect: 1 against 1; window: 5 against 2, off by 3/5. The mean of the two.
  EXPECT_DOUBLE_EQ(other.structure, 0.3);
}

TEST(StyleDistance, ALabelOnlyOneSideHasCountsFully) {
  const StyleDistance d = style_distance(sample("a --> I(rect)", 1, 5), sample("a --> I(roof)", 1, 5));
  EXPECT_DOUBLE_EQ(d.structure, 1.0);
}

TEST(SameLayout, IgnoresOrderAndNoiseButNotADifference) {
  const Derivation d = test::derive_text("a --> split(x){ 2 : I(rect) | ~1 : I(window) | 2 : I(rect) }", {10, 4, 3});
  Derivation shuffled = d;
  std::swap(shuffled.terminals[0], shuffled.terminals[2]);
  shuffled.terminals[1].scope.origin.x += 1e-7;
  EXPECT_TRUE(same_layout(d, shuffled, 1e-5));
  Derivation moved = d;
  moved.terminals[1].scope.origin.x += 1e-3;
  EXPECT_FALSE(same_layout(d, moved, 1e-5));
  Derivation relabelled = d;
  relabelled.terminals[0].label = relabelled.terminals[1].label;
  EXPECT_FALSE(same_layout(d, relabelled, 1e-5));
}

}  // namespace
}  // namespace vern
