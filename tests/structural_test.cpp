// Structural hashing and equality: what inference will hash-cons with.
#include "graph/structural.hpp"

#include <gtest/gtest.h>

#include "graph/parser.hpp"

namespace vern {
namespace {

NodeId split_of(Grammar& g, Axis axis, std::vector<std::pair<double, NodeId>> parts) {
  Split s;
  s.axis = Expr::axis(axis);
  for (auto [size, child] : parts) s.parts.push_back({{Expr::number(size), true}, child});
  return g.intern({std::move(s), {}});
}

// A chain `depth` splits deep, each holding the next and a leaf.
NodeId chain(Grammar& g, int depth, const char* leaf) {
  Primitive p;
  p.label = g.label_id(leaf);
  NodeId at = g.intern({p, {}});
  const NodeId side = g.intern({Nil{}, {}});
  for (int i = 0; i < depth; ++i) at = split_of(g, Axis::X, {{1, at}, {1, side}});
  return at;
}

TEST(Structural, AGraphHundredsOfThousandsDeepHashesAndComparesWithoutRunningOutOfStack) {
  // A recursion ran the stack out tens of thousands deep (graphs inference
  // made of 378 CMP facades).
  Grammar a, b;
  const NodeId deep_a = chain(a, 300'000, "wall"), deep_b = chain(b, 300'000, "wall");
  EXPECT_EQ(structural_hash(a, deep_a), structural_hash(b, deep_b));
  Grammar c;
  EXPECT_NE(structural_hash(a, deep_a), structural_hash(c, chain(c, 300'000, "roof")));
  EXPECT_NE(structural_hash(a, deep_a), structural_hash(c, chain(c, 299'999, "wall")));
  // And compares so: equal to its twin, unequal to one with another leaf.
  EXPECT_TRUE(structurally_equal(a, deep_a, b, deep_b));
  Grammar d;
  EXPECT_FALSE(structurally_equal(a, deep_a, d, chain(d, 300'000, "roof")));
}

TEST(Structural, InterningSharesEqualSubgraphs) {
  Grammar g;
  const NodeId rect = g.intern({Primitive{g.label_id("rect")}, {}});
  const NodeId roof = g.intern({Primitive{g.label_id("roof")}, {}});
  EXPECT_EQ(g.intern({Primitive{g.label_id("rect")}, {SourceLoc{3, 4}}}), rect);  // locations do not count
  const NodeId a = split_of(g, Axis::Z, {{2, rect}, {1, roof}});
  const NodeId b = split_of(g, Axis::Z, {{2, rect}, {1, roof}});
  const NodeId c = split_of(g, Axis::Z, {{1, rect}, {2, roof}});
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  EXPECT_EQ(g.node_count(), 4u);
  EXPECT_EQ(shallow_hash(g.op(a)), shallow_hash(g.op(b)));
}

TEST(Structural, DeepEqualityAcrossGrammarsIgnoresIdsAndLocations) {
  const Grammar a = parse_grammar("p --> split(x){ ~2 : h | ~1 : I(rect) }\nh --> split(z){ ~2 : I(rect) | ~1 : I(roof) }");
  // The same grammar laid out differently, with labels interned in another order.
  const Grammar b = parse_grammar(
      "p -->\n  split(x){\n    ~2 : h |\n    ~1 : I(rect)\n  }\nh --> split(z){ ~2 : I(rect) | ~1 : I(roof) }  # same");
  EXPECT_TRUE(equal_grammars(a, b));
  EXPECT_TRUE(structurally_equal(a, a.rules[1].body, b, b.rules[1].body));
  EXPECT_EQ(structural_hash(a, a.rules[0].body), structural_hash(b, b.rules[0].body));
}

TEST(Structural, SeesEveryKindOfDifference) {
  const std::string base = "p --> split(x){ ~2 : h | ~1 : I(rect) }\nh --> split(z){ ~2 : I(rect) | ~1 : I(roof) }";
  const Grammar a = parse_grammar(base);
  for (const std::string& other : {
           std::string("p --> split(y){ ~2 : h | ~1 : I(rect) }\nh --> split(z){ ~2 : I(rect) | ~1 : I(roof) }"),
           std::string("p --> split(x){ 2 : h | ~1 : I(rect) }\nh --> split(z){ ~2 : I(rect) | ~1 : I(roof) }"),
           std::string("p --> split(x){ ~2 : h | ~1 : I(rect) }\nh --> split(z){ ~2 : I(rect) | ~1 : I(hip) }"),
           std::string("p --> split(x){ ~2 : h | ~1 : I(rect) }\nh --> split(z){ ~2 : I(rect) | ~1 : nil }"),
           std::string("p --> split(x){ ~2 : h | ~1 : I(rect) } : 2\nh --> split(z){ ~2 : I(rect) | ~1 : I(roof) }"),
           std::string("p --> split(x){ ~2 : h | ~1 : I(rect) }\nh --> split(z){ ~2 : I(rect) | ~1 : I(roof) | ~1 : nil }"),
       }) {
    const Grammar b = parse_grammar(other);
    EXPECT_FALSE(equal_grammars(a, b)) << other;
    // A call hashes by the rule it names, not by that rule's body, so the
    // grammars' hashes are the rules' hashes together.
    auto all_rules = [](const Grammar& g) {
      std::size_t h = 0;
      for (const auto& r : g.rules) h = hash_combine(h, structural_hash(g, r.body));
      return h;
    };
    EXPECT_NE(all_rules(a), all_rules(b)) << other;
  }
}

TEST(Structural, RecursiveGrammarsCompareWithoutLooping) {
  const char* text = "p --> a(3)\na(n) : n > 0 --> split(x){ ~1 : I(rect) | ~1 : a(n - 1) }\na(n) --> nil";
  EXPECT_TRUE(equal_grammars(parse_grammar(text), parse_grammar(text)));
  EXPECT_FALSE(equal_grammars(parse_grammar(text), parse_grammar("p --> a(3)\na(n) : n > 0 --> split(x){ ~1 : I(rect) | ~1 : a(n - 2) }\na(n) --> nil")));
}

TEST(Structural, EveryNodesHashAtOnceIsEachNodesOwn) {
  // A recursive rule, calls, repeats and choices: every node's hash taken
  // at once is what structural_hash gives it alone.
  const Grammar g = parse_grammar(
      "a --> split(x){ ~1 : b | ~2 : repeat(z, 3){ I(window) } }\n"
      "b --> split(y){ 1 : I(rect) | ~1 : a } : 2\n"
      "b --> I(roof)\n");
  const std::vector<std::size_t> all = structural_hashes(g);
  ASSERT_EQ(all.size(), g.node_count());
  for (NodeId id = 0; id < g.node_count(); ++id) EXPECT_EQ(all[id], structural_hash(g, id)) << id;
}

}  // namespace
}  // namespace vern
