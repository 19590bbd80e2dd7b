// Tiers set in step by step, read as nesting (inset_runs.hpp).
#include "inverse/merge/inset_runs.hpp"

#include <gtest/gtest.h>

#include "forward/derive.hpp"
#include "graph/nodes_below.hpp"
#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "inverse/check/check.hpp"
#include "inverse/infer.hpp"
#include "support/example_helpers.hpp"
#include "support/one_line.hpp"

namespace vern {
namespace {

// A grammar's text on one line (support/one_line.hpp).
constexpr auto flat = test::one_line;

// The inset of m on both ends of x and y around what, on a scope w x d.
std::string inset(double m, double w, double d, const std::string& what) {
  auto n = [](double v) { return std::to_string(v); };
  return "split(x){ ~" + n(m) + " : nil | ~" + n(w - 2 * m) + " : split(y){ ~" + n(m) + " : nil | ~" + n(d - 2 * m) +
         " : " + what + " | ~" + n(m) + " : nil } | ~" + n(m) + " : nil }";
}

TEST(InsetRuns, DrumsSetInStepByStepAreOneInsideTheOther) {
  // A body, a drum, drums set in 0.5, 1 and 1.5 m, all on a 10 x 8 plot.
  const std::string stack = "a --> split(z){ ~6 : I(body) | ~1 : I(drum) | ~1 : " + inset(0.5, 10, 8, "I(drum)") +
                            " | ~1 : " + inset(1, 10, 8, "I(drum)") + " | ~1 : " + inset(1.5, 10, 8, "I(roof)") + " }\n";
  Grammar g = parse_grammar(stack);
  const NodeId before = g.rules[0].body;
  const NodeId nested = nest_inset_runs(g, before, 1e-6);
  const std::string out = flat(write_operation(g, nested, {}));
  // The body, then one part for the whole stack: a drum under one inset
  // of 0.5 m holding the rest, and so on.
  const auto* s = std::get_if<Split>(&g.op(nested));
  ASSERT_NE(s, nullptr) << out;
  ASSERT_EQ(s->parts.size(), 2u) << out;
  EXPECT_EQ(s->parts[1].size.value.literal(), 4.0) << out;
  EXPECT_NE(out.find("~1 : I(drum) | ~3 : split(x){ ~0.5 : nil | ~9 : split(y){ ~0.5 : nil | ~7 : split(z){ ~1 : "
                     "I(drum) | ~2 : split(x){ ~0.5 : nil | ~8 : split(y){"),
            std::string::npos)
      << out;
  // The same building: every part where it was.
  DeriveOptions o;
  o.size = glm::dvec3{10, 8, 10};
  g.rules[0].body = before;
  const auto flat_parts = test::derived_parts(derive(g, o));
  g.rules[0].body = nested;
  const auto nested_parts = test::derived_parts(derive(g, o));
  EXPECT_TRUE(check_example(g, flat_parts, {10, 8, 10}).derivable);
  ASSERT_EQ(nested_parts.size(), flat_parts.size());
}

TEST(InsetRuns, MarginsThatDoNotStepAreLeftAlone) {
  const std::string text = "a --> split(z){ ~1 : " + inset(0.5, 10, 8, "I(drum)") + " | ~1 : " +
                           inset(0.8, 10, 8, "I(roof)") + " }\n";
  Grammar g = parse_grammar(text);
  EXPECT_EQ(nest_inset_runs(g, g.rules[0].body, 1e-6), g.rules[0].body);
}

TEST(InsetRuns, ACapSetInAllRoundOnOneTierIsAStackOfOneLevel) {
  // Storeys, a band, a drum and a cap set in 1 m all round on the drum:
  // the drum and its cap are one part, as a stack of more tiers is (a
  // drum under an inset holding the rest), so that a front with two
  // tiers and one with three hold the same thing above their band.
  const std::string tiers = "a --> split(z){ ~4 : I(ground) | ~3 : I(storey) | ~3 : I(storey) | ~0.5 : I(band) | ~2 : "
                            "I(drum) | ~2 : " + inset(1, 10, 8, "I(hip)") + " }\n";
  Grammar g = parse_grammar(tiers);
  const NodeId nested = nest_inset_runs(g, g.rules[0].body, 1e-6);
  const std::string out = flat(write_operation(g, nested, {}));
  const auto* s = std::get_if<Split>(&g.op(nested));
  ASSERT_NE(s, nullptr) << out;
  ASSERT_EQ(s->parts.size(), 5u) << out;
  EXPECT_EQ(s->parts[4].size.value.literal(), 4.0) << out;
  EXPECT_NE(out.find("~4 : split(z){ ~2 : I(drum) | ~2 : split(x){ ~1 : nil"), std::string::npos) << out;
  // Storeys under a roof set in from their eaves stay storeys; a roof
  // centred along one axis only is no tier.
  for (const std::string& text : std::vector<std::string>
       {"a --> split(z){ ~4 : I(ground) | ~3 : I(storey) | ~3 : I(storey) | ~2 : " + inset(1, 10, 8, "I(hip)") + " }\n",
        "a --> split(z){ ~4 : I(ground) | ~0.5 : I(band) | ~2 : split(x){ ~3 : nil | ~4 : I(roof) | ~3 : nil } }\n"}) {
    Grammar other = parse_grammar(text);
    EXPECT_EQ(nest_inset_runs(other, other.rules[0].body, 1e-6), other.rules[0].body) << text;
  }
}

TEST(InsetRuns, APagodaOfTwoToFiveTiersInfersAsOneRecursion) {
  // Each tier set in 0.7 m: in every example a stack along z whose k-th
  // drum is set in k times 0.7 m. Read flat, each tier count was an
  // alternative of its own (precision 0 on such styles).
  const Grammar source = parse_grammar(R"(
@start site
@scope rand(12, 20), rand(12, 20), rand(14, 24)
site --> split(z){ ~2 : I(body) | ~1 : pagoda(randint(2, 5)) }
pagoda(n) : n > 1 --> split(z){ ~1 : I(drum) | ~(n - 1) : split(x){ 0.7 : nil | ~1 : split(y){ 0.7 : nil | ~1 : pagoda(n - 1) | 0.7 : nil } | 0.7 : nil } }
pagoda(n) : n <= 1 --> I(roof)
)",
                                       "pagoda.grm");
  const std::vector<Example> examples = test::derived_examples(source, 10);
  const Inference inferred = infer(examples, {});
  const Grammar& g = inferred.grammar;
  const std::string text = write_grammar(g);
  // A rule that calls itself, its margin 0.7 m.
  bool recursive = false;
  for (std::size_t r = 0; r < g.rules.size(); ++r)
    for (const NodeId n : nodes_below(g, g.rules[r].body))
      if (const auto* call = std::get_if<Call>(&g.op(n)); call && call->rule == r) recursive = true;
  EXPECT_TRUE(recursive) << text;
  EXPECT_NE(text.find("0.7 : nil"), std::string::npos) << text;
  for (const Example& e : examples) {
    const CheckResult c = check_example(g, e.boxes, example_size(e));
    EXPECT_TRUE(c.derivable) << c.mismatch << "\n" << text;
  }
}

}  // namespace
}  // namespace vern
