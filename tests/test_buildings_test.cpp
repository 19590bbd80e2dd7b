// infer's test buildings (inverse/write/test_buildings.hpp): a limit reached is a
// warning that says where, any other failure is thrown.
#include "inverse/write/test_buildings.hpp"

#include <gtest/gtest.h>

#include "base/error.hpp"
#include "graph/parser.hpp"

namespace vern {
namespace {

TEST(TestBuildings, AGrammarThatDerivesGivesNoWarning) {
  const Grammar g = parse_grammar("@scope 4, 4, 4\nb --> repeat(x, 1){ I(brick) }\n", "g.grm");
  EXPECT_TRUE(derive_test_buildings(g, {}).empty());
}

// Bricks of 0.1 m in a scope drawn up to 80 m: half a billion of them.
TEST(TestBuildings, ABuildingPastALimitIsAWarningThatSaysWhereAndHowToAvoidIt) {
  const Grammar g = parse_grammar(
      "@scope rand(40, 80), 80, 80\nb --> repeat(x, 0.1){ repeat(y, 0.1){ repeat(z, 0.1){ I(brick) } } }\n", "g.grm");
  TestBuildingsOptions options;
  options.first_seed = 5;
  options.example_parts = 64;
  const std::vector<std::string> warnings = derive_test_buildings(g, options);
  ASSERT_EQ(warnings.size(), 1u);
  const std::string& w = warnings[0];
  EXPECT_EQ(w.rfind("infer: warning: the test building of seed 5 (scope ", 0), 0u) << w;
  EXPECT_NE(w.find(" x 80.00 x 80.00 m) stops at a limit: more than 1000000 terminals in one derivation; the largest "
                   "example has 64 parts"),
            std::string::npos)
      << w;
  EXPECT_NE(w.find("hint: "), std::string::npos) << w;
  EXPECT_NE(w.find("--scope"), std::string::npos) << w;
}

// A placed part that reaches into its neighbour in some buildings (a
// placed group varied, as CMP facades at a noise level gave): said, with
// how many and the first fault; judged only where the examples are small.
TEST(TestBuildings, BuildingsWithOverlappingPartsAreAWarningSayingHowMany) {
  const Grammar g = parse_grammar(
      "@scope 4, 4, 4\nb --> split(x){ ~1 : S(~rand(1, 1.4), ~1, ~1){ I(wall) } | ~1 : I(door) }\n", "g.grm");
  TestBuildingsOptions options;
  options.example_parts = 2;
  const std::vector<std::string> warnings = derive_test_buildings(g, options);
  ASSERT_EQ(warnings.size(), 1u);
  const std::string& w = warnings[0];
  EXPECT_EQ(w.rfind("infer: warning: ", 0), 0u) << w;
  EXPECT_NE(w.find(" of 8 test buildings have overlapping parts or parts outside their plot (seed "), std::string::npos)
      << w;
  EXPECT_NE(w.find("overlaps"), std::string::npos) << w;
  options.example_parts = kJudgedParts + 1;
  EXPECT_TRUE(derive_test_buildings(g, options).empty());
}

TEST(TestBuildings, AnyOtherFailureIsThrown) {
  const Grammar g = parse_grammar("@scope 4, 4, 4\nb --> split(x){ 1 / 0 : I(brick) | ~1 : I(wall) }\n", "g.grm");
  try {
    derive_test_buildings(g, {});
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Input) << e.what();
  }
}

}  // namespace
}  // namespace vern
