// The grammar writer: exact text for graphs built in code, and round trips
// through the parser (parse(write(g)) equals g, and writing is a fixed point).
#include "graph/writer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <utility>

#include "base/error.hpp"
#include "graph/parser.hpp"
#include "graph/structural.hpp"

namespace vern {
namespace {

// ---- building graphs in code ----

Expr num(double v) { return Expr::number(v); }
Expr par(std::uint32_t i) { return Expr::param(i); }
Expr con(std::uint32_t i) { return Expr::constant(i); }
Expr ax(Axis a) { return Expr::axis(a); }
Expr bin(BinaryOp op, Expr a, Expr b) { return Expr::binary(op, std::move(a), std::move(b)); }
Size rel(Expr e) { return {std::move(e), true}; }
Size abs_size(Expr e) { return {std::move(e), false}; }

class Builder {
 public:
  Grammar g;

  RuleId rule(const std::string& label, std::vector<std::string> params = {}) {
    g.rules.push_back({label, std::move(params), 0, {}});
    return static_cast<RuleId>(g.rules.size() - 1);
  }
  void body(RuleId r, NodeId node) { g.rules[r].body = node; }
  std::uint32_t constant(const std::string& name, Expr value) {
    g.constants.push_back({name, std::move(value), {}});
    return static_cast<std::uint32_t>(g.constants.size() - 1);
  }

