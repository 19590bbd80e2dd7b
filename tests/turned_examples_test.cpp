// Whole buildings turned a quarter about z (turned_examples.hpp).
#include "inverse/load/turned_examples.hpp"

#include <gtest/gtest.h>

#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "inverse/check/check.hpp"
#include "inverse/infer.hpp"
#include "inverse/load/derived_example.hpp"
#include "support/example_helpers.hpp"

namespace vern {
namespace {

using test::part;

// An L: a range along x, a wing at its left end reaching along y.
Example l_house(double width, double depth, std::string source) {
  return test::example_of(test::numbered({part("rect", {0, 0, 0}, {width, 4, 3}),
                                          part("roof", {0, 4, 0}, {4, depth, 3})}),
                          std::move(source));
}

TEST(TurnedExamples, AQuarterTurnTurnsBoxesCounterclockwise) {
  const Example e = test::example_of({part("rect", {1, 2, 0}, {3, 7, 5})});
  const Example t = turned_example(e, 1);
  // (x, y) -> (-y, x): x from -7 to -2, y from 1 to 3.
  EXPECT_EQ(t.boxes[0].min, glm::dvec3(-7, 1, 0));
  EXPECT_EQ(t.boxes[0].max, glm::dvec3(-2, 3, 5));
  EXPECT_EQ(turned_example(t, 3).boxes[0].min, e.boxes[0].min);
}

// Whether some alternative of g's start is a quarter turn about z of a
// split (reached through the calls inference writes): the turn written.
bool writes_the_turn(const Grammar& g) {
  auto through_calls = [&](NodeId n) {
    while (const auto* call = std::get_if<Call>(&g.op(n))) n = g.rules[call->rule].body;
    return n;
  };
  const auto* start = std::get_if<Choose>(&g.op(g.rules[g.start_rule].body));
  if (!start) return false;
  for (const auto& o : start->options) {
    const auto* turn = std::get_if<Rotate>(&g.op(o.child));
    if (turn && write_grammar(g).find("R(z, pi / 2){") != std::string::npos &&
        std::holds_alternative<Split>(g.op(through_calls(turn->child))))
      return true;
  }
  return false;
}

// common_orientation with each example cut as it is.
std::vector<int> orientation(const std::vector<Example>& examples) {
  std::vector<SplitTree> trees;
  for (const Example& e : examples) trees.push_back(split_boxes(e.boxes, BoxSplitOptions{1e-6}, e.source));
  return common_orientation(examples, trees, 1e-6);
}

TEST(TurnedExamples, TheOddOneTurnedAQuarterIsTurnedBack) {
  std::vector<Example> examples{l_house(12, 10, "a.obj"), l_house(15, 9, "b.obj"), l_house(10, 12, "c.obj")};
  examples.push_back(turned_example(l_house(14, 11, "d.obj"), 1));
  examples.push_back(turned_example(l_house(11, 10, "e.obj"), 3));
  const std::vector<int> q = orientation(examples);
  EXPECT_EQ(q, (std::vector<int>{0, 0, 0, 3, 1}));
  // Alike as they are, or with no turn that makes them alike: left alone.
  EXPECT_EQ(orientation({l_house(12, 10, "a"), l_house(15, 9, "b")}), (std::vector<int>{0, 0}));
}

// A house of `bays` bays along x, each a pier, a column of wall, window
// and wall, and a pier, in front of its body; the roof on top.
Example bay_house(int bays, std::string source) {
  std::vector<LabelledBox> boxes = {part("wall", {0, 0.2, 0}, {2.4 * bays, 5, 3}),
                                    part("roof", {0, 0, 3}, {2.4 * bays, 5, 4.5})};
  for (int i = 0; i < bays; ++i) {
    const double x = 2.4 * i;
    boxes.push_back(part("wall", {x, 0, 0}, {x + 0.7, 0.2, 3}));
    boxes.push_back(part("wall", {x + 0.7, 0, 0}, {x + 1.7, 0.2, 1}));
    boxes.push_back(part("window", {x + 0.7, 0, 1}, {x + 1.7, 0.2, 2.2}));
    boxes.push_back(part("wall", {x + 0.7, 0, 2.2}, {x + 1.7, 0.2, 3}));
    boxes.push_back(part("wall", {x + 1.7, 0, 0}, {x + 2.4, 0.2, 3}));
  }
  return test::example_of(test::numbered(boxes), std::move(source));
}

// Houses of 2, 3 and 4 bays, two of them turned a quarter: their rows of
// bays are one layout whatever their count, so the odd one is turned to
// the others'. Bays of pier, window and pier, each row a run of groups of
// three pieces, were three layouts, and nothing was turned.
TEST(TurnedExamples, RowsOfBaysOfAnyCountAreOneLayout) {
  const std::vector<Example> examples{bay_house(2, "a.obj"), turned_example(bay_house(3, "b.obj"), 1),
                                      turned_example(bay_house(4, "c.obj"), 1)};
  EXPECT_EQ(orientation(examples), (std::vector<int>{1, 0, 0}));
}

TEST(TurnedExamples, InferenceWritesTheTurnAndDerivesEveryExample) {
  // Houses modelled facing either way (the style's own R(z, pi / 2)).
  const Grammar source = read_grammar_file(std::string(VERN_SOURCE_DIR) + "/data/styles/dev/turned_houses.grm");
  std::vector<Example> examples = test::derived_examples(source, 12);
  InferOptions o;
  o.threads = 1;
  const Inference learnt = infer(examples, o);
  const std::string text = write_grammar(learnt.grammar);
  EXPECT_TRUE(writes_the_turn(learnt.grammar)) << text;
  for (const Example& e : examples) {
    const Example placed = at_origin(e);
    EXPECT_TRUE(check_example(learnt.grammar, placed.boxes, example_size(placed)).derivable) << e.source;
  }
}

// On two threads, turned buildings are looked for on one while the other
// builds and merges the graphs of the examples as they are; a turn found
// drops those graphs and makes them again. The grammar and warnings are
// those of one thread, where the looking comes first and nothing is made
// twice.
TEST(TurnedExamples, TheGrammarIsTheSameOnOneThreadAsOnTwo) {
  const Grammar source = read_grammar_file(std::string(VERN_SOURCE_DIR) + "/data/styles/dev/turned_houses.grm");
  const std::vector<Example> examples = test::derived_examples(source, 12);
  InferOptions one;
  one.threads = 1;
  InferOptions two;
  two.threads = 2;
  const Inference a = infer(examples, one), b = infer(examples, two);
  const std::string text = write_grammar(a.grammar);
  EXPECT_TRUE(writes_the_turn(a.grammar)) << text;  // a turn was found
  EXPECT_EQ(text, write_grammar(b.grammar));
  EXPECT_EQ(a.warnings, b.warnings);
}

}  // namespace
}  // namespace vern
