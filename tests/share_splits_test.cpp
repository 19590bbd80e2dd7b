// A split of two relative parts that both draw becomes one draw and the
// rest, and every example it derived before it still derives.
#include "inverse/sizes/share_splits.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "forward/derive.hpp"
#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "support/example_helpers.hpp"

namespace vern {
namespace {

constexpr const char* kColumns = R"(
@scope 12, 8, 10
b --> split(x){ ~1 : col | ~1 : col }
col --> split(z){ ~rand(1, 9) : I(rect) | ~rand(1, 9) : nil }
)";

// The plot: the examples' own extent ends at their tallest box.
constexpr glm::dvec3 kPlot{12, 8, 10};

std::vector<Example> examples_of(const Grammar& g) { return test::derived_examples(g, 6); }

// Each example checked against g on the plot.
std::vector<CheckResult> checked(const Grammar& g, const std::vector<Example>& examples) {
  std::vector<CheckResult> out;
  for (const Example& e : examples) out.push_back(check_example(g, e.boxes, kPlot));
  return out;
}

// share_splits on g, given the examples it derives as they checked.
std::size_t shared_splits(Grammar& g, const std::vector<Example>& examples) {
  const std::vector<CheckResult> results = checked(g, examples);
  for (const CheckResult& r : results) EXPECT_TRUE(r.derivable) << r.mismatch;
  return share_splits(g, results, {1e-6, false});
}

TEST(ShareSplits, TwoDrawnSharesBecomeOneDrawAndTheRest) {
  Grammar g = parse_grammar(kColumns, "columns.grm");
  const std::vector<Example> examples = examples_of(g);
  const std::vector<CheckResult> results = checked(g, examples);
  for (const CheckResult& r : results) ASSERT_TRUE(r.derivable) << r.mismatch;

  EXPECT_EQ(share_splits(g, results, {1e-6, false}), 1u);
  const auto col = g.find_rule("col");
  ASSERT_TRUE(col);
  EXPECT_EQ(g.rules[*col].params, std::vector<std::string>{"s1"}) << write_grammar(g);
  const auto& split = std::get<Split>(g.op(g.rules[*col].body));
  EXPECT_FALSE(split.parts[0].size.value.draws_random());
  EXPECT_FALSE(split.parts[1].size.value.draws_random());
  // The callers draw the share: two calls, one draw each.
  const auto& row = std::get<Split>(g.op(g.rules[g.start_rule].body));
  for (const SplitPart& p : row.parts) {
    const auto& call = std::get<Call>(g.op(p.child));
    ASSERT_EQ(call.args.size(), 1u);
    EXPECT_TRUE(call.args[0].draws_random());
  }
  for (const Example& e : examples) {
    const CheckResult r = check_example(g, e.boxes, kPlot);
    EXPECT_TRUE(r.derivable) << r.mismatch << "\n" << write_grammar(g);
  }
  // Written and read back, it is the same grammar.
  EXPECT_EQ(write_grammar(parse_grammar(write_grammar(g), "again.grm")), write_grammar(g));
}

TEST(ShareSplits, ASplitWithAFixedShareIsLeftAsItIs) {
  // One share fixed (~1): the other's draw is the only one already.
  Grammar g = parse_grammar(R"(
@scope 12, 8, 10
b --> split(x){ ~1 : col | ~1 : col }
col --> split(z){ ~rand(1, 9) : I(rect) | ~1 : nil }
)",
                            "fixed.grm");
  std::vector<CheckResult> results;
  for (const Example& e : examples_of(g)) results.push_back(check_example(g, e.boxes, kPlot));
  const std::string before = write_grammar(g);
  EXPECT_EQ(share_splits(g, results, {1e-6, false}), 0u);
  EXPECT_EQ(write_grammar(g), before);
}

