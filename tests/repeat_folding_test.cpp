// Folding runs of equal parts and repeating patterns into stretching
// repeats, on examples' split graphs.
#include "inverse/repeat_folding.hpp"

#include <gtest/gtest.h>

#include "forward/derive.hpp"
#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "support/derive_helpers.hpp"

namespace vern {
namespace {

// A grammar's text on one line: runs of white space as one space.
std::string flat(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const bool space = c == ' ' || c == '\n';
    if (!(space && !out.empty() && out.back() == ' ')) out += space ? ' ' : c;
  }
  return out;
}

// Folds the start rule's body of a grammar text; returns the result written.
std::string folded(const std::string& text, double tolerance = 1e-6) {
  Grammar g = parse_grammar(text);
  g.rules[0].body = fold_repeats(g, g.rules[0].body, tolerance);
  return flat(write_grammar(g));
}

// The tile sizes written are the shortest decimals just above the tiles
// (3.02 for 3 tiles of 3): a size of exactly 3 would make a fourth tile
// once rounding lengthens the row by a hair.
TEST(RepeatFolding, APeriodicRowBecomesARepeatedTile) {
  const std::string out = folded("a --> split(x){ ~1 : I(rect) | ~2 : I(window) | ~1 : I(rect) | ~2 : I(window) | ~1 : I(rect) | ~2 : I(window) }\n");
  EXPECT_NE(out.find("a --> repeat(x, 3.02){ split(x){ ~1 : I(rect) | ~2 : I(window) } }"), std::string::npos) << out;
}

TEST(RepeatFolding, EndWallsStayAroundTheRun) {
  const std::string out =
      folded("a --> split(x){ ~0.5 : I(wall) | ~2 : I(window) | ~2 : I(window) | ~2 : I(window) | ~0.5 : I(wall) }\n");
  EXPECT_NE(out.find("split(x){ ~0.5 : I(wall) | ~6 : repeat(x, 2.01){ I(window) } | ~0.5 : I(wall) }"), std::string::npos)
      << out;
}

TEST(RepeatFolding, WallWindowWallIsATileAndAWall) {
  const std::string out =
      folded("a --> split(x){ ~1 : I(wall) | ~2 : I(window) | ~1 : I(wall) | ~2 : I(window) | ~1 : I(wall) }\n");
  EXPECT_NE(out.find("~6 : repeat(x, 3.02){ split(x){ ~1 : I(wall) | ~2 : I(window) } } | ~1 : I(wall)"), std::string::npos)
      << out;
}

TEST(RepeatFolding, AMixedRowIsLeftForMerging) {
  const std::string text = "a --> split(x){ ~1 : I(a) | ~1 : I(b) | ~1 : I(c) | ~1 : I(c) | ~1 : I(a) | ~1 : I(b) }\n";
  EXPECT_EQ(folded(text), flat(write_grammar(parse_grammar(text))));
}

TEST(RepeatFolding, NoiseWithinTheToleranceFoldsAndTheResultDerivesTheSameCuts) {
  const std::string text =
      "a --> split(x){ ~2.0000001 : I(w) | ~1.9999999 : I(w) | ~2.0000002 : I(w) | ~1.9999998 : I(w) }\n";
  Grammar g = parse_grammar(text);
  g.rules[0].body = fold_repeats(g, g.rules[0].body, 1e-6);
  EXPECT_TRUE(std::holds_alternative<Repeat>(g.op(g.rules[0].body)));
  const Derivation before = test::derive_text(text, {8, 1, 1});
  DeriveOptions o;
  o.size = glm::dvec3(8, 1, 1);
  const Derivation after = derive(g, o);
  ASSERT_EQ(after.terminals.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(after.terminals[i].scope.origin.x, before.terminals[i].scope.origin.x, 1e-6);
  }
}

TEST(RepeatFolding, DifferentSizesDoNotFold) {
  const std::string text = "a --> split(x){ ~1 : I(w) | ~1.5 : I(w) | ~1 : I(w) }\n";
  EXPECT_EQ(folded(text), flat(write_grammar(parse_grammar(text))));
}

TEST(RepeatFolding, AdjacentEmptyPartsJoin) {
  const std::string out = folded("a --> split(x){ ~1 : I(a) | ~1 : nil | ~2 : nil | ~1 : I(b) }\n");
  EXPECT_NE(out.find("split(x){ ~1 : I(a) | ~3 : nil | ~1 : I(b) }"), std::string::npos) << out;
}

}  // namespace
}  // namespace vern
