// A plot whose size follows a count the grammar draws becomes a line in
// that count, drawn once (scope_by_count.hpp).
#include "inverse/sizes/scope_by_count.hpp"

#include <gtest/gtest.h>

#include <functional>

#include "forward/derive.hpp"
#include "graph/parser.hpp"
#include "inverse/check/check.hpp"
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

TEST(ScopeByCount, APagodaAsTallAsItsTiersReadsItsTierCountOffItsPlot) {
  const Grammar source = parse_grammar(kPagoda);
  const std::vector<Example> examples = derived_examples(source, 10);
  const Inference inferred = infer(examples, {});
  const std::string text = write_grammar(inferred.grammar);
  EXPECT_NE(text.find(", 3 * randint(3, 5) + 2.5\n"), std::string::npos) << text;
  EXPECT_NE(text.find("(round((size(z) - 2.5) / 3))"), std::string::npos) << text;
  // On its own plots (generate without --scope): every variant a pagoda of
  // the source's, where a height drawn apart from the count gave one in
  // four (tiers stretched or squeezed to the plot).
  EXPECT_TRUE(source_derives_variants(source, inferred.grammar, 1001, 1040));
  // And on the examples' plots, as precision is measured: the count each
  // plot's height holds, where a count drawn apart gave one in three.
  for (std::size_t i = 0; i < examples.size(); ++i) {
    DeriveOptions o;
    o.seed = 1001 + i;
    o.size = example_size(examples[i]);
    const Example variant = example_of(derived_parts(derive(inferred.grammar, o)));
    EXPECT_TRUE(check_example(source, variant.boxes, example_size(variant)).derivable) << "plot of example " << i;
  }
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

// Examples of the grammar `rules` with its count randint(2, 4) set to 2,
// 3, 4 and 3, on plots height(n) high.
std::vector<Example> count_examples(const std::string& rules, const std::function<double(int)>& height) {
  std::vector<Example> out;
  for (const int n : {2, 3, 4, 3}) {
    std::string text = "@scope 10, 10, " + std::to_string(height(n)) + "\n" + rules;
    text.replace(text.find("randint(2, 4)"), 13, std::to_string(n));
    out.push_back(example_of(derived_parts(parse_grammar(text), 1)));
  }
  return out;
}

// g with its plot tied to its count by the examples, as written; g derives
// every example before and after, and one axis is tied.
std::string tied(Grammar& g, const std::vector<Example>& examples) {
  EXPECT_TRUE(derives_every_example(g, examples));
  EXPECT_EQ(tie_scope_to_counts(g, examples, {}), 1u);
  EXPECT_TRUE(derives_every_example(g, examples));
  return write_grammar(g);
}

TEST(ScopeByCount, APlotThatFollowsTheCountIsALineInItAndStillDerivesEveryExample) {
  // Tiers of 3 m under a roof of 2 m: plots 3n + 2 high. The call stands
  // on the plot: the count is read off it.
  const std::string rules = std::string("building --> tiers(randint(2, 4))\n") + kMetreTiers;
  Grammar g = parse_grammar("@scope 10, 10, choice(8, 11, 14)\n" + rules);
  const std::string text = tied(g, count_examples(rules, [](int n) { return 3 * n + 2; }));
  EXPECT_NE(text.find("@scope 10, 10, 3 * randint(2, 4) + 2\n"), std::string::npos) << text;
  EXPECT_NE(text.find("building --> tiers(round((size(z) - 2) / 3))"), std::string::npos) << text;
}

TEST(ScopeByCount, ACountOnABaseOfFixedHeightIsReadOffWhatTheBaseLeaves) {
  // The tiers on a podium 4 m high: the call's scope is the plot less
  // 4 m, so the count is read off it as 3n + 2 of what is left.
  const std::string rules =
      std::string("building --> split(z){ 4 : I(podium) | ~1 : tiers(randint(2, 4)) }\n") + kMetreTiers;
  Grammar g = parse_grammar("@scope 10, 10, choice(12, 15, 18)\n" + rules);
  const std::string text = tied(g, count_examples(rules, [](int n) { return 3 * n + 2 + 4; }));
  EXPECT_NE(text.find("@scope 10, 10, 3 * randint(2, 4) + 6\n"), std::string::npos) << text;
  EXPECT_NE(text.find("~1 : tiers(round((size(z) - 2) / 3))"), std::string::npos) << text;
}

TEST(ScopeByCount, ACountOnAShareOfThePlotIsAConstantThePlotFollows) {
  // The tiers on three quarters of the plot, a podium on the rest: what
  // the call stands on is no fixed number of metres less than the plot,
  // so the count is drawn once, as a constant, and the plot is the line
  // in it.
  const std::string rules =
      std::string("building --> split(z){ ~1 : I(podium) | ~3 : tiers(randint(2, 4)) }\n") + kMetreTiers;
  Grammar g = parse_grammar("@scope 10, 10, rand(10, 20)\n" + rules);
  const std::string text = tied(g, count_examples(rules, [](int n) { return (3 * n + 2) * 4.0 / 3; }));
  EXPECT_NE(text.find("tiersN = randint(2, 4)\n@scope 10, 10, 4 * tiersN + 2.666667\n"), std::string::npos) << text;
  EXPECT_NE(text.find("~3 : tiers(tiersN)"), std::string::npos) << text;
}

}  // namespace
}  // namespace vern
