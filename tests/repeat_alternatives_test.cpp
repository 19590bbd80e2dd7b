// Alternatives of one choice that are runs of one tile along one axis
// (repeat_alternatives.hpp): storeys seen two to a house in most examples
// and three in a few are one repeat whose count follows the height.
#include "inverse/sizes/repeat_alternatives.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "graph/nodes_below.hpp"
#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "inverse/infer.hpp"
#include "support/example_helpers.hpp"

namespace vern {
namespace {

// Storeys of a 2.9 m tile under a roof that takes a share of the height:
// on plots 6 to 9 m high, two storeys below 8.4 m and three above. Each
// window row draws its own window width, so no two storeys of one house
// are alike: the two of most houses are a pair only once examples merge.
const char* kStoreys = R"(
@start plot
@scope rand(26, 35.5), rand(7, 13), rand(6, 9)
plot --> split(z){ ~1 : repeat(z, 2.9){ floor } | ~0.45 : I(roof) }
floor --> repeat(x, 3.6){ opening }
opening --> split(x){ ~1 : I(masonry) | ~tnormal(2.03, 0.09, 1.85, 2.2) : split(z){ ~1 : I(masonry) | ~2 : I(window) | ~0.5 : I(masonry) } | ~1 : I(masonry) }
)";

// Inferred from 30 of the source's buildings: every run of storeys one
// repeat of one tile size (no repeatN along z), and 40 variants the
// source's own.
::testing::AssertionResult storeys_follow_the_height(const char* text, const std::string& name) {
  const Grammar source = parse_grammar(text, name);
  const Inference inferred = infer(test::derived_examples(source, 30), {});
  const Grammar& g = inferred.grammar;
  std::set<double> tiles;
  std::size_t counted = 0;
  for (const NodeId n : nodes_of_rules(g)) {
    if (const auto* r = std::get_if<Repeat>(&g.op(n)); r && r->axis.literal_axis() == 2)
      tiles.insert(r->size.literal().value_or(-1));
    if (const auto* r = std::get_if<RepeatN>(&g.op(n)); r && r->axis.literal_axis() == 2) ++counted;
  }
  if (tiles.size() != 1 || counted != 0)
    return ::testing::AssertionFailure() << tiles.size() << " storey tile sizes and " << counted
                                         << " runs of a fixed count:\n"
                                         << write_grammar(g);
  return test::source_derives_variants(source, g, 101, 140);
}

TEST(RepeatAlternatives, StoreysSeenTwoAndThreeToAHouseAreOneRepeatThatFollowsTheHeight) {
  EXPECT_TRUE(storeys_follow_the_height(kStoreys, "storeys.grm"));
}

// The same storeys, each house's windows with a railing below or not, as
// one choice kept for the building: alternatives of two kinds of storey,
// each seen two and three to a house.
const char* kKeptStoreys = R"(
@start plot
@scope rand(26, 35.5), rand(7, 13), rand(6, 9)
plot --> house(randint(0, 1))
house(b) --> split(z){ ~1 : repeat(z, 2.9){ floor(b) } | ~0.45 : I(roof) }
floor(b) --> repeat(x, 3.6){ opening(b) }
opening(b) : b == 0 --> split(x){ ~1 : I(masonry) | 2 : split(z){ ~1 : I(masonry) | ~2 : I(window) | ~0.5 : I(masonry) } | ~1 : I(masonry) }
opening(b) : b == 1 --> split(x){ ~1 : I(masonry) | 2 : split(z){ ~1 : I(railing) | ~2 : I(window) } | ~1 : I(masonry) }
)";

TEST(RepeatAlternatives, StoreysOfTwoKindsShareOneTile) {
  EXPECT_TRUE(storeys_follow_the_height(kKeptStoreys, "kept.grm"));
}

// Two or three storeys whatever the height: no tile gives those counts,
// so the alternatives keep their counts.
TEST(RepeatAlternatives, CountsThatDoNotFollowTheHeightStayCounts) {
  const Grammar source = parse_grammar(R"(
@start plot
@scope rand(20, 30), 10, rand(6, 9)
plot --> split(z){ ~1 : repeatN(z, randint(2, 3)){ floor } | ~0.45 : I(roof) }
floor --> repeat(x, 3.6){ split(x){ ~1 : I(wall) | 2 : I(window) | ~1 : I(wall) } }
)",
                                       "counts.grm");
  const Inference inferred = infer(test::derived_examples(source, 30), {});
  EXPECT_TRUE(test::source_derives_variants(source, inferred.grammar, 101, 140));
}

}  // namespace
}  // namespace vern
