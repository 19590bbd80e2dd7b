// vernacular::derive and derive_many (src/api/derive.cpp).
#include <gtest/gtest.h>

#include <vernacular/vernacular.hpp>

namespace {

const char* kStreet =
    "@start street\n"
    "@scope rand(10, 20), 8, 9\n"
    "street --> split(x){ ~1 : house | ~rand(0.5, 2) : house }\n"
    "house --> split(z){ 3 : I(wall) | ~1 : I(roof) }\n";

TEST(ApiDerive, PartsAreTheGrammarsBoxesOnItsPlot) {
  const vernacular::Grammar g = vernacular::Grammar::parse(kStreet);
  vernacular::DeriveOptions o;
  o.plot = vernacular::Vec3{12, 8, 9};
  const vernacular::Building b = vernacular::derive(g, o);
  EXPECT_EQ(b.plot, (vernacular::Vec3{12, 8, 9}));
  ASSERT_EQ(b.parts.size(), 4u);
  double width = 0;
  for (const vernacular::Part& p : b.parts) {
    EXPECT_TRUE(p.label == "wall" || p.label == "roof") << p.label;
    if (p.label == "wall") {
      EXPECT_DOUBLE_EQ(p.size[2], 3);
      width += p.size[0];
    }
    EXPECT_EQ(p.axes[0], (vernacular::Vec3{1, 0, 0}));
  }
  EXPECT_DOUBLE_EQ(width, 12);
}

TEST(ApiDerive, TheSameSeedGivesTheSameBuildingAndManyAreSeedsInARow) {
  const vernacular::Grammar g = vernacular::Grammar::parse(kStreet);
  vernacular::DeriveOptions o;
  o.seed = 7;
  const std::vector<vernacular::Building> many = vernacular::derive_many(g, 4, o, 2);
  ASSERT_EQ(many.size(), 4u);
  for (std::uint32_t i = 0; i < 4; ++i) {
    vernacular::DeriveOptions one = o;
    one.seed = 7 + i;
    EXPECT_EQ(vernacular::derive(g, one), many[i]);
  }
  EXPECT_NE(many[0].plot, many[1].plot);  // @scope draws the plot from the seed
}

TEST(ApiDerive, ALimitReachedIsALimitError) {
  const vernacular::Grammar g = vernacular::Grammar::parse("a --> split(x){ ~1 : a | ~1 : a }\n", "runaway.grm");
  vernacular::DeriveOptions o;
  o.max_depth = 20;
  try {
    vernacular::derive(g, o);
    FAIL() << "a runaway grammar derived";
  } catch (const vernacular::Failure& f) {
    EXPECT_EQ(f.error().kind, vernacular::ErrorKind::Limit) << f.what();
    EXPECT_EQ(f.error().location.file, "runaway.grm") << f.what();
  }
}

}  // namespace

namespace {

TEST(ApiDerive, ShardsOfARunDeriveItsBuildingsSliceBySlice) {
  const vernacular::Grammar g = vernacular::Grammar::parse(kStreet);
  vernacular::DeriveOptions o;
  o.seed = 40;
  const std::vector<vernacular::Building> run = vernacular::derive_many(g, 10, o);
  std::vector<vernacular::Building> joined;
  for (std::uint32_t k = 1; k <= 3; ++k) {
    const vernacular::Slice s = vernacular::shard(10, k, 3);
    vernacular::DeriveOptions mine = o;
    mine.seed = o.seed + s.first;
    for (vernacular::Building& b : vernacular::derive_many(g, s.count, mine)) joined.push_back(std::move(b));
  }
  EXPECT_EQ(joined, run);
  EXPECT_THROW(vernacular::shard(10, 0, 3), vernacular::Failure);
  EXPECT_THROW(vernacular::shard(10, 4, 3), vernacular::Failure);
}

}  // namespace
