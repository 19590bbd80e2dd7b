// Alternatives that other alternatives already derive (subsumed_options.hpp).
#include "inverse/merge/subsumed_options.hpp"

#include <gtest/gtest.h>

#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "inverse/infer.hpp"
#include "support/derive_helpers.hpp"
#include "support/example_helpers.hpp"

namespace vern {
namespace {

// Rows of bays, as examples: `doors` says which of the bays hold a door.
Example row(const std::vector<bool>& doors, const std::string& name) {
  std::string text = "r --> split(x){";
  for (std::size_t i = 0; i < doors.size(); ++i)
    text += std::string(i ? " |" : "") + " ~1 : I(wall) | ~1.5 : I(" + (doors[i] ? "door" : "window") + ") | ~1 : I(wall)";
  text += " }\n";
  const double width = 3.5 * static_cast<double>(doors.size());
  return test::example_of(test::derived_parts(test::derive_text(text, {width, 1, 3})), name);
}

std::vector<Example> rows() {
  return {row({false, true, false, false, true}, "two_doors.obj"), row({true, false, false, true}, "ends.obj"),
          row({false, false, true, false}, "one_door.obj")};
}

// A repeat of bays each a window or a door, beside a row split around its
// one door bay: the one-door row derives from the repeat, so the split
// goes, its weight with the repeat. Listed first, the split is what the
// one-door row's witness takes (an alternative examples take, tried
// without); listed second, no witness takes it (dropped as it stands).
TEST(SubsumedOptions, ARowTheRepeatAlsoDerivesIsDropped) {
  const std::string repeat = "building --> repeat(x, 3.5){ bay } : 2\n";
  const std::string split =
      "building --> split(x){ ~7 : repeat(x, 3.5){ bay } | ~3.5 : doorBay | ~3.5 : repeat(x, 3.5){ bay } } : 1\n";
  const std::string rest =
      "bay --> split(x){ ~1 : I(wall) | 1.5 : opening | ~1 : I(wall) }\n"
      "opening --> I(window) : 8\n"
      "opening --> I(door) : 4\n"
      "doorBay --> split(x){ ~1 : I(wall) | 1.5 : I(door) | ~1 : I(wall) }\n";
  for (const std::string& text : {split + repeat + rest, repeat + split + rest}) {
    Grammar g = parse_grammar(text);
    Witnesses witnesses;
    EXPECT_EQ(drop_subsumed_options(g, rows(), {}, witnesses), 1u) << text;
    EXPECT_EQ(write_grammar(g),
              "building --> repeat(x, 3.5){ bay }\n"
              "bay --> split(x){ ~1 : I(wall) | 1.5 : opening | ~1 : I(wall) }\n"
              "opening --> I(window) : 8\n"
              "opening --> I(door) : 4\n")
        << text;
    std::vector<CheckResult> results;
    EXPECT_TRUE(derives_examples(g, rows(), {}, results));
  }
}

// Windows and doors both needed: nothing is dropped, and the grammar is
// as it was.
TEST(SubsumedOptions, AlternativesEachNeededStay) {
  const std::string text =
      "building --> repeat(x, 3.5){ bay }\n"
      "bay --> split(x){ ~1 : I(wall) | 1.5 : opening | ~1 : I(wall) }\n"
      "opening --> I(window) : 8\n"
      "opening --> I(door) : 4\n";
  Grammar g = parse_grammar(text);
  Witnesses witnesses;
  EXPECT_EQ(drop_subsumed_options(g, rows(), {}, witnesses), 0u);
  EXPECT_EQ(write_grammar(g), write_grammar(parse_grammar(text)));
}

// Bays each a window or a door, learnt from 30 rows: one repeat of bays,
// no row split around a lone door bay, and every variant the source's.
TEST(SubsumedOptions, BaysEachAWindowOrADoorAreLearntAsOneRow) {
  const Grammar source = parse_grammar(R"(
@start plot
@scope rand(26, 35.5), 1, 3
plot --> repeat(x, 3.6){ bay }
bay --> split(x){ ~1 : I(wall) | 1.5 : I(window) | ~1 : I(wall) } : 2
bay --> split(x){ ~1 : I(wall) | 1.5 : I(door) | ~1 : I(wall) } : 1
)",
                                       "bays.grm");
  const Inference inferred = infer(test::derived_examples(source, 30), {});
  const Grammar& g = inferred.grammar;
  EXPECT_TRUE(std::holds_alternative<Call>(g.op(g.rules[g.start_rule].body)) ||
              std::holds_alternative<Repeat>(g.op(g.rules[g.start_rule].body)))
      << write_grammar(g);
  EXPECT_TRUE(test::source_derives_variants(source, g, 101, 140));
}

}  // namespace
}  // namespace vern
