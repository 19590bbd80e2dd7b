// A plot whose size follows a count the grammar draws becomes a line in
// that count, drawn once (scope_by_count.hpp).
#include "inverse/sizes/scope_by_count.hpp"

#include <gtest/gtest.h>

#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "inverse/infer.hpp"
#include "support/example_helpers.hpp"

namespace vern {
namespace {

using test::derived_examples;
using test::derived_parts;
using test::derives_every_example;
using test::example_of;
using test::source_derives_variants;

// A pagoda of three to five 3 m tiers, each set in by 1.2 m, under a roof
// 2.5 m high, on a plot with air above: each example is as tall as its
// tiers make it.
const char* const kPagoda =
    "@start pagoda\n"
    "@scope rand(14, 20), rand(14, 20), 30\n"
    "pagoda --> tiers(randint(3, 5))\n"
    "tiers(n) : n > 0 --> split(z){ 3 : I(rect) | ~1 : split(x){ 1.2 : nil | ~1 : split(y){ 1.2 : nil | ~1 : "
    "tiers(n - 1) | 1.2 : nil } | 1.2 : nil } }\n"
    "tiers(n) : n <= 0 --> split(z){ 2.5 : I(roof) | ~1 : nil }\n";

TEST(ScopeByCount, APagodaAsTallAsItsTiersDrawsItsHeightFromItsTierCount) {
  const Grammar source = parse_grammar(kPagoda);
  const Inference inferred = infer(derived_examples(source, 10), {});
  const std::string text = write_grammar(inferred.grammar);
  EXPECT_NE(text.find(" = randint(3, 5)\n"), std::string::npos) << text;
  EXPECT_NE(text.find("3 * "), std::string::npos) << text;
  // On its own plots (generate without --scope): every variant a pagoda of
  // the source's, where a height drawn apart from the count gave one in
  // three (tiers stretched or squeezed to the plot).
  EXPECT_TRUE(source_derives_variants(source, inferred.grammar, 1001, 1040));
}

// Tiers set in by 1 m, as shares of the plot (kShareTiers) or 3 m each
// (kMetreTiers), and a building of n of them on a plot of that height.
const char* const kShareTiers =
    "tiers(n) : n <= 0 --> I(roof)\n"
    "tiers(n) : n > 0 --> split(z){ ~1 : I(rect) | ~n : split(x){ 1 : nil | ~1 : tiers(n - 1) | 1 : nil } }\n";
const char* const kMetreTiers =
    "tiers(n) : n <= 0 --> I(roof)\n"
    "tiers(n) : n > 0 --> split(z){ 3 : I(rect) | ~1 : split(x){ 1 : nil | ~1 : tiers(n - 1) | 1 : nil } }\n";

Example tiers_example(const char* tiers, int n, double height) {
  const Grammar g = parse_grammar("@scope 10, 10, " + std::to_string(height) + "\nbuilding --> tiers(" +
                                  std::to_string(n) + ")\n" + tiers);
  return example_of(derived_parts(g, 1));
}

TEST(ScopeByCount, AHeightThatDoesNotFollowTheCountStaysItsOwn) {
  // Tiers as shares of a plot drawn on its own: two examples of one count
  // differ in height, so the height is no line in the count.
  Grammar g = parse_grammar(std::string("@scope 10, 10, rand(10, 20)\nbuilding --> tiers(randint(2, 4))\n") +
                            kShareTiers);
  const std::vector<Example> examples{tiers_example(kShareTiers, 2, 12), tiers_example(kShareTiers, 2, 15),
                                      tiers_example(kShareTiers, 3, 14), tiers_example(kShareTiers, 4, 19)};
  ASSERT_TRUE(derives_every_example(g, examples));
  const std::string before = write_grammar(g);
  EXPECT_EQ(tie_scope_to_counts(g, examples, {}), 0u);
  EXPECT_EQ(write_grammar(g), before);
}

TEST(ScopeByCount, APlotThatFollowsTheCountIsALineInItAndStillDerivesEveryExample) {
  // Tiers of 3 m under a roof of 2 m: plots 3n + 2 high.
  Grammar g = parse_grammar(std::string("@scope 10, 10, choice(8, 11, 14)\nbuilding --> tiers(randint(2, 4))\n") +
                            kMetreTiers);
  std::vector<Example> examples;
  for (const int n : {2, 3, 4, 3}) examples.push_back(tiers_example(kMetreTiers, n, 3 * n + 2));
  ASSERT_TRUE(derives_every_example(g, examples));
  EXPECT_EQ(tie_scope_to_counts(g, examples, {}), 1u);
  const std::string text = write_grammar(g);
  EXPECT_NE(text.find("tiersN = randint(2, 4)\n@scope 10, 10, 3 * tiersN + 2\n"), std::string::npos) << text;
  EXPECT_NE(text.find("building --> tiers(tiersN)"), std::string::npos) << text;
  EXPECT_TRUE(derives_every_example(g, examples));
}

}  // namespace
}  // namespace vern
