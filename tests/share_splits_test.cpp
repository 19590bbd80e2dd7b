// A split of two relative parts that both draw becomes one draw and the
// rest, and every example it derived before it still derives.
#include "inverse/share_splits.hpp"

#include <gtest/gtest.h>

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

std::vector<Example> examples_of(const Grammar& g) {
  std::vector<Example> out;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    DeriveOptions o;
    o.seed = seed;
    out.push_back(test::example_of(test::derived_parts(derive(g, o))));
  }
  return out;
}

TEST(ShareSplits, TwoDrawnSharesBecomeOneDrawAndTheRest) {
  Grammar g = parse_grammar(kColumns, "columns.grm");
  const std::vector<Example> examples = examples_of(g);
  std::vector<CheckResult> results;
  for (const Example& e : examples) results.push_back(check_example(g, e.boxes, kPlot));
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
  std::vector<CheckResult> results;
  for (const Example& e : examples) results.push_back(check_example(g, e.boxes, kPlot));
  for (const CheckResult& r : results) ASSERT_TRUE(r.derivable) << r.mismatch;

  EXPECT_EQ(share_splits(g, results, {1e-6, false}), 1u);
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
  results.clear();
  for (const Example& e : examples_of(apart)) results.push_back(check_example(apart, e.boxes, kPlot));
  EXPECT_EQ(share_splits(apart, results, {1e-6, false}), 0u) << write_grammar(apart);
}

}  // namespace
}  // namespace vern
