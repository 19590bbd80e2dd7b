// Rows whose tiles follow a progression become a recursion with the step
// (progressions.hpp).
#include "inverse/sizes/progressions.hpp"

#include <gtest/gtest.h>

#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "inverse/check/check.hpp"
#include "inverse/load/derived_example.hpp"
#include "support/derive_helpers.hpp"
#include "support/example_helpers.hpp"

namespace vern {
namespace {

// Rows of 3 to 5 blocks 4 m wide, each 0.8 as high as the one before.
const char* const kSteps =
    "row(h, n) : n > 1 --> split(x){ 4 : block(h) | ~1 : row(0.8 * h, n - 1) }\n"
    "row(h, n) : n <= 1 --> block(h)\n"
    "block(h) --> split(z){ ~h : I(rect) | ~(1 - h) : nil }\n";

std::vector<Example> rows() {
  std::vector<Example> out;
  for (int n = 3; n <= 5; ++n) {
    const std::string text = std::string("@start start\nstart --> row(1, ") + std::to_string(n) + ")\n" + kSteps;
    out.push_back(test::example_of(test::derived_parts(test::derive_text(text, {4.0 * n, 2, 10})),
                                   "row" + std::to_string(n) + ".obj"));
  }
  return out;
}

TEST(Progressions, ARepeatOfHeightsSeenInOrderIsTheirRecursion) {
  // What merging writes: a repeat of blocks, each of the heights seen.
  Grammar g = parse_grammar(
      "building --> repeat(x, 4.01){ blockChoice }\n"
      "blockChoice --> I(rect) : 3\n"
      "blockChoice --> split(z){ ~1 : I(rect) | ~choice(0.25, 0.5625, 0.953125, 1.441406) : nil } : 9\n");
  EXPECT_EQ(fold_progressions(g, rows(), {}), 1u) << write_grammar(g);
  const std::string text = write_grammar(g);
  EXPECT_NE(text.find("building --> rectZRow(1)"), std::string::npos) << text;
  EXPECT_NE(text.find("4 : rectZ(s1) |"), std::string::npos) << text;
  EXPECT_NE(text.find("~1 : rectZRow(0.8 * s1)"), std::string::npos) << text;
  for (const Example& e : rows()) {
    const Example placed = at_origin(e);
    EXPECT_TRUE(check_example(g, placed.boxes, example_size(placed)).derivable) << e.source;
  }
}

TEST(Progressions, HeightsInAnyOrderStayAChoice) {
  // The same heights, but the examples have them out of order.
  std::vector<Example> shuffled = rows();
  for (Example& e : shuffled) std::swap(e.boxes[1].max.z, e.boxes[2].max.z);
  Grammar g = parse_grammar(
      "building --> repeat(x, 4.01){ blockChoice }\n"
      "blockChoice --> I(rect) : 3\n"
      "blockChoice --> split(z){ ~1 : I(rect) | ~rand(0.1, 2) : nil } : 9\n");
  const std::string before = write_grammar(g);
  EXPECT_EQ(fold_progressions(g, shuffled, {}), 0u);
  EXPECT_EQ(write_grammar(g), before);
}

}  // namespace
}  // namespace vern
