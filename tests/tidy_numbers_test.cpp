// tidy_numbers: relative sizes as small whole ratios where they have
// them, beside absolute parts too, and the same lengths derived.
#include "inverse/sizes/tidy_numbers.hpp"

#include <gtest/gtest.h>

#include <string>

#include "forward/derive.hpp"
#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "support/example_graphs.hpp"
#include "support/example_helpers.hpp"

namespace vern {
namespace {

// The start rule's body tidied with a tolerance of 1e-6 m.
Grammar tidied(const std::string& text) {
  Grammar g = parse_grammar(text, "tidy.grm");
  g.rules[g.start_rule].body = tidy_numbers(g, g.rules[g.start_rule].body, 1e-6);
  return g;
}

TEST(TidyNumbers, RelativeSizesBesideAnAbsoluteOneBecomeWholeRatios) {
  // 0.40383... and 0.80766... metres of one example, in the ratio 1 : 2.
  const std::string source = R"(
@scope 5, 1, 1
b --> split(x){ ~0.4038333333333333 : I(a) | 1.2 : I(b) | ~0.8076666666666666 : I(a) }
)";
  const Grammar g = tidied(source);
  const std::string text = write_grammar(g);
  EXPECT_NE(text.find("split(x){ ~1 : I(a) | 1.2 : I(b) | ~2 : I(a) }"), std::string::npos) << text;
  EXPECT_TRUE(test::same_boxes(test::derived_parts(derive(parse_grammar(source), {})),
                               test::derived_parts(derive(g, {})), 1e-9));
}

TEST(TidyNumbers, AllRelativeSizesBecomeWholeRatios) {
  const Grammar g = tidied("b --> split(x){ ~6.666666666666667 : I(a) | ~3.3333333333333335 : I(b) }");
  EXPECT_NE(write_grammar(g).find("split(x){ ~2 : I(a) | ~1 : I(b) }"), std::string::npos) << write_grammar(g);
}

TEST(TidyNumbers, RelativeSizesWithoutWholeRatiosKeepTheirDecimals) {
  // 0.41 : 0.8 is 41 : 80, beyond the 60 units a person would write.
  const Grammar g = tidied("b --> split(x){ ~0.4100000000000001 : I(a) | 1.2 : I(b) | ~0.8 : I(a) }");
  EXPECT_NE(write_grammar(g).find("split(x){ ~0.41 : I(a) | 1.2 : I(b) | ~0.8 : I(a) }"), std::string::npos)
      << write_grammar(g);
}

TEST(TidyNumbers, AlternativesWrittenAlikeAreOne) {
  // Two houses on plots 19.4 and 25.1 m wide, kept apart by merging (their
  // middles lie far apart), whose middle is the lone share: written ~1 in
  // both, they are one alternative, seen twice.
  Grammar g;
  const auto roots = test::example_graphs(g, {"split(x){ 0.5 : I(a) | ~18.4 : I(b) | 0.5 : I(a) }",
                                              "split(x){ 0.5 : I(a) | ~24.1 : I(b) | 0.5 : I(a) }", "I(c)"});
  Choose c;
  for (const NodeId r : roots) c.options.push_back({Expr{}, Expr::number(1), r});
  const NodeId tidied = tidy_numbers(g, g.intern({std::move(c), {}}), 1e-6);
  const auto& options = std::get<Choose>(g.op(tidied)).options;
  ASSERT_EQ(options.size(), 2u);
  EXPECT_EQ(write_operation(g, options[0].child, {}), "split(x){ 0.5 : I(a) | ~1 : I(b) | 0.5 : I(a) }");
  EXPECT_EQ(options[0].priority.literal(), 2.0);
  EXPECT_EQ(write_operation(g, options[1].child, {}), "I(c)");
}

}  // namespace
}  // namespace vern
