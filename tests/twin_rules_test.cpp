// Subgraphs built alike but for some numbers or an axis become one rule
// with parameters; the grammar still derives exactly what it did.
#include "inverse/merge/twin_rules.hpp"

#include <gtest/gtest.h>

#include <string>

#include "forward/derive.hpp"
#include "graph/description_length.hpp"
#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "inverse/check/check.hpp"
#include "inverse/infer.hpp"
#include "support/example_helpers.hpp"

namespace vern {
namespace {

Derivation derive_seed(const Grammar& g, std::uint64_t seed) {
  DeriveOptions o;
  o.seed = seed;
  return derive(g, o);
}

// The same terminals in the same order, every coordinate equal: what
// byte-identical output files need.
::testing::AssertionResult same_terminals(const Derivation& a, const Derivation& b) {
  if (a.terminals.size() != b.terminals.size())
    return ::testing::AssertionFailure() << a.terminals.size() << " terminals against " << b.terminals.size();
  for (std::size_t i = 0; i < a.terminals.size(); ++i) {
    const Scope& x = a.terminals[i].scope;
    const Scope& y = b.terminals[i].scope;
    if (a.labels[a.terminals[i].label] != b.labels[b.terminals[i].label] || x.origin != y.origin ||
        x.size != y.size || x.frame != y.frame)
      return ::testing::AssertionFailure() << "terminal " << i << " differs";
  }
  return ::testing::AssertionSuccess();
}

// Joins g's twins and expects every seed to derive what it did.
TwinRules joined_keeping_derivations(Grammar& g) {
  const Grammar before = g;
  const TwinRules out = parameterise_twins(g);
  for (std::uint64_t seed = 1; seed <= 20; ++seed)
    EXPECT_TRUE(same_terminals(derive_seed(before, seed), derive_seed(g, seed))) << "seed " << seed << "\n"
                                                                                  << write_grammar(g);
  return out;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Two wings built alike, one 6 m high and one 4 m: written out in full.
constexpr const char* kTwoWings = R"(
@scope 20, 8, 10
building --> split(x){
    ~1 : split(z){ 6 : split(y){ 0.5 : I(wall) | ~1 : I(window) | 0.5 : I(wall) } | ~1 : I(roof) } |
    2 : I(rect) |
    ~1 : split(z){ 4 : split(y){ 0.5 : I(wall) | ~1 : I(window) | 0.5 : I(wall) } | ~1 : I(roof) } }
)";

TEST(TwinRules, WingsThatDifferInAHeightAreOneRule) {
  Grammar g = parse_grammar(kTwoWings, "wings.grm");
  const std::size_t before = description_length(g).total();
  const TwinRules twins = joined_keeping_derivations(g);
  EXPECT_EQ(twins.rules, 1u);
  EXPECT_EQ(twins.copies, 2u);
  const std::string text = write_grammar(g);
  ASSERT_EQ(g.rules.size(), 2u) << text;
  EXPECT_EQ(g.rules[1].params.size(), 1u) << text;
  EXPECT_EQ(count(text, "I(window)"), 1u) << text;
  EXPECT_NE(text.find("(6)"), std::string::npos) << text;
  EXPECT_NE(text.find("(4)"), std::string::npos) << text;
  EXPECT_LT(description_length(g).total(), before) << text;
}

// The same facade along x in one wing and along y in the other.
constexpr const char* kTwoFacades = R"(
@scope 20, 20, 6
building --> split(y){
    8 : split(x){ 0.5 : I(wall) | ~1 : I(window) | 0.5 : I(wall) | 1 : I(rect) | ~2 : I(door) } |
    ~1 : split(x){ ~1 : nil | 8 : split(y){ 0.5 : I(wall) | ~1 : I(window) | 0.5 : I(wall) | 1 : I(rect) | ~2 : I(door) } } }
)";

TEST(TwinRules, AFacadeAlongEitherAxisIsOneRuleTakingTheAxis) {
  Grammar g = parse_grammar(kTwoFacades, "facades.grm");
  EXPECT_EQ(joined_keeping_derivations(g).rules, 1u);
  const std::string text = write_grammar(g);
  // Named without an axis letter, since the axis is the parameter.
  EXPECT_NE(text.find("wallWindowRectSplit(a1) --> split(a1){"), std::string::npos) << text;
  EXPECT_NE(text.find("wallWindowRectSplit(x)"), std::string::npos) << text;
  EXPECT_NE(text.find("wallWindowRectSplit(y)"), std::string::npos) << text;
}

TEST(TwinRules, ASizeWrittenTwiceAlikeIsOneParameter) {
  // The wall thickness differs between the wings, the same on both sides.
  Grammar g = parse_grammar(R"(
@scope 20, 8, 10
building --> split(x){
    ~1 : split(y){ 0.5 : I(wall) | ~1 : split(z){ ~1 : I(window) | ~1 : I(rect) } | 0.5 : I(wall) } |
    ~1 : split(y){ 0.8 : I(wall) | ~1 : split(z){ ~1 : I(window) | ~1 : I(rect) } | 0.8 : I(wall) } }
)",
                            "walls.grm");
  EXPECT_EQ(joined_keeping_derivations(g).rules, 1u);
  const std::string text = write_grammar(g);
  ASSERT_EQ(g.rules.size(), 2u) << text;
  EXPECT_EQ(g.rules[1].params.size(), 1u) << text;
  EXPECT_EQ(count(text, "v1 : I(wall)"), 2u) << text;
}