// A bay of two windows and a mullion between piers, as merging writes a
// row of them from bays of several widths: the windows and the mullion
// are shares written as numbers, each pier draws. The examples' piers are
// equal in every bay (the source draws one width for both).
constexpr const char* kPiersOfOneWidth = R"(
@scope 12, 8, 10
b --> repeat(x, 4){ bay(rand(0.5, 1.5)) }
bay(p) --> split(x){ ~p : I(pier) | ~1 : I(window) | ~0.4 : I(mullion) | ~1 : I(window) | ~p : I(pier) }
)";
constexpr const char* kPiersAsMerged = R"(
@scope 12, 8, 10
b --> repeat(x, 4){ split(x){
    ~rand(0.5, 1.5) : I(pier) | ~1 : I(window) | ~0.4 : I(mullion) | ~1 : I(window) | ~rand(0.5, 1.5) : I(pier) } }
)";

TEST(ShareSplits, DrawnSharesBesideNumbersBecomeOneDrawInTheNumbersScale) {
  const std::vector<Example> examples = examples_of(parse_grammar(kPiersOfOneWidth, "source.grm"));
  Grammar g = parse_grammar(kPiersAsMerged, "merged.grm");
  EXPECT_EQ(shared_splits(g, examples), 1u);
  // One rule of one parameter: both piers are s1, the numbers stay.
  const Rule* bay = nullptr;
  for (const Rule& r : g.rules)
    if (r.params == std::vector<std::string>{"s1"}) bay = &r;
  ASSERT_NE(bay, nullptr) << write_grammar(g);
  const auto& split = std::get<Split>(g.op(bay->body));
  ASSERT_EQ(split.parts.size(), 5u);
  EXPECT_EQ(split.parts[0].size.value, split.parts[4].size.value) << write_grammar(g);
  EXPECT_TRUE(split.parts[0].size.value.uses_params());
  for (const std::size_t i : {1, 3}) EXPECT_NEAR(split.parts[i].size.value.literal().value_or(0), 1, 1e-6);
  EXPECT_NEAR(split.parts[2].size.value.literal().value_or(0), 0.4, 1e-6);
  for (const Example& e : examples) {
    const CheckResult r = check_example(g, e.boxes, kPlot);
    EXPECT_TRUE(r.derivable) << r.mismatch << "\n" << write_grammar(g);
  }
  // Piers drawn apart in the examples stay apart.
  Grammar apart = parse_grammar(kPiersAsMerged, "merged.grm");
  EXPECT_EQ(share_splits(apart, checked(apart, examples_of(apart)), {1e-6, false}), 0u) << write_grammar(apart);
}

// A pair of casements and their mullion, 1 to 1.3 m in all, in one
// proportion, as merging writes a row of them from bays of several
// widths: three lengths in metres, each drawn apart.
constexpr const char* kPairOfOneWidth = R"(
@scope 12, 8, 10
b --> repeat(x, 3){ split(x){ ~1 : I(wall) | rand(1, 1.3) : pair | ~1 : I(wall) } }
pair --> split(x){ ~1 : I(casement) | ~0.4 : I(mullion) | ~1 : I(casement) }
)";
constexpr const char* kPairAsMerged = R"(
@scope 12, 8, 10
b --> repeat(x, 3){ split(x){
    ~1 : I(wall) | rand(0.4, 0.55) : I(casement) | rand(0.16, 0.22) : I(mullion) | rand(0.4, 0.55) : I(casement) |
    ~1 : I(wall) } }
)";

