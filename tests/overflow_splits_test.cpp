// A split and its overflow are one split (overflow_splits.hpp).
#include "inverse/sizes/overflow_splits.hpp"

#include <gtest/gtest.h>

#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "support/derive_helpers.hpp"
#include "support/example_helpers.hpp"

namespace vern {
namespace {

// A storey of a fixed sill and window under a head of what is left, on 3 m
// and on 2 m (where the sill and window shrink to fit and the head is not
// made), as examples.
std::vector<Example> storeys() {
  const std::string source = "s --> split(z){ 0.9 : I(rect) | 1.5 : I(window) | ~1 : I(roof) }\n";
  return {test::example_of(test::derived_parts(test::derive_text(source, {1, 1, 3})), "tall.obj"),
          test::example_of(test::derived_parts(test::derive_text(source, {1, 1, 2})), "short.obj")};
}

TEST(OverflowSplits, AShortStoreyIsTheStoreyOverflowing) {
  Grammar g = parse_grammar(
      "building --> split(z){ 0.9 : I(rect) | 1.5 : I(window) | ~1 : I(roof) } : 2\n"
      "building --> split(z){ ~3 : I(rect) | ~5 : I(window) } : 1\n");
  EXPECT_EQ(unify_overflows(g, storeys(), {}), 1u);
  // One alternative left: the choice is gone.
  EXPECT_EQ(write_grammar(g), "building --> split(z){ 0.9 : I(rect) | 1.5 : I(window) | ~1 : I(roof) }\n");
}

TEST(OverflowSplits, OtherRatiosStayApart) {
  // 3 : 4 is no shrunk 0.9 : 1.5: nothing changes.
  const std::string text =
      "building --> split(z){ 0.9 : I(rect) | 1.5 : I(window) | ~1 : I(roof) } : 2\n"
      "building --> split(z){ ~3 : I(rect) | ~4 : I(window) } : 1\n";
  Grammar g = parse_grammar(text);
  EXPECT_EQ(unify_overflows(g, storeys(), {}), 0u);
  EXPECT_EQ(write_grammar(g), write_grammar(parse_grammar(text)));
}

TEST(OverflowSplits, AChangeThatLosesAnExampleIsUndone) {
  // The short storey really is 3 : 5 but its window is a door: the split
  // taken for the storey would not derive it.
  const std::string text =
      "building --> split(z){ 0.9 : I(rect) | 1.5 : I(window) | ~1 : I(roof) } : 2\n"
      "building --> split(z){ ~3 : I(rect) | ~5 : I(door) } : 1\n";
  Grammar g = parse_grammar(text);
  EXPECT_EQ(unify_overflows(g, storeys(), {}), 0u);
  EXPECT_EQ(write_grammar(g), write_grammar(parse_grammar(text)));
}

}  // namespace
}  // namespace vern