TEST(TwinRules, SmallTwinsStayWrittenOut) {
  // A call and its rule would write as much as the two copies.
  Grammar g = parse_grammar(R"(
@scope 10, 8, 10
building --> split(x){ ~1 : split(z){ 3 : I(rect) | ~1 : nil } | ~1 : split(z){ 4 : I(rect) | ~1 : nil } }
)",
                            "small.grm");
  const std::string before = write_grammar(g);
  EXPECT_EQ(parameterise_twins(g).rules, 0u);
  EXPECT_EQ(write_grammar(g), before);
}

TEST(TwinRules, TwinsDifferingInTooManyValuesStayApart) {
  Grammar g = parse_grammar(R"(
@scope 20, 8, 10
building --> split(x){
    ~1 : split(z){ 1 : I(a) | 2 : I(b) | 3 : I(c) | 4 : I(d) | 5 : I(e) | ~1 : split(y){ ~1 : I(f) | ~2 : I(g) } } |
    ~1 : split(z){ 1.5 : I(a) | 2.5 : I(b) | 3.5 : I(c) | 4.5 : I(d) | 5.5 : I(e) | ~1 : split(y){ ~1 : I(f) | ~2 : I(g) } } }
)",
                            "many.grm");
  TwinOptions five;
  five.max_params = 5;
  Grammar allowed = g;
  EXPECT_EQ(parameterise_twins(allowed, five).rules, 1u) << write_grammar(allowed);
  EXPECT_EQ(parameterise_twins(g).rules, 0u) << write_grammar(g);  // 4 by default
}

TEST(TwinRules, PartsReadingAParameterStayApart) {
  Grammar g = parse_grammar(R"(
@scope 20, 8, 10
building --> wings(3)
wings(h) --> split(x){
    ~1 : split(z){ h : split(y){ 0.5 : I(wall) | ~1 : I(window) | 0.5 : I(wall) } | ~1 : I(roof) } |
    ~1 : split(z){ 4 : split(y){ 0.5 : I(wall) | ~1 : I(window) | 0.5 : I(wall) } | ~1 : I(roof) } }
)",
                            "param.grm");
  // The wall splits are one node already; the wings are no twins, as one
  // reads h.
  EXPECT_EQ(parameterise_twins(g).rules, 0u) << write_grammar(g);
}

TEST(TwinRules, ARuleWhoseBodyIsATwinTakesTheParameters) {
  // Each wing is a rule called from two places; the second rule goes.
  Grammar g = parse_grammar(R"(
@scope 40, 8, 10
building --> split(x){ ~1 : high | ~1 : low | ~1 : high | ~1 : low }
high --> split(z){ 6 : split(y){ 0.5 : I(wall) | ~1 : I(window) | 0.5 : I(wall) } | ~1 : I(roof) }
low --> split(z){ 4 : split(y){ 0.5 : I(wall) | ~1 : I(window) | 0.5 : I(wall) } | ~1 : I(roof) }
)",
                            "rules.grm");
  EXPECT_EQ(joined_keeping_derivations(g).rules, 1u);
  const std::string text = write_grammar(g);
  ASSERT_EQ(g.rules.size(), 2u) << text;
  EXPECT_EQ(g.rules[1].label, "high") << text;
  EXPECT_EQ(count(text, "high(6)"), 2u) << text;
  EXPECT_EQ(count(text, "high(4)"), 2u) << text;
}

TEST(TwinRules, TwinsInsideTwinsAreJoinedToo) {
  // The two wings differ in their height and in their window's share;
  // inside each, the two bays differ in the window's share alone.
  Grammar g = parse_grammar(R"(
@scope 20, 8, 10
building --> split(x){
    ~1 : split(z){ 6 : split(y){ ~1 : split(z){ ~1 : I(window) | ~2 : I(rect) } | 0.5 : I(wall) | ~1 : split(z){ ~1 : I(window) | ~3 : I(rect) } } | ~1 : I(roof) } |
    ~1 : split(z){ 4 : split(y){ ~1 : split(z){ ~1 : I(window) | ~2 : I(rect) } | 0.5 : I(wall) | ~1 : split(z){ ~1 : I(window) | ~3 : I(rect) } } | ~1 : I(roof) } }
)",
                            "nested.grm");
  const std::size_t before = description_length(g).total();
  joined_keeping_derivations(g);
  const std::string text = write_grammar(g);
  EXPECT_EQ(count(text, "I(roof)"), 1u) << text;
  EXPECT_LT(description_length(g).total(), before) << text;
}

