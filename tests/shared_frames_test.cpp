// Alternatives that are the same split but at one place become one
// alternative with a choice there; alternatives differing at two stay.
#include "inverse/merge/shared_frames.hpp"

#include <gtest/gtest.h>

#include <map>

#include "forward/derive.hpp"
#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "inverse/check/check.hpp"
#include "inverse/infer.hpp"
#include "support/example_graphs.hpp"
#include "support/example_helpers.hpp"

namespace vern {
namespace {

TEST(SharedFrames, HousesDifferingInTheirGroundFloorShareOneFrame) {
  Grammar g;
  const auto r = test::example_graphs(g, {"split(z){ 0.5 : I(slab) | 4.5 : I(shop) | ~1 : I(storeys) }",
                                          "split(z){ 0.5 : I(slab) | 4.5 : I(hall) | ~1 : I(storeys) }",
                                          "split(z){ 0.5 : I(slab) | 4.5 : I(hall) | ~1 : I(attic) }",
                                          "split(z){ 0.5 : I(slab) | 4 : I(shop) | ~1 : I(storeys) }"});
  Choose c;
  const double weights[] = {2, 1, 4, 1};
  for (std::size_t k = 0; k < r.size(); ++k) c.options.push_back({Expr{}, Expr::number(weights[k]), r[k]});
  const NodeId before = g.intern({std::move(c), {}});
  const NodeId out = share_frames(g, before);
  // The same buildings as often: over 4,000 seeds each label's share of
  // the buildings is the same within sampling noise (shop 3/8 of them,
  // hall 5/8, attic 1/2).
  auto shares = [&](NodeId body) {
    Grammar d = g;
    d.rules = {Rule{"b", {}, body, {}}};
    d.start_rule = 0;
    std::map<std::string, double> seen;
    for (std::uint64_t seed = 1; seed <= 4000; ++seed) {
      DeriveOptions o;
      o.seed = seed;
      o.size = glm::dvec3(10, 10, 20);
      for (const auto& b : test::derived_parts(derive(d, o))) seen[b.label] += 1.0 / 4000;
    }
    return seen;
  };
  const auto was = shares(before), now = shares(out);
  for (const char* label : {"shop", "hall", "attic", "storeys"}) EXPECT_NEAR(now.at(label), was.at(label), 0.03) << label;
  EXPECT_NEAR(now.at("shop"), 3.0 / 8, 0.03);
  const auto& options = std::get<Choose>(g.op(out)).options;
  // The first two share all but the ground floor; the third differs from
  // the first at two places, and the fourth in a size.
  ASSERT_EQ(options.size(), 3u);
  EXPECT_EQ(options[0].priority.literal(), 3.0);
  const Split& frame = std::get<Split>(g.op(options[0].child));
  const auto& ground = std::get<Choose>(g.op(frame.parts[1].child)).options;
  ASSERT_EQ(ground.size(), 2u);
  EXPECT_EQ(write_operation(g, ground[0].child, {}), "I(shop)");
  EXPECT_EQ(ground[0].priority.literal(), 2.0);
  EXPECT_EQ(write_operation(g, ground[1].child, {}), "I(hall)");
  EXPECT_EQ(ground[1].priority.literal(), 1.0);
  EXPECT_EQ(frame.parts[2].child, std::get<Split>(g.op(r[0])).parts[2].child);
  EXPECT_EQ(options[1].child, r[2]);
  EXPECT_EQ(options[2].child, r[3]);
}

TEST(SharedFrames, AChoiceOfTwoThatBecomesOneFrameIsThatFrame) {
  Grammar g;
  const auto r = test::example_graphs(g, {"split(x){ 1 : I(a) | ~1 : I(b) }", "split(x){ 1 : I(a) | ~1 : I(c) }"});
  Choose c;
  for (const NodeId n : r) c.options.push_back({Expr{}, Expr::number(1), n});
  const NodeId out = share_frames(g, g.intern({std::move(c), {}}));
  ASSERT_TRUE(std::holds_alternative<Split>(g.op(out)));
  EXPECT_EQ(std::get<Choose>(g.op(std::get<Split>(g.op(out)).parts[1].child)).options.size(), 2u);
}

// The modern houses of the evaluation: ten examples, their ground floors
// built in many ways over a few kinds of storeys. No two alternatives of
// the inferred building are the same split but at one place, every example
// still derives.
TEST(SharedFrames, InferredHousesWriteEachFrameOnceAndStillDeriveEveryExample) {
  const Grammar source = read_grammar_file(VERN_SOURCE_DIR "/data/grammars/modern_houses.grm");
  const std::vector<Example> examples = test::derived_examples(source, 10);
  const Inference inferred = infer(examples, {});
  const Grammar& g = inferred.grammar;
  const std::string text = write_grammar(g);
  // The houses' alternatives: the start rule's, or those of the rule it
  // calls where their sizes are drawn once for all (joint_sizes.hpp).
  NodeId body = g.rules[g.start_rule].body;
  if (const auto* call = std::get_if<Call>(&g.op(body))) body = g.rules[call->rule].body;
  // (One alternative, where the others derived nothing it does not:
  // subsumed_options.hpp.)
  const Operation& start = g.op(body);
  const std::vector<ChooseOption> options =
      std::holds_alternative<Choose>(start) ? std::get<Choose>(start).options : std::vector<ChooseOption>{{{}, {}, body}};
  for (std::size_t i = 0; i < options.size(); ++i)
    for (std::size_t j = i + 1; j < options.size(); ++j) {
      const auto* a = std::get_if<Split>(&g.op(options[i].child));
      const auto* b = std::get_if<Split>(&g.op(options[j].child));
      if (!a || !b || a->axis != b->axis || a->parts.size() != b->parts.size()) continue;
      std::size_t differ = 0;
      for (std::size_t p = 0; p < a->parts.size(); ++p)
        differ += a->parts[p].size == b->parts[p].size && a->parts[p].child == b->parts[p].child ? 0 : 1;
      EXPECT_GE(differ, 2u) << i << " " << j << "\n" << text;
    }
  EXPECT_LE(options.size(), 3u) << text;
  for (const Example& e : examples) {
    const CheckResult r = check_example(g, e.boxes, example_size(e));
    EXPECT_TRUE(r.derivable) << r.mismatch << "\n" << text;
  }
}

}  // namespace
}  // namespace vern
