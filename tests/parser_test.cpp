// Reading grammar text: what it accepts, what it builds, what it rejects.
#include "graph/parser.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "graph/structural.hpp"

namespace vern {
namespace {

// The message of the Input error parsing text throws ("" if none).
std::string parse_error(const std::string& text) {
  try {
    parse_grammar(text, "g.grm");
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Input);
    return e.what();
  }
  return "";
}

TEST(Parser, ReadsRulesConstantsAndDirectives) {
  const Grammar g = parse_grammar(
      "# a comment\n"
      "@start plot\n"
      "@scope 10, 8, rand(5, 7)   // another comment\n"
      "@primitives \"style.prims.obj\"\n"
      "wallDepth = 0.7\n"
      "plot --> split(x){ ~2 : house | wallDepth : garage } : 0.5\n"
      "house -> I(rect)\n"
      "garage → nil",
      "g.grm");
  ASSERT_EQ(g.rules.size(), 3u);
  EXPECT_TRUE(g.start_written);
  EXPECT_EQ(g.rules[g.start_rule].label, "plot");
  EXPECT_EQ(g.primitives, "style.prims.obj");
  EXPECT_EQ(g.scope[0].literal(), 10.0);
  EXPECT_TRUE(g.scope[2].draws_random());
  ASSERT_EQ(g.constants.size(), 1u);
  EXPECT_EQ(g.constants[0].name, "wallDepth");
  // A single rule with a priority is a one-option choose.
  const auto* choose = std::get_if<Choose>(&g.op(g.rules[0].body));
  ASSERT_NE(choose, nullptr);
  ASSERT_EQ(choose->options.size(), 1u);
  EXPECT_EQ(choose->options[0].priority.literal(), 0.5);
  const auto* split = std::get_if<Split>(&g.op(choose->options[0].child));
  ASSERT_NE(split, nullptr);
  EXPECT_TRUE(split->parts[0].size.relative);
  EXPECT_FALSE(split->parts[1].size.relative);
  EXPECT_EQ(split->parts[1].size.value, Expr::constant(0));
  // A rule with neither condition nor priority is its operation.
  EXPECT_NE(std::get_if<Primitive>(&g.op(g.rules[1].body)), nullptr);
  EXPECT_NE(std::get_if<Nil>(&g.op(g.rules[2].body)), nullptr);
}

TEST(Parser, KeepsSourceLocations) {
  const Grammar g = parse_grammar("a --> split(x){\n  ~1 : I(rect) |\n  ~1 : b }\nb --> nil\n");
  const auto& split = std::get<Split>(g.op(g.rules[0].body));
  EXPECT_EQ(g.node(g.rules[0].body).loc, (SourceLoc{1, 7}));
  EXPECT_EQ(g.node(split.parts[1].child).loc, (SourceLoc{3, 8}));
  EXPECT_EQ(split.parts[1].size.value.loc(), (SourceLoc{3, 4}));
}

TEST(Parser, RelativeSizeRunsToTheColon) {
  // The thesis writes ~(rand/2) + 0.75 : the whole expression is relative.
  const Grammar g = parse_grammar("g --> split(z){ ~(rand/2) + 0.75 : I(rect) | ~2 : nil }");
  const auto& split = std::get<Split>(g.op(g.rules[0].body));
  EXPECT_TRUE(split.parts[0].size.relative);
  const Expr& e = split.parts[0].size.value;
  EXPECT_EQ(e.node(e.root()).kind, ExprKind::Binary);
  EXPECT_EQ(static_cast<BinaryOp>(e.node(e.root()).op), BinaryOp::Add);
}

TEST(Parser, OperatorPrecedenceAndAssociativity) {
  const Grammar g = parse_grammar("c = 1 - 2 - 3 * 4 + -5\nd = 1 < 2 && 3 == 3 || !0\np --> nil");
  // ((1 - 2) - (3 * 4)) + (-5)
  const Expr want = Expr::binary(
      BinaryOp::Add,
      Expr::binary(BinaryOp::Sub, Expr::binary(BinaryOp::Sub, Expr::number(1), Expr::number(2)),
                   Expr::binary(BinaryOp::Mul, Expr::number(3), Expr::number(4))),
      Expr::number(-5));
  EXPECT_EQ(g.constants[0].value, want);
  const Expr& d = g.constants[1].value;
  EXPECT_EQ(static_cast<BinaryOp>(d.node(d.root()).op), BinaryOp::Or);
}

TEST(Parser, NamesResolveToParametersConstantsAxesAndPi) {
  const Grammar g = parse_grammar("k = 2\nwall(ax, n) --> repeatN(ax, n * k){ R(z, pi / 2){ I(window) } }\np --> wall(y, 3)\n@start p");
  const auto& rep = std::get<RepeatN>(g.op(g.rules[0].body));
  EXPECT_EQ(rep.axis, Expr::param(0));
  EXPECT_EQ(rep.count, Expr::binary(BinaryOp::Mul, Expr::param(1), Expr::constant(0)));
  const auto& rot = std::get<Rotate>(g.op(rep.child));
  EXPECT_EQ(rot.axis, Expr::axis(Axis::Z));
  EXPECT_EQ(rot.angle, Expr::binary(BinaryOp::Div, Expr::number(std::numbers::pi), Expr::number(2)));
  const auto& call = std::get<Call>(g.op(g.rules[1].body));
  EXPECT_EQ(call.rule, 0u);
  ASSERT_EQ(call.args.size(), 2u);
  EXPECT_EQ(call.args[0], Expr::axis(Axis::Y));
}

TEST(Parser, AParameterMayShadowAFunctionName) {
  // The thesis's skyscraper grammar: tower(h, max).
  const Grammar g = parse_grammar("tower(h, max) --> split(z){ ~(h * max) : I(rect) | ~max(0, 1 - h * max) : nil }\n"
                                  "p --> tower(0.5, 1)\n@start p");
  EXPECT_EQ(g.rules[g.start_rule].label, "p");
}

TEST(Parser, SizeReadsTheScopeOfARuleAndNowhereElse) {
  // size(axis) in a rule's sizes, arguments and conditions; an axis
  // parameter names the axis too.
  const Grammar g = parse_grammar("p(a) : size(z) > 3 --> split(a){ size(a) / 2 : I(b) | ~1 : q(size(x)) }\n"
                                  "q(w) --> I(c)\n");
  EXPECT_TRUE(std::get<Choose>(g.op(g.rules[0].body)).options[0].condition.reads_scope());
  // Constants and @scope are evaluated before there is any scope.
  for (const char* text : {"w = size(x)\np --> I(b)\n", "@scope 10, 10, size(x)\np --> I(b)\n"}) {
    const std::string e = parse_error(text);
    EXPECT_NE(e.find("size() reads the size of the scope a rule's operation stands in"), std::string::npos) << e;
    EXPECT_NE(e.find("use size() in a rule"), std::string::npos) << e;
  }
  EXPECT_NE(parse_error("p --> split(x){ size() : I(b) }").find("write size(x), size(y) or size(z)"), std::string::npos);
}

TEST(Parser, AlternativesBecomeOneChooseInFileOrder) {
  const Grammar g = parse_grammar("a --> I(x) : 2\nb --> nil\na(  ) : 1 > 0 --> I(y)\n");
  ASSERT_EQ(g.rules.size(), 2u);
  const auto& c = std::get<Choose>(g.op(g.rules[0].body));
  ASSERT_EQ(c.options.size(), 2u);
  EXPECT_EQ(c.options[0].priority.literal(), 2.0);
  EXPECT_TRUE(c.options[0].condition.empty());
  EXPECT_EQ(c.options[1].priority.literal(), 1.0);
  EXPECT_FALSE(c.options[1].condition.empty());
}

TEST(Parser, ReadsEveryOperation) {
  const Grammar g = parse_grammar(
      "p --> split(x){ ~1 : repeat(y, 2){ I(a) } | ~1 : repeat(y){ 2 : I(b) } | ~1 : repeatN(z, 3){ nil } |\n"
      "  ~1 : T(~0.5, 1, 0){ S(1, ~1, 2){ R(0, pi){ I(\"my mesh\") } } } |\n"
      "  ~1 : comp(f){ top : colour(red) | front : colour(0.1, 0.2, 0.3) | left : color(\"#ff8000\") } }");
  const auto& split = std::get<Split>(g.op(g.rules[0].body));
  ASSERT_EQ(split.parts.size(), 5u);
  EXPECT_EQ(std::get<Repeat>(g.op(split.parts[0].child)).size.literal(), 2.0);
  EXPECT_EQ(std::get<Repeat>(g.op(split.parts[1].child)).size.literal(), 2.0);
  EXPECT_EQ(std::get<RepeatN>(g.op(split.parts[2].child)).count.literal(), 3.0);
  const auto& t = std::get<Translate>(g.op(split.parts[3].child));
  EXPECT_TRUE(t.offset[0].relative);
  const auto& s = std::get<Scale>(g.op(t.child));
  const auto& r = std::get<Rotate>(g.op(s.child));
  EXPECT_EQ(g.label(std::get<Primitive>(g.op(r.child)).label), "my mesh");
  const auto& comp = std::get<Comp>(g.op(split.parts[4].child));
  ASSERT_EQ(comp.parts.size(), 3u);
  EXPECT_EQ(comp.parts[1].face, Face::Front);
  EXPECT_EQ(std::get<Colour>(g.op(comp.parts[2].child)).rgb[1].literal(), 128.0 / 255.0);
}

TEST(Parser, RulesMayContinueInsideBracketsAndTheLastLineNeedsNoNewline) {
  const Grammar g = parse_grammar("p -->\n  split(x){\n    ~1 : a |\n    ~1 : a\n  }\na --> I(rect)");
  EXPECT_EQ(g.rules.size(), 2u);
}

TEST(Parser, ReportsSyntaxErrorsWithLineAndColumn) {
  EXPECT_EQ(parse_error("p --> split(x){ ~1 : I(a) ~1 : I(b) }"),
            "g.grm:1:27: error: expected '}' or '|' after a split part, found '~'\n"
            "  hint: write split(axis){ size : operation | size : operation }");
  EXPECT_EQ(parse_error("p --> split(x{ ~1 : nil }"),
            "g.grm:1:14: error: expected ')' after the axis of split, found '{'\n"
            "  hint: write split(axis){ size : operation | size : operation }");
  EXPECT_NE(parse_error("p split(x){ ~1 : nil }").find("g.grm:1:3: error: expected '-->'"), std::string::npos);
  EXPECT_NE(parse_error("p --> nil\n  $").find("g.grm:2:3: error: unexpected character '$'"), std::string::npos);
  EXPECT_NE(parse_error("p --> I()").find("g.grm:1:9: error: expected a primitive name"), std::string::npos);
  EXPECT_NE(parse_error("p --> nil nil").find("g.grm:1:11: error: unexpected 'nil' after a complete line"),
            std::string::npos);
  EXPECT_NE(parse_error("c = 1e999\np --> nil").find("g.grm:1:5: error: the number 1e999 is too large"),
            std::string::npos);
  EXPECT_NE(parse_error("p --> I(\"open").find("g.grm:1:9: error: this string has no closing"), std::string::npos);
  EXPECT_NE(parse_error("").find("no rules"), std::string::npos);
  EXPECT_NE(parse_error(std::string("p --> nil\n\0", 11)).find("byte 0x00"), std::string::npos);
}

TEST(Parser, ReportsUnknownNamesWithSuggestions) {
  EXPECT_EQ(parse_error("plot --> split(x){ ~2 : house | ~1 : garag }\nhouse --> nil\ngarage --> nil"),
            "g.grm:1:38: error: unknown rule 'garag'\n  hint: did you mean 'garage'?");
  EXPECT_NE(parse_error("p --> split(x){ wdth : nil }\nwidth = 2").find("unknown name 'wdth'"), std::string::npos);
  EXPECT_NE(parse_error("p --> split(x){ rnd(1, 2) : nil }").find("unknown function 'rnd'\n  hint: did you mean 'rand'?"),
            std::string::npos);
  EXPECT_NE(parse_error("b = a\na = 1\np --> nil").find("g.grm:1:5: error: unknown name 'a'"), std::string::npos);
  EXPECT_NE(parse_error("@start nope\np --> nil").find("@start names 'nope'"), std::string::npos);
  EXPECT_NE(parse_error("p --> comp(f){ roof : nil }").find("'roof' is not a face"), std::string::npos);
  EXPECT_NE(parse_error("p --> colour(purpel)").find("unknown colour 'purpel'"), std::string::npos);
}

// A name of megabytes makes no message of megabytes; a character that may
// show as nothing is named by its code point.
TEST(Parser, ShowsWhatItQuotesReadably) {
  const std::string name(100, 'a');
  EXPECT_NE(parse_error("p --> split " + name).find("found '" + std::string(40, 'a') + "... (100 characters)'"),
            std::string::npos);
  EXPECT_NE(parse_error("p --> " + name).find("unknown rule '" + std::string(40, 'a') + "... (100 characters)'"),
            std::string::npos);
  EXPECT_NE(parse_error("p --> split(x){ 1 \xE2\x89\x88 2 : nil }").find("character '\xE2\x89\x88' (U+2248)"),
            std::string::npos);
  EXPECT_NE(parse_error("p --> nil\xC2\xA0").find("unexpected character '\xC2\xA0' (U+00A0)"), std::string::npos);
}

TEST(Parser, ReportsWrongArgumentCounts) {
  EXPECT_EQ(parse_error("p --> wall(x)\nwall(a, b) --> nil"),
            "g.grm:1:7: error: 'wall' takes 2 arguments, given 1\n  hint: it is defined at 2:1 as wall(a, b)");
  EXPECT_NE(parse_error("w(a) --> nil\np --> w(1, 2)").find("'w' takes 1 argument, given 2"), std::string::npos);
  EXPECT_NE(parse_error("w(a) --> nil\nw(a, b) --> nil").find("'w' takes 1 parameters where it was first defined"),
            std::string::npos);
  EXPECT_NE(parse_error("p --> split(x){ rand(1) : nil }").find("rand takes 0 or 2 arguments, given 1"),
            std::string::npos);
  EXPECT_NE(parse_error("p --> split(x){ tnormal(1, 2) : nil }").find("tnormal takes 4 arguments, given 2"),
            std::string::npos);
}

TEST(Parser, ReportsTypeErrorsItCanSeeStatically) {
  EXPECT_EQ(parse_error("p --> split(x){ x + 1 : nil }"),
            "g.grm:1:17: error: '+' expects numbers, found the axis x\n  hint: axes can only be compared with == and !=");
  EXPECT_NE(parse_error("p --> split(7){ ~1 : nil }").find("the axis of split is 7"), std::string::npos);
  EXPECT_NE(parse_error("p --> split(x){ sqrt(y) : nil }").find("sqrt expects numbers, found an axis"),
            std::string::npos);
}

TEST(Parser, RejectsReservedAndDuplicateNames) {
  EXPECT_NE(parse_error("x = 2\np --> nil").find("'x' cannot name a constant"), std::string::npos);
  EXPECT_NE(parse_error("f(a, a) --> nil").find("listed twice"), std::string::npos);
  EXPECT_NE(parse_error("split --> nil").find("'split' is an operation"), std::string::npos);
  EXPECT_NE(parse_error("@start p\np(n) --> nil").find("g.grm:1:8: error: the start rule 'p' takes parameters"),
            std::string::npos);
  // A default start rule with parameters may still be replaced (--start).
  EXPECT_EQ(parse_error("p(n) --> nil\nq --> p(1)"), "");
}

TEST(Parser, ReadGrammarFileNamesTheFile) {
  try {
    read_grammar_file("/nonexistent/style.grm");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Io);
    EXPECT_NE(std::string(e.what()).find("/nonexistent/style.grm"), std::string::npos);
  }
}

}  // namespace
}  // namespace vern