TEST(TwinRules, RulesReadingTheirParametersAlikeBecomeOneRule) {
  // Two wings inset by a drawn share s1 of two widths (as joint_sizes
  // writes a tier centred on the one below): the same rule but for 8 and 6.
  Grammar g = parse_grammar(R"(
@scope 20, 10, 10
building --> split(x){ ~1 : wingY(rand(0.5, 1)) | ~1 : wingY2(rand(1, 2)) }
wingY(s1) --> split(y){ ~s1 : nil | ~(8 - 2 * s1) : split(z){ ~2 : I(wall) | ~1 : I(roof) } | ~s1 : nil }
wingY2(s1) --> split(y){ ~s1 : nil | ~(6 - 2 * s1) : split(z){ ~2 : I(wall) | ~1 : I(roof) } | ~s1 : nil }
)",
                            "wings.grm");
  const TwinRules twins = joined_keeping_derivations(g);
  EXPECT_EQ(twins.rules, 1u);
  const std::string text = write_grammar(g);
  EXPECT_EQ(g.rules.size(), 2u) << text;
  EXPECT_NE(text.find("wingY(s1, v1) --> split(y){"), std::string::npos) << text;
  EXPECT_NE(text.find("~(v1 - 2 * s1) : "), std::string::npos) << text;
  EXPECT_NE(text.find("wingY(rand(0.5, 1), 8)"), std::string::npos) << text;
  EXPECT_NE(text.find("wingY(rand(1, 2), 6)"), std::string::npos) << text;
  EXPECT_EQ(count(text, "I(roof)"), 1u) << text;
}

TEST(TwinRules, TwinRulesThatCallOneOfThemStayApart) {
  // Two towers whose tiers recurse into t: joined, the rebuilt body's call
  // of t would keep its one argument where t takes two.
  Grammar g = parse_grammar(R"(
@scope 20, 10, 10
building --> split(x){ ~1 : t(0.8) | ~1 : u(0.8) }
t(s1) : s1 < 0.1 --> I(rect)
t(s1) : s1 >= 0.1 --> split(z){ ~s1 : I(rect) | ~(3 - s1) : t(s1 / 2) }
u(s1) : s1 < 0.1 --> I(rect)
u(s1) : s1 >= 0.1 --> split(z){ ~s1 : I(rect) | ~(5 - s1) : t(s1 / 2) }
)",
                            "towers.grm");
  const std::string before = write_grammar(g);
  EXPECT_EQ(joined_keeping_derivations(g).rules, 0u) << write_grammar(g);
  EXPECT_EQ(write_grammar(g), before);
}

// A farmstead: a house range and a barn range built alike, the barn with
// thicker walls, wider bays and lower windows; plots of different widths.
constexpr const char* kFarmstead = R"(
@start farmstead
@scope rand(16, 28), 22, 6
farmstead --> split(y){ 7 : range(0.5, 2.5, 1.4) | ~1 : nil | 6 : range(0.8, 3.2, 0.8) }
range(wall, bw, wh) --> split(x){ wall : I(rect) | ~1 : repeat(x, bw){ bay(wh) } | wall : I(rect) }
bay(wh) --> split(x){ ~1 : I(rect) | 1.2 : split(z){ 1 : I(rect) | wh : I(window) | ~1 : I(rect) } | ~2 : I(rect) }
)";

TEST(TwinRules, InferredBaysOfHouseAndBarnAreOneRuleAndEveryExampleStillChecks) {
  const Grammar source = parse_grammar(kFarmstead, "farmstead.grm");
  std::vector<Example> examples;
  for (std::uint64_t seed = 1; seed <= 10; ++seed)
    examples.push_back(test::example_of(test::derived_parts(derive_seed(source, seed))));
  const Inference joined = infer(examples, {});
  InferOptions apart_options;
  apart_options.twin_rules = false;
  const Inference apart = infer(examples, apart_options);
  const std::string text = write_grammar(joined.grammar);
  EXPECT_GE(joined.twins.rules, 1u) << text;
  EXPECT_EQ(count(text, "I(window)"), 1u) << text;
  EXPECT_EQ(count(write_grammar(apart.grammar), "I(window)"), 2u) << write_grammar(apart.grammar);
  EXPECT_LT(description_length(joined.grammar).total(), description_length(apart.grammar).total()) << text;
  for (const Example& e : examples) {
    const CheckResult r = check_example(joined.grammar, e.boxes, example_size(e));
    EXPECT_TRUE(r.derivable) << r.mismatch << "\n" << text;
  }
  // Joining twins changes how the grammar is written, not what it makes.
  for (std::uint64_t seed = 1001; seed <= 1020; ++seed)
    EXPECT_TRUE(same_terminals(derive_seed(apart.grammar, seed), derive_seed(joined.grammar, seed))) << seed;
}

}  // namespace
}  // namespace vern
