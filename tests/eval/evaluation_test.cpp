// The inference round trip as evaluate reports it, on bundled grammars.
#include "eval/evaluation.hpp"

#include <gtest/gtest.h>

#include "graph/parser.hpp"

namespace vern {
namespace {

Grammar bundled(const std::string& name) {
  return read_grammar_file(std::string(VERN_SOURCE_DIR) + "/data/grammars/" + name + ".grm");
}

TEST(Evaluation, GarageRoundTripReproducesAndVaries) {
  EvaluationOptions o;
  o.examples = 10;
  o.variants = 50;
  o.threads = 1;
  const Evaluation e = evaluate_inference(bundled("garage"), o);
  EXPECT_EQ(e.reproduced, 10u) << e.first_unreproduced;
  EXPECT_EQ(e.valid, 50u) << e.first_fault;
  EXPECT_EQ(e.source_valid, 50u);
  EXPECT_TRUE(e.source_varies);
  EXPECT_GE(e.novel, 45u);
  EXPECT_EQ(e.distance.structure, 0.0);  // two sides, one garage each, like the source
  EXPECT_LT(e.distance.sizes, 0.02);
  EXPECT_LE(e.inferred.rules, 5u);
  EXPECT_NE(e.inferred_text.find("building -->"), std::string::npos);
}

TEST(Evaluation, AGrammarThatNeverVariesHasNoNovelty) {
  EvaluationOptions o;
  o.examples = 3;
  o.variants = 10;
  o.threads = 1;
  const Evaluation e = evaluate_inference(bundled("cube_skeleton"), o);
  EXPECT_EQ(e.reproduced, 3u);
  EXPECT_FALSE(e.source_varies);
  EXPECT_EQ(e.novel, 0u);  // every variant is the one building
  EXPECT_EQ(e.distance.sizes, 0.0);
}

}  // namespace
}  // namespace vern
