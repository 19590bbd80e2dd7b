// Sizes of a recursion's levels as functions of the levels still to come.
#include "inverse/sizes/levels_left.hpp"

#include <gtest/gtest.h>

#include "graph/writer.hpp"

namespace vern {
namespace {

// A relative part seen at counts 1..counts with weights w(n).
template <class Weight>
LevelPart relative(Weight w, int counts = 5) {
  LevelPart p;
  p.relative = true;
  for (int n = 1; n <= counts; ++n) p.seen.emplace_back(n, w(n));
  return p;
}

std::string text(const std::optional<Size>& s) {
  if (!s) return "-";
  return std::string(s->relative ? "~" : "") + write_expression(Grammar{}, s->value, {"n"});
}

TEST(LevelsLeft, ADrumOneShareInNOfItsTier) {
  // split(z){ ~1 : drum | ~(n - 1) : rest } on a tier 17 high, as merging
  // writes it: the drum 17 / n, the rest 17 (n - 1) / n, with n the tiers
  // left counting this one; here n counts from 1 at the innermost.
  const std::vector<std::vector<LevelPart>> levels = {
      {relative([](int n) { return 17.0 / (n + 1); }), relative([](int n) { return 17.0 * n / (n + 1); })}};
  const auto sizes = sizes_by_levels_left(levels, 1e-6);
  ASSERT_TRUE(sizes.has_value());
  EXPECT_EQ(text((*sizes)[0][0]), "~1");
  EXPECT_EQ(text((*sizes)[0][1]), "~n");
}

TEST(LevelsLeft, ALengthOnALineInTheCount) {
  LevelPart storey;
  for (int n = 1; n <= 4; ++n) storey.seen.emplace_back(n, 3 + 0.5 * n);
  LevelPart rest;
  rest.relative = true;
  rest.ranged = true;
  const auto sizes = sizes_by_levels_left({{storey, rest}}, 1e-6);
  ASSERT_TRUE(sizes.has_value());
  EXPECT_EQ(text((*sizes)[0][0]), "0.5 * n + 3");
  EXPECT_EQ(text((*sizes)[0][1]), "-");  // keeps its range
}

TEST(LevelsLeft, SizesThatDoNotFollowTheCountAreNone) {
  // The same at every count, or drawn: nothing to count.
  const auto same = relative([](int) { return 2.0; });
  EXPECT_FALSE(sizes_by_levels_left({{same, same}}, 1e-6).has_value());
  LevelPart drawn;
  drawn.ranged = true;
  EXPECT_FALSE(sizes_by_levels_left({{drawn, same}}, 1e-6).has_value());
}

TEST(LevelsLeft, ALengthOffAnyLineOrSeenAtTwoCountsIsNone) {
  LevelPart squares;
  for (int n = 1; n <= 4; ++n) squares.seen.emplace_back(n, n * n);
  EXPECT_FALSE(sizes_by_levels_left({{squares}}, 1e-6).has_value());
  LevelPart two;
  two.seen = {{1, 3.0}, {2, 4.0}};
  EXPECT_FALSE(sizes_by_levels_left({{two}}, 1e-6).has_value());
  LevelPart disagreeing;  // two sizes at one count: no function of it
  disagreeing.seen = {{1, 3.0}, {1, 5.0}, {2, 4.0}, {3, 5.0}};
  EXPECT_FALSE(sizes_by_levels_left({{disagreeing}}, 1e-6).has_value());
}

TEST(LevelsLeft, AWholeRatioAtTwoCountsIsALine) {
  // Pagodas of two and three tiers: the drum is a half, then a third, of
  // its tier, n in 1..2. The rest's ratio to the drum is 1, then 2: whole
  // numbers, which a grammar writes and chance hardly gives.
  const auto tier = [](double height) {
    return std::vector<LevelPart>{relative([=](int n) { return height / (n + 1); }, 2),
                                  relative([=](int n) { return height * n / (n + 1); }, 2)};
  };
  const auto sizes = sizes_by_levels_left({tier(17)}, 1e-6);
  ASSERT_TRUE(sizes.has_value());
  EXPECT_EQ(text((*sizes)[0][0]), "~1");
  EXPECT_EQ(text((*sizes)[0][1]), "~n");
  // Ratios that are not whole numbers at two counts follow no line.
  LevelPart drum, rest;
  drum.relative = rest.relative = true;
  drum.seen = {{1, 4.0}, {2, 3.0}};
  rest.seen = {{1, 5.2}, {2, 7.5}};
  EXPECT_FALSE(sizes_by_levels_left({{drum, rest}}, 1e-6).has_value());
}

}  // namespace
}  // namespace vern