  NodeId node(Operation op) { return g.intern({std::move(op), {}}); }
  NodeId prim(std::string_view name) { return node(Primitive{g.label_id(name)}); }
  NodeId nil() { return node(Nil{}); }
  NodeId call(RuleId r, std::vector<Expr> args = {}) { return node(Call{r, std::move(args)}); }
  NodeId split(Axis a, std::vector<SplitPart> parts) { return node(Split{ax(a), std::move(parts)}); }
  NodeId choose(std::vector<ChooseOption> options) { return node(Choose{std::move(options)}); }
};

std::string write(const Builder& b, const WriteOptions& options = {}) { return write_grammar(b.g, options); }

// ---- exact text ----

TEST(Writer, AGrammarNestedDeeperThanTheStackHoldsIsALimitSaidNotACrash) {
  Grammar g;
  Primitive p;
  p.label = g.label_id("wall");
  NodeId at = g.intern({p, {}});
  for (int i = 0; i < 300'000; ++i) {
    Split s;
    s.axis = Expr::axis(Axis::X);
    s.parts.push_back({{Expr::number(1), true}, at});
    at = g.intern({std::move(s), {}});
  }
  try {
    write_operation(g, at, {});
    FAIL() << "written";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Limit);
    EXPECT_NE(std::string(e.what()).find("nest deeper than this thread's"), std::string::npos) << e.what();
  }
}

TEST(Writer, ShortSplitStaysOnOneLine) {
  Builder b;
  const RuleId plot = b.rule("plot");
  b.body(plot, b.split(Axis::Z, {{rel(num(2)), b.prim("rect")}, {rel(num(1)), b.prim("roof")}}));
  EXPECT_EQ(write(b), "plot --> split(z){ ~2 : I(rect) | ~1 : I(roof) }\n");
}

// The brief's example: the outer split breaks, one part per line; the inner
// split fits its line and stays whole.
Builder floors_grammar() {
  Builder b;
  const auto max_floors = b.constant("maxFloors", num(5));
  const RuleId plot = b.rule("plot");
  const RuleId floors = b.rule("floors", {"numFloors"});
  const RuleId base = b.rule("base");
  const RuleId house = b.rule("house", {"n"});
  b.body(plot, b.call(floors, {num(3)}));
  const NodeId inner = b.split(Axis::Y, {{rel(num(1)), b.call(house, {par(0)})}, {rel(num(1)), b.nil()}});
  b.body(floors, b.split(Axis::Z, {{rel(num(1)), b.call(base)},
                                   {rel(bin(BinaryOp::Mul, num(10), par(0))), inner},
                                   {rel(bin(BinaryOp::Mul, num(10), bin(BinaryOp::Sub, con(max_floors), par(0)))),
                                    b.nil()}}));
  b.body(base, b.prim("base"));
  b.body(house, b.prim("house"));
  return b;
}

TEST(Writer, LongRuleBreaksOnePartPerLine) {
  EXPECT_EQ(write(floors_grammar()),
            "maxFloors = 5\n"
            "\n"
            "plot --> floors(3)\n"
            "floors(numFloors) --> split(z){\n"
            "    ~1 : base |\n"
            "    ~(10 * numFloors) : split(y){ ~1 : house(numFloors) | ~1 : nil } |\n"
            "    ~(10 * (maxFloors - numFloors)) : nil }\n"
            "base --> I(base)\n"
            "house(n) --> I(house)\n");
}

TEST(Writer, NarrowWidthBreaksNestedSplitsWithDeeperIndent) {
  WriteOptions narrow;
  narrow.width = 40;
  narrow.indent = 2;
  const std::string text = write(floors_grammar(), narrow);
  EXPECT_NE(text.find("floors(numFloors) --> split(z){\n"
                      "  ~1 : base |\n"
                      "  ~(10 * numFloors) : split(y){\n"
                      "    ~1 : house(numFloors) |\n"
                      "    ~1 : nil } |\n"
                      "  ~(10 * (maxFloors - numFloors)) : nil }\n"),
            std::string::npos)
      << text;
}

TEST(Writer, LineExactlyAtWidthStaysWhole) {
  Builder b;
  const RuleId r = b.rule("r");
  b.body(r, b.split(Axis::X, {{rel(num(1)), b.prim("aaaa")}, {rel(num(1)), b.prim("bbbb")}}));
  const std::string line = "r --> split(x){ ~1 : I(aaaa) | ~1 : I(bbbb) }";
  WriteOptions exact;
  exact.width = static_cast<int>(line.size());
  EXPECT_EQ(write(b, exact), line + "\n");
  exact.width -= 1;
  EXPECT_EQ(write(b, exact), "r --> split(x){\n    ~1 : I(aaaa) |\n    ~1 : I(bbbb) }\n");
}

TEST(Writer, ChooseBodyWritesOneLinePerOption) {
  Builder b;
  const RuleId plot = b.rule("plot");
  const RuleId facade = b.rule("facade", {"n"});
  b.body(plot, b.call(facade, {num(3)}));
  const NodeId wide = b.split(Axis::X, {{rel(num(1)), b.prim("a")}, {rel(num(1)), b.prim("b")}});
  b.body(facade, b.choose({{bin(BinaryOp::Gt, par(0), num(2)), num(0.5), wide},
                           {Expr{}, num(1), b.prim("c")},
                           {bin(BinaryOp::Le, par(0), num(0)), num(2), b.nil()}}));
  EXPECT_EQ(write(b),
            "plot --> facade(3)\n"
            "facade(n) : n > 2 --> split(x){ ~1 : I(a) | ~1 : I(b) } : 0.5\n"
            "facade(n) --> I(c)\n"
            "facade(n) : n <= 0 --> nil : 2\n");
}

TEST(Writer, TrailingPriorityCountsTowardsTheWidth) {
  Builder b;
  const RuleId r = b.rule("r");
  const NodeId s = b.split(Axis::X, {{rel(num(1)), b.prim("a")}, {rel(num(1)), b.prim("b")}});
  b.body(r, b.choose({{Expr{}, num(0.25), s}, {Expr{}, num(1), b.nil()}}));
  const std::string whole = "r --> split(x){ ~1 : I(a) | ~1 : I(b) } : 0.25";
  WriteOptions options;
  options.width = static_cast<int>(whole.size()) - 1;  // fits but for the priority
  EXPECT_EQ(write(b, options), "r --> split(x){\n    ~1 : I(a) |\n    ~1 : I(b) } : 0.25\nr --> nil\n");
}

TEST(Writer, LoneOptionAlwaysShowsWhyItIsAChoose) {
  Builder b;
  const RuleId roof = b.rule("roof");
  b.body(roof, b.choose({{Expr{}, num(1), b.prim("roof")}}));
  EXPECT_EQ(write(b), "roof --> I(roof) : 1\n");

  Builder c;
  const RuleId plot = c.rule("plot");
  const RuleId cond = c.rule("roof", {"n"});
  c.body(plot, c.call(cond, {num(2)}));
  c.body(cond, c.choose({{bin(BinaryOp::Gt, par(0), num(1)), num(1), c.prim("roof")}}));
  EXPECT_EQ(write(c), "plot --> roof(2)\nroof(n) : n > 1 --> I(roof)\n");
}

TEST(Writer, ParametersAndConstantsByName) {
  Builder b;
  const auto depth = b.constant("wallDepth", num(0.7));
  b.constant("twice", bin(BinaryOp::Mul, num(2), con(depth)));
  const RuleId plot = b.rule("plot");
  const RuleId win = b.rule("win", {"w", "h"});
  b.body(plot, b.call(win, {num(1.2), bin(BinaryOp::Add, con(1), num(1))}));
  b.body(win, b.node(Scale{{abs_size(par(0)), abs_size(con(depth)), abs_size(par(1))}, b.prim("window")}));
  EXPECT_EQ(write(b),
            "wallDepth = 0.7\n"
            "twice = 2 * wallDepth\n"
            "\n"
            "plot --> win(1.2, twice + 1)\n"
            "win(w, h) --> S(w, wallDepth, h){ I(window) }\n");
}

TEST(Writer, ExpressionsTakeTheFewestParentheses) {
  Builder b;
  const Grammar& g = b.g;
  const std::vector<std::string> n{"a", "b", "c"};
  auto text = [&](const Expr& e) { return write_expression(g, e, n); };
  const Expr a = par(0), bb = par(1), c = par(2);
  using enum BinaryOp;
  EXPECT_EQ(text(bin(Sub, a, bin(Sub, bb, c))), "a - (b - c)");
  EXPECT_EQ(text(bin(Sub, bin(Sub, a, bb), c)), "a - b - c");
  EXPECT_EQ(text(bin(Mul, bin(Add, a, bb), c)), "(a + b) * c");
  EXPECT_EQ(text(bin(Add, a, bin(Mul, bb, c))), "a + b * c");
  EXPECT_EQ(text(bin(Div, a, bin(Mul, bb, c))), "a / (b * c)");
  EXPECT_EQ(text(Expr::unary(UnaryOp::Neg, a)), "-a");
  EXPECT_EQ(text(Expr::unary(UnaryOp::Neg, Expr::unary(UnaryOp::Neg, a))), "-(-a)");
  EXPECT_EQ(text(Expr::unary(UnaryOp::Neg, bin(Add, a, bb))), "-(a + b)");
  EXPECT_EQ(text(bin(Or, Expr::unary(UnaryOp::Not, bin(And, a, bb)), c)), "!(a && b) || c");
  EXPECT_EQ(text(bin(Or, a, bin(And, bb, c))), "a || b && c");
  EXPECT_EQ(text(bin(And, bin(Or, a, bb), c)), "(a || b) && c");
  EXPECT_EQ(text(bin(Eq, bin(Lt, a, bb), bin(Gt, c, num(1)))), "a < b == c > 1");
  EXPECT_EQ(text(bin(Lt, a, bin(Eq, bb, c))), "a < (b == c)");
  EXPECT_EQ(text(bin(Div, bin(Mul, num(3), num(std::numbers::pi)), num(2))), "3 * pi / 2");
  EXPECT_EQ(text(num(-std::numbers::pi)), "-pi");
  EXPECT_EQ(text(bin(Sub, a, num(-2))), "a - -2");
  EXPECT_EQ(text(bin(Mul, num(-2), a)), "-2 * a");
  EXPECT_EQ(text(bin(Mod, a, num(0.1))), "a % 0.1");
  EXPECT_EQ(text(num(1e-7)), "1e-07");
  EXPECT_EQ(text(num(-0.0)), "0");
  EXPECT_EQ(text(Expr::call(Function::Rand, {})), "rand()");
  EXPECT_EQ(text(Expr::call(Function::Rand, {num(0.29), num(0.31)})), "rand(0.29, 0.31)");
  EXPECT_EQ(text(Expr::call(Function::Min, {bin(Add, a, num(1)), num(3)})), "min(a + 1, 3)");
  EXPECT_EQ(text(bin(Eq, a, ax(Axis::Y))), "a == y");
  EXPECT_EQ(text(Expr{}), "");
}

TEST(Writer, PrimitiveNamesAreQuotedWhenNotNames) {
  Builder b;
  const RuleId r = b.rule("r");
  b.body(r, b.split(Axis::X, {{rel(num(1)), b.prim("name with space")},
                              {rel(num(1)), b.prim("win.001")},
                              {rel(num(1)), b.prim("say \"hi\\")},
                              {rel(num(1)), b.prim("_ok2")}}));
  WriteOptions wide;
  wide.width = 200;
  EXPECT_EQ(write(b, wide),
            "r --> split(x){ ~1 : I(\"name with space\") | ~1 : I(\"win.001\") | ~1 : I(\"say \\\"hi\\\\\") | "
            "~1 : I(_ok2) }\n");
}

TEST(Writer, TranslateAndScaleWithRelativeSizes) {
  Builder b;
  const RuleId plot = b.rule("plot");
  const RuleId r = b.rule("r", {"n"});
  b.body(plot, b.call(r, {num(2)}));
  const NodeId scaled = b.node(Scale{{rel(num(1)), rel(bin(BinaryOp::Sub, par(0), num(1))),
                                      abs_size(bin(BinaryOp::Mul, num(2), par(0)))},
                                     b.prim("a")});
  b.body(r, b.node(Translate{{abs_size(num(0)), abs_size(num(-0.5)), rel(num(-1))}, scaled}));
  EXPECT_EQ(write(b), "plot --> r(2)\nr(n) --> T(0, -0.5, ~(-1)){ S(~1, ~(n - 1), 2 * n){ I(a) } }\n");
}

TEST(Writer, CompColourRotate) {
  Builder b;
  const RuleId box = b.rule("box");
  const NodeId red = b.node(Colour{{num(0.8), num(0.1), num(0.1)}});
  const NodeId turned = b.node(Rotate{ax(Axis::Z), bin(BinaryOp::Div, num(std::numbers::pi), num(2)), b.prim("roof")});
  b.body(box, b.node(Comp{{{Face::Top, turned}, {Face::Front, red}}}));
  EXPECT_EQ(write(b), "box --> comp(f){ top : R(z, pi / 2){ I(roof) } | front : colour(0.8, 0.1, 0.1) }\n");
}

TEST(Writer, RepeatAndRepeatN) {
  Builder b;
  const RuleId r = b.rule("r");
  const RuleId tiles = b.rule("tiles");
  b.body(r, b.node(Repeat{ax(Axis::X), num(2.5), b.call(tiles)}));
  const NodeId s = b.split(Axis::Z, {{rel(num(1)), b.prim("a")}, {rel(num(1)), b.nil()}});
  b.body(tiles, b.node(RepeatN{ax(Axis::Y), num(3), s}));
  EXPECT_EQ(write(b), "r --> repeat(x, 2.5){ tiles }\ntiles --> repeatN(y, 3){ split(z){ ~1 : I(a) | ~1 : nil } }\n");
}

TEST(Writer, SingleChildOperationsHugABracedChild) {
  Builder b;
  const RuleId facade = b.rule("facade");
  const NodeId s = b.split(Axis::Z, {{rel(num(1)), b.prim("groundFloorWindow")}, {rel(num(2)), b.prim("upperWall")}});
  const NodeId moved = b.node(Translate{{rel(num(0)), abs_size(num(0.1)), abs_size(num(0))}, s});
  b.body(facade, b.node(Repeat{ax(Axis::X), num(3), moved}));
  EXPECT_EQ(write(b),
            "facade --> repeat(x, 3){ T(~0, 0.1, 0){ split(z){\n"
            "    ~1 : I(groundFloorWindow) |\n"
            "    ~2 : I(upperWall) } } }\n");
}

TEST(Writer, SingleChildOperationBreaksBeforeALongLeaf) {
  Builder b;
  const RuleId r = b.rule("r");
  b.body(r, b.node(Repeat{ax(Axis::X), num(3), b.prim("a_primitive_with_a_rather_long_name_indeed")}));
  WriteOptions narrow;
  narrow.width = 50;
  EXPECT_EQ(write(b, narrow), "r --> repeat(x, 3){\n    I(a_primitive_with_a_rather_long_name_indeed) }\n");
}

TEST(Writer, HeaderDirectivesInOrder) {
  Builder b;
  const RuleId a = b.rule("a");
  const RuleId plot = b.rule("plot");
  b.body(a, b.nil());
  b.body(plot, b.call(a));
  b.g.start_rule = plot;
  b.g.start_written = true;
  b.g.scope = {num(10), num(8), Expr::call(Function::Rand, {num(5), num(7)})};
  b.g.primitives = "my \"prims\\\".obj";
  b.constant("k", num(1));
  EXPECT_EQ(write(b),
            "@start plot\n"
            "@scope 10, 8, rand(5, 7)\n"
            "@primitives \"my \\\"prims\\\\\\\".obj\"\n"
            "k = 1\n"
            "\n"
            "a --> nil\n"
            "plot --> a\n");
}

TEST(Writer, StartIsWrittenWhenItIsNotTheFirstRuleAndScopeFollowsItsConstants) {
  Builder b;
  const RuleId a = b.rule("a");
  const RuleId plot = b.rule("plot");
  b.body(a, b.nil());
  b.body(plot, b.call(a));
  b.g.start_rule = plot;  // start_written left false
  const auto w = b.constant("w", num(12));
  b.g.scope = {con(w), num(8), num(6)};
  EXPECT_EQ(write(b), "@start plot\nw = 12\n@scope w, 8, 6\n\na --> nil\nplot --> a\n");
}

TEST(Writer, WriteOperationForMessages) {
  Builder b;
  const NodeId s =
      b.split(Axis::X, {{abs_size(bin(BinaryOp::Add, par(0), num(1))), b.prim("a")}, {rel(num(1)), b.nil()}});
  EXPECT_EQ(write_operation(b.g, s, {"w"}), "split(x){ w + 1 : I(a) | ~1 : nil }");
}

TEST(Writer, RefusesWhatNoParseCouldGive) {
  auto expect_internal = [](const Builder& b, const std::string& words) {
    try {
      write_grammar(b.g);
      ADD_FAILURE() << "expected an error mentioning: " << words;
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::Internal);
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  {
    Builder b;  // a choose inside a split
    const RuleId r = b.rule("r");
    const NodeId c = b.choose({{Expr{}, num(1), b.nil()}, {Expr{}, num(2), b.prim("a")}});
    b.body(r, b.split(Axis::X, {{rel(num(1)), c}}));
    expect_internal(b, "must become a rule first");
  }
  {
    Builder b;  // two rules with one label
    const RuleId r1 = b.rule("r");
    const RuleId r2 = b.rule("r");
    b.body(r1, b.nil());
    b.body(r2, b.nil());
    expect_internal(b, "two rules are labelled 'r'");
  }
  {
    Builder b;  // a rule label that is an operation
    b.body(b.rule("split"), b.nil());
    expect_internal(b, "'split' is a word of the grammar language");
  }
  {
    Builder b;  // a parameter that would read as an axis
    const RuleId plot = b.rule("plot");
    const RuleId r = b.rule("r", {"x"});
    b.body(plot, b.call(r, {num(1)}));
    b.body(r, b.nil());
    expect_internal(b, "parameter 'x'");
  }
  {
    Builder b;  // not a finite number
    b.body(b.rule("r"), b.node(Repeat{ax(Axis::X), num(std::numeric_limits<double>::infinity()), b.nil()}));
    expect_internal(b, "not finite");
  }
  {
    Builder b;  // a constant hidden by a parameter
    const auto k = b.constant("k", num(1));
    const RuleId plot = b.rule("plot");
    const RuleId r = b.rule("r", {"k"});
    b.body(plot, b.call(r, {num(1)}));
    b.body(r, b.node(Repeat{ax(Axis::X), con(k), b.nil()}));
    expect_internal(b, "hidden by a parameter");
  }
}

// ---- round trips through the parser ----

// parse(write(g)) equals g, and writing what was read gives the same text.
void expect_round_trip(const Grammar& g, const std::string& what) {
  const std::string text = write_grammar(g);
  Grammar back;
  try {
    back = parse_grammar(text, what);
  } catch (const Error& e) {
    FAIL() << what << ": the written text does not parse: " << e.what() << "\n" << text;
  }
  EXPECT_TRUE(equal_grammars(g, back)) << what << ": reads back as a different graph\n" << text;
  EXPECT_EQ(write_grammar(back), text) << what << ": writing is not a fixed point";
}

void expect_text_round_trip(const std::string& source, const std::string& what) {
  Grammar g;
  try {
    g = parse_grammar(source, what);
  } catch (const Error& e) {
    FAIL() << what << ": the test text does not parse: " << e.what();
  }
  expect_round_trip(g, what);
}

TEST(WriterRoundTrip, BuiltGraphs) {
  expect_round_trip(floors_grammar().g, "floors");
  WriteOptions narrow;
  narrow.width = 30;
  const Grammar g = floors_grammar().g;
  EXPECT_TRUE(equal_grammars(g, parse_grammar(write_grammar(g, narrow))));
}

// Random expressions in every position an expression can take: whatever
// the nesting, the parentheses the writer leaves out must not change the tree.
class RandomExprs {
 public:
  explicit RandomExprs(std::uint32_t seed) : rng_(seed) {}

  Expr make(int depth) {
    using enum BinaryOp;
    static constexpr BinaryOp kOps[] = {Add, Sub, Mul, Div, Mod, Eq, Ne, Lt, Le, Gt, Ge, And, Or};
    static constexpr double kNumbers[] = {0, 1, 2.5, -3, std::numbers::pi, 1e-7, 0.1, -0.25};
    const int pick = depth <= 0 ? below(3) : below(7);
    switch (pick) {
      case 0: return num(kNumbers[below(8)]);
      case 1: return par(static_cast<std::uint32_t>(below(2)));
      case 2: return con(0);
      case 3: return Expr::unary(below(2) == 0 ? UnaryOp::Neg : UnaryOp::Not, make(depth - 1));
      case 4:
        if (below(3) == 0) return Expr::call(Function::Rand, {});
        return Expr::call(below(2) == 0 ? Function::Min : Function::Rand, {make(depth - 1), make(depth - 1)});
      default: return bin(kOps[below(13)], make(depth - 1), make(depth - 1));
    }
  }

 private:
  int below(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
  std::mt19937 rng_;
};

TEST(WriterRoundTrip, RandomExpressionsEverywhere) {
  RandomExprs random(20240611);
  for (int round = 0; round < 200; ++round) {
    Builder b;
    b.constant("k", num(3));
    const RuleId plot = b.rule("plot");
    const RuleId r = b.rule("r", {"a", "b"});
    b.body(plot, b.call(r, {num(1), num(4)}));
    const NodeId leaf = b.node(Colour{{random.make(2), random.make(2), random.make(2)}});
    const NodeId again = b.call(r, {random.make(2), random.make(2)});
    const NodeId s = b.split(Axis::X, {{rel(random.make(3)), leaf}, {abs_size(random.make(3)), again}});
    const NodeId t = b.node(Translate{{rel(random.make(2)), abs_size(random.make(2)), rel(random.make(1))}, s});
    b.body(r, b.choose({{random.make(3), random.make(2), t}, {Expr{}, random.make(3), b.nil()}}));
    expect_round_trip(b.g, "random grammar " + std::to_string(round));
    if (HasFailure()) break;
  }
}

TEST(WriterRoundTrip, EveryConstruct) {
  const std::string text = R"(# every construct of the language, in one grammar
@start plot
@scope 10, 8, rand(5, 7)
@primitives "style \"one\".obj"
wallDepth = 0.7
storey = 3 + wallDepth * 2
angle = -pi / 4

plot --> split(x){ ~2 : house(3, x) | ~1 : garage | 1.5 : nil }
house(n, ax) : n > 1 && ax == x --> split(z){ ~1 : I(rect) | ~(n - 1) : house(n - 1, ax) } : 0.5
house(n, ax) : !(n > 1) || ax != x --> roof(n)
house(n, ax) --> nil : 0
roof(k) --> R(z, pi / 2){ I(roof) } : 1
garage --> repeat(y, 2.5){ T(~0.1, -0.2, 0){ S(~1, ~(1 - 0.25), wallDepth){ I("garage door") } } }
tiles --> repeatN(x, round(storey % 2)){ comp(f){ top : colour(0.5, 0.25, 1) | front : I("win.frame") | left : nil } }
maths(a, b) --> repeat(x, min(a, b, max(1, abs(a - b)))){ T(floor(a), ceil(b), round(a / b)){ nil } }
randoms(a) --> split(y){ rand : nil | rand(1, 2) : nil | randint(1, 3) : nil | normal(1, 0.1) : nil |
    ~tnormal(1, 0.1, 0.5, 2) : nil | choice(1, 2, 3) : nil }
functionNames(max, min) --> split(z){ max : nil | min(max, min) : nil }
more(a) --> split(z){ sqrt(a) : nil | sin(a) * cos(a) : nil | a - (a - 1) : nil | -(-a) : nil | a % 2 == 0 : nil }
)";
  expect_text_round_trip(text, "every construct");
}

TEST(WriterRoundTrip, ColourNamesAndHexReadAsNumbers) {
  expect_text_round_trip("plot --> comp(f){ top : colour(red) | bottom : color(\"#ff8000\") }\n", "colours");
}

TEST(WriterRoundTrip, LongRulesWrapAndReadBack) {
  const std::string text =
      "plot --> split(x){ ~1 : split(y){ ~1 : split(z){ ~1 : I(a) | ~1 : I(b) | ~1 : I(c) } | ~2 : "
      "repeat(z, 3){ split(x){ ~1 : I(window_with_frame) | ~1 : I(wall_with_plaster) } } } | "
      "~1 : comp(f){ top : I(roof_tiles_red) | front : I(door_wooden) | back : I(wall_back) } } : 2\n"
      "plot --> nil\n";
  expect_text_round_trip(text, "long rules");
  const std::string written = write_grammar(parse_grammar(text));
  std::istringstream lines(written);
  for (std::string line; std::getline(lines, line);) EXPECT_LE(line.size(), 80u) << line;
}

TEST(WriterRoundTrip, GrammarFilesInTheRepository) {
  const std::filesystem::path folder = VERN_SOURCE_DIR "/data/grammars";
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) GTEST_SKIP() << "no " << folder;
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.path().extension() == ".grm") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  if (files.empty()) GTEST_SKIP() << "no .grm files in " << folder;
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    Grammar g;
    try {
      g = read_grammar_file(file);
    } catch (const Error& e) {
      ADD_FAILURE() << "does not parse, so cannot round-trip: " << e.what();
      continue;
    }
    expect_round_trip(g, file.filename().string());
  }
}

}  // namespace
}  // namespace vern