TEST(ShareSplits, LengthsInMetresInOneProportionBecomeOneDraw) {
  const std::vector<Example> examples = examples_of(parse_grammar(kPairOfOneWidth, "source.grm"));
  Grammar g = parse_grammar(kPairAsMerged, "merged.grm");
  EXPECT_EQ(shared_splits(g, examples), 1u);
  // Over 100 variants, every mullion is 0.4 of its casements, and both
  // casements of a bay are one width.
  double worst = 0;
  std::size_t pairs = 0;
  for (std::uint64_t seed = 1001; seed <= 1100; ++seed) {
    std::vector<LabelledBox> parts = test::derived_parts(g, seed);
    std::ranges::sort(parts, {}, [](const LabelledBox& b) { return b.min.x; });
    for (std::size_t i = 0; i + 2 < parts.size(); ++i) {
      if (parts[i].label != "casement" || parts[i + 1].label != "mullion") continue;
      const double left = parts[i].max.x - parts[i].min.x, mullion = parts[i + 1].max.x - parts[i + 1].min.x,
                   right = parts[i + 2].max.x - parts[i + 2].min.x;
      worst = std::max({worst, std::abs(mullion - 0.4 * left), std::abs(right - left)});
      ++pairs;
    }
  }
  EXPECT_GE(pairs, 100u);
  EXPECT_LT(worst, 1e-6) << write_grammar(g);
  for (const Example& e : examples) {
    const CheckResult r = check_example(g, e.boxes, kPlot);
    EXPECT_TRUE(r.derivable) << r.mismatch << "\n" << write_grammar(g);
  }
}

TEST(ShareSplits, ASplitInACountedRecursionTakesTheCountOn) {
  // A tower of n tiers, each tier's share of its storey and the rest
  // drawn: the split holds the call tower(n - 1), so the rule it becomes
  // takes n on before its share, tier(n, s1). Given only the share, n
  // read the share (tower(s1 - 1)) and no example derived any more, so
  // nothing was shared.
  Grammar g = parse_grammar(R"(
@scope 12, 8, 10
b --> tower(randint(1, 3))
tower(n) : n <= 0 --> I(roof)
tower(n) : n > 0 --> split(z){ ~rand(1, 3) : I(rect) | ~rand(4, 6) : tower(n - 1) }
)",
                            "tower.grm");
  const std::vector<Example> examples = examples_of(g);
  EXPECT_EQ(shared_splits(g, examples), 1u);
  const auto tier = std::ranges::find_if(g.rules, [](const Rule& r) { return r.params.size() == 2; });
  ASSERT_NE(tier, g.rules.end()) << write_grammar(g);
  EXPECT_EQ(tier->params, (std::vector<std::string>{"n", "s1"})) << write_grammar(g);
  for (const CheckResult& r : checked(g, examples)) EXPECT_TRUE(r.derivable) << r.mismatch << "\n" << write_grammar(g);
}

TEST(ShareSplits, PartsInMetresThatFillTheirSplitInOneProportionAreShares) {
  // A row of a tenth of its width, eight tenths and a tenth, as merging
  // may write it (a tier set in on each side): three lengths in metres,
  // drawn. Read as one draw, they were
  // s1 : 8 * s1 : s1, with s1 drawn apart from the width they must fill;
  // they always fill it, so they are shares, and nothing is drawn.
  const Grammar source = parse_grammar(R"(
@scope rand(10, 20), 8, 4
b --> split(x){ ~1 : I(wall) | ~8 : I(rect) | ~1 : I(wall) }
)",
                                       "source.grm");
  Grammar g = parse_grammar(R"(
@scope 15, 8, 4
b --> split(x){ rand(1, 2) : I(wall) | rand(8, 16) : I(rect) | rand(1, 2) : I(wall) }
)",
                            "metres.grm");
  std::vector<CheckResult> results;
  for (const Example& e : test::derived_examples(source, 6)) {
    results.push_back(check_example(g, e.boxes, example_size(e)));
    ASSERT_TRUE(results.back().derivable) << results.back().mismatch;
  }
  EXPECT_EQ(share_splits(g, results, {1e-6, false}), 1u);
  const auto& split = std::get<Split>(g.op(g.rules[g.start_rule].body));
  ASSERT_EQ(split.parts.size(), 3u) << write_grammar(g);
  const std::vector<double> shares{1, 8, 1};
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_TRUE(split.parts[i].size.relative) << write_grammar(g);
    EXPECT_EQ(split.parts[i].size.value.literal(), shares[i]) << write_grammar(g);
  }
}

}  // namespace
}  // namespace vern
