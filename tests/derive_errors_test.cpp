// Errors that stop a derivation (docs/grammar.md, "Errors and warnings"): each names
// file:line:col and the chain of rules, and has the right kind.
#include <gtest/gtest.h>

#include "support/derive_helpers.hpp"

namespace vern {
namespace {

struct Failure {
  ErrorKind kind;
  std::string message;
};

Failure derive_failure(const std::string& text, DeriveLimits limits = {}, bool strict = false,
                       bool keep_terminals = true) {
  const Grammar g = parse_grammar(text, "g.grm");
  DeriveOptions o;
  o.limits = limits;
  o.strict = strict;
  o.keep_terminals = keep_terminals;
  try {
    derive(g, o);
  } catch (const Error& e) {
    return {e.kind(), e.what()};
  }
  ADD_FAILURE() << "no error for: " << text;
  return {ErrorKind::Internal, ""};
}

TEST(DeriveErrors, TypeErrorNamesPlaceAndChain) {
  const auto f = derive_failure("p --> wall(y)\nwall(a) --> split(x){ a * 2 : nil }");
  EXPECT_EQ(f.kind, ErrorKind::Input);
  EXPECT_EQ(f.message,
            "g.grm:2:23: error: expected a number here, found axis y\n  rule chain: p > wall(axis y)\n"
            "  hint: axes can only be compared with == and !=");
}

TEST(DeriveErrors, AxisExpectedButNumberGiven) {
  const auto f = derive_failure("p --> wall(5)\nwall(a) --> split(a){ ~1 : nil }");
  EXPECT_EQ(f.kind, ErrorKind::Input);
  EXPECT_NE(f.message.find("g.grm:2:19: error: the axis of split must be an axis, found 5"), std::string::npos);
}

TEST(DeriveErrors, RecursionDeeperThanTheLimit) {
  DeriveLimits limits;
  limits.max_depth = 50;
  const auto f = derive_failure("p --> a(1)\na(n) --> split(x){ ~1 : a(n + 1) | ~1 : I(rect) }", limits);
  EXPECT_EQ(f.kind, ErrorKind::Limit);
  EXPECT_NE(f.message.find("g.grm:2:25: error: rule calls nested deeper than 50"), std::string::npos) << f.message;
  EXPECT_NE(f.message.find("rule chain: p > a(1) > a(2) > a(3) > ... (40 more) ... > a(45)"), std::string::npos);
  EXPECT_NE(f.message.find("--max-depth"), std::string::npos);
}

TEST(DeriveErrors, MoreTerminalsThanTheLimit) {
  DeriveLimits limits;
  limits.max_terminals = 100;
  const auto f = derive_failure("p --> repeatN(x, 1000){ I(rect) }", limits);
  EXPECT_EQ(f.kind, ErrorKind::Limit);
  EXPECT_NE(f.message.find("g.grm:1:25: error: more than 100 terminals"), std::string::npos);
  EXPECT_NE(f.message.find("--max-terminals"), std::string::npos);
}

TEST(DeriveErrors, TerminalsNotKeptStillCount) {
  DeriveLimits limits;
  limits.max_terminals = 100;
  const auto f = derive_failure("p --> repeatN(x, 1000){ I(rect) }", limits, false, false);
  EXPECT_EQ(f.kind, ErrorKind::Limit);
  EXPECT_NE(f.message.find("g.grm:1:25: error: more than 100 terminals"), std::string::npos);
}

TEST(DeriveErrors, HugeRepeatCountsStopBeforeRunning) {
  const auto f = derive_failure("p --> repeatN(x, 1e12){ nil }");
  EXPECT_EQ(f.kind, ErrorKind::Limit);
  EXPECT_NE(f.message.find("--max-operations"), std::string::npos);
}

TEST(DeriveErrors, ArithmeticErrors) {
  auto f = derive_failure("zero = 0\np --> split(x){ 1 / zero : nil }");
  EXPECT_NE(f.message.find("g.grm:2:19: error: division by zero (1 / 0)"), std::string::npos);
  f = derive_failure("p --> split(x){ -1 : nil }");
  EXPECT_NE(f.message.find("a split size is negative (-1)"), std::string::npos);
  f = derive_failure("p --> repeat(x, 0){ nil }");
  EXPECT_NE(f.message.find("the tile size of repeat is 0"), std::string::npos);
  f = derive_failure("p --> split(x){ sqrt(-4) : nil }");
  EXPECT_NE(f.message.find("sqrt of a negative number"), std::string::npos);
  f = derive_failure("big = 1e300 * 1e300\np --> split(x){ big : nil }");
  EXPECT_NE(f.message.find("a split size is inf, not a finite number"), std::string::npos);
}

TEST(DeriveErrors, StartRuleWithParameters) {
  const auto f = derive_failure("wall(a) --> nil\np --> wall(1)");
  EXPECT_EQ(f.kind, ErrorKind::Input);
  EXPECT_NE(f.message.find("g.grm:1:1: error: the start rule 'wall' takes parameters"), std::string::npos);
}

TEST(DeriveErrors, NoApplicableRuleWarnsOnceOrFailsWhenStrict) {
  const char* text = "p --> repeatN(x, 3){ q(2) }\nq(n) : n > 5 --> I(rect)\n";
  const Grammar g = parse_grammar(text, "g.grm");
  const auto d = derive(g, DeriveOptions{});
  EXPECT_TRUE(d.terminals.empty());
  ASSERT_EQ(d.warnings.size(), 1u);
  EXPECT_NE(d.warnings[0].find("g.grm:2:1: warning: no rule of 'q' applies"), std::string::npos);
  const auto f = derive_failure(text, {}, true);
  EXPECT_EQ(f.kind, ErrorKind::Input);
  EXPECT_NE(f.message.find("no rule of 'q' applies"), std::string::npos);
  EXPECT_NE(f.message.find("rule chain: p > q(2)"), std::string::npos);
}

}  // namespace
}  // namespace vern
