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

// Whether every run of storeys in g is one repeat of one tile size (no
// repeatN along z); else why not, with the grammar.
::testing::AssertionResult one_storey_tile(const Grammar& g) {
  std::set<double> tiles;
  std::size_t counted = 0;
  for (const NodeId n : nodes_of_rules(g)) {
    if (const auto* r = std::get_if<Repeat>(&g.op(n)); r && r->axis.literal_axis() == 2)
      tiles.insert(r->size.literal().value_or(-1));
    if (const auto* r = std::get_if<RepeatN>(&g.op(n)); r && r->axis.literal_axis() == 2) ++counted;
  }
  if (tiles.size() == 1 && counted == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << tiles.size() << " storey tile sizes and " << counted
                                       << " runs of a fixed count:\n"
                                       << write_grammar(g);
}

// Inferred from 30 of the source's buildings: one storey tile, and 40
// variants the source's own.
::testing::AssertionResult storeys_follow_the_height(const char* text, const std::string& name) {
  const Grammar source = parse_grammar(text, name);
  const Inference inferred = infer(test::derived_examples(source, 30), {});
  if (auto one = one_storey_tile(inferred.grammar); !one) return one;
  return test::source_derives_variants(source, inferred.grammar, 101, 140);
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

// Storeys each drawing where their accent bay stands: the houses of three
// storeys are one rule (a repeat of any storey, or of one holding its
// accent further along, as the examples show them), the houses of two a
// pair beside it. The rule's body is rewritten: one tile, 3.1 m, for
// every house. (A random style, evaluate --random-styles 300 --seed 777,
// style 153.)
TEST(RepeatAlternatives, StoreysInARuleOfTheirOwnShareTheTileOfTheOthers) {
  const Grammar source = parse_grammar(R"(
@start lot
@scope rand(24.5, 34.5), rand(15.5, 24.5), rand(6.5, 11)
lot --> split(y){ ~rand(0.65, 1.1) : house | ~1 : split(x){ ~0.45 : wing | ~1 : nil } }
house --> split(z){ ~1 : repeat(z, 3.1){ upper } | ~tnormal(0.4, 0.03, 0.35, 0.45) : cap }
upper --> sequence(randint(0, 3))
sequence(k) --> split(x){ 4.2 * k : repeatN(x, k){ bay } | 4.2 : accent | ~1 : repeat(x, 4.2){ bay } }
bay --> split(x){ ~1 : I(wall) | ~rand(1.2, 2.1) : split(z){ ~1 : I(wall) | ~2 : I(casement) | ~0.5 : I(wall) } | ~1 : I(wall) }
accent --> split(x){ ~1 : I(wall) | ~rand(1.2, 2.1) : split(z){ ~1 : I(loggia) | ~2 : I(casement) } | ~1 : I(wall) }
cap --> I(roof) : 2
cap --> I(hip) : 1
wing --> split(z){ ~2.6 : repeat(y, 4.8){ wingBay } | ~1 : annexRoof }
wingBay --> split(y){ ~1 : I(masonry) | ~1.1 : I(casement) | ~1 : I(masonry) }
annexRoof --> I(hip)
)",
                                       "accents.grm");
  const Inference inferred = infer(test::derived_examples(source, 30), {});
  EXPECT_TRUE(one_storey_tile(inferred.grammar));
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
