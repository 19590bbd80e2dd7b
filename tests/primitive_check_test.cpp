// Warnings for the primitives a grammar inserts that the library lacks.
#include "forward/primitive_check.hpp"

#include <gtest/gtest.h>

#include <string>

#include "graph/parser.hpp"

namespace vern {
namespace {

TEST(PrimitiveCheck, WarnsOncePerUnknownNameWithAHint) {
  const Grammar g =
      parse_grammar("p --> split(x){ ~1 : I(widow) | ~1 : I(widow) | ~1 : I(rect) | ~1 : I(qqq) }", "g.grm");
  const std::vector<std::string> w = unknown_primitive_warnings(g, PrimitiveLibrary::builtin());
  ASSERT_EQ(w.size(), 2u);
  EXPECT_NE(w[0].find("g.grm:1:22: warning: unknown primitive 'widow'"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("did you mean 'window'?"), std::string::npos) << w[0];
  EXPECT_NE(w[1].find("the known primitives are: corner, door"), std::string::npos) << w[1];
}

// Past 100 unknown names the primitives are missing, not misspelt: the
// warnings list the known ones, with no name compared against them all.
TEST(PrimitiveCheck, ManyUnknownNamesAreNotComparedWithEveryKnownOne) {
  // wind + two letters: each two edits from window at most.
  const auto name = [](int i) {
    return "wind" + std::string{static_cast<char>('a' + i / 26), static_cast<char>('a' + i % 26)};
  };
  std::string text = "p --> split(x){ ~1 : I(" + name(0) + ")";
  for (int i = 1; i <= 100; ++i) text += " | ~1 : I(" + name(i) + ")";
  const Grammar g = parse_grammar(text + " }", "g.grm");
  const std::vector<std::string> w = unknown_primitive_warnings(g, PrimitiveLibrary::builtin());
  ASSERT_EQ(w.size(), 101u);
  EXPECT_NE(w[99].find("did you mean 'window'?"), std::string::npos) << w[99];
  EXPECT_EQ(w[100].find("did you mean"), std::string::npos) << w[100];
  EXPECT_NE(w[100].find("unknown primitive 'winddw'"), std::string::npos) << w[100];
  EXPECT_NE(w[100].find("the known primitives are: corner, door"), std::string::npos) << w[100];
}

}  // namespace
}  // namespace vern
