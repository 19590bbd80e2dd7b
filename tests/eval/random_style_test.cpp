// Random styles (issue 23, item 4): deterministic, each class at its rate,
// and every style a fair judge of its own buildings.
#include "eval/random_style.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <set>
#include <thread>

#include "eval/precision_recall.hpp"
#include "forward/layout_faults.hpp"
#include "graph/parser.hpp"
#include "support/derive_helpers.hpp"

namespace vern {
namespace {

// The seeds of a run, as evaluate --random-styles makes them.
std::vector<std::uint64_t> run_seeds(std::uint64_t run_seed, std::uint32_t count) {
  std::vector<std::uint64_t> seeds;
  for (std::uint32_t i = 0; i < count; ++i) seeds.push_back(random_style_seed(run_seed, i));
  return seeds;
}

TEST(RandomStyle, TheSameSeedGivesTheSameTextAndOthersDiffer) {
  const std::vector<std::uint64_t> seeds = run_seeds(7, 300);
  std::vector<std::string> texts;
  for (std::uint64_t s : seeds) texts.push_back(random_style(s).text);
  // Again, on another thread, in the reverse order: nothing carries over
  // from one style to the next.
  std::vector<std::string> again(seeds.size());
  std::thread([&] {
    for (std::size_t i = seeds.size(); i-- > 0;) again[i] = random_style(seeds[i]).text;
  }).join();
  EXPECT_EQ(texts, again);
  EXPECT_EQ(std::set<std::string>(texts.begin(), texts.end()).size(), texts.size()) << "two seeds gave one style";
  // Style i of a run differs from style i of the next run's seed.
  EXPECT_NE(random_style(random_style_seed(8, 0)).text, texts[0]);
  EXPECT_NE(random_style_seed(7, 1), random_style_seed(8, 0));
}

TEST(RandomStyle, EachClassAppearsAtItsRate) {
  const std::vector<std::uint64_t> seeds = run_seeds(11, 300);
  std::array<int, kStyleClasses.size()> seen{};
  for (std::uint64_t s : seeds)
    for (StyleClass c : random_style(s).classes) ++seen[static_cast<std::size_t>(c)];
  for (std::size_t i = 0; i < kStyleClasses.size(); ++i) {
    // 300 draws at 0.4: a standard deviation of 0.028; 0.08 is three of them.
    const double rate = seen[i] / 300.0;
    EXPECT_NEAR(rate, kStyleClasses[i].rate, 0.08) << kStyleClasses[i].name;
  }
}

// What each class writes, read back from the text: a class is listed if and
// only if the style composes it (for the classes whose construct no other
// class writes; the others only one way).
bool contains(const std::string& text, const char* pattern) { return std::regex_search(text, std::regex(pattern)); }

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

// The tiles of the repeats along x and y.
std::vector<std::string> tiles(const std::string& text) {
  std::vector<std::string> found;
  const std::regex tile(R"(repeat\([xy], ([0-9.]+)\))");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), tile); it != std::sregex_iterator(); ++it)
    found.push_back((*it)[1]);
  return found;
}

TEST(RandomStyle, EachListedClassIsInTheText) {
  for (std::uint64_t s : run_seeds(3, 300)) {
    const RandomStyle style = random_style(s);
    const std::string rules = style.text.substr(style.text.find("\n\n"));
    auto iff = [&](StyleClass c, bool shown) { EXPECT_EQ(style.has(c), shown) << class_name(c) << "\n" << style.text; };
    auto implies = [&](StyleClass c, bool shown) {
      if (style.has(c)) {
        EXPECT_TRUE(shown) << class_name(c) << "\n" << style.text;
      }
    };
    // A plan taking the size drawn once by the start rule.
    iff(StyleClass::SharedSize, contains(rules, R"(\w+\([dh]\) --> )"));
    iff(StyleClass::LinearSize, contains(rules, R"( [0-9.]+ \* u \+ [0-9.]+ : repeat\(z)"));
    iff(StyleClass::ConstantInVarying, contains(rules, R"(I\((cornice|slab|band|ledge)\))") ||
                                           contains(rules, R"(split\(x\)\{ [0-9.]+ : I\(\w+\) \| ~1 : (?!I\()\w+)"));
    const std::vector<std::string> t = tiles(rules);
    const std::size_t kinds = std::set<std::string>(t.begin(), t.end()).size();
    if (style.has(StyleClass::SharedTile)) {
      EXPECT_EQ(kinds, 1u) << style.text;
      EXPECT_GE(t.size(), 2u) << style.text;
    } else if (contains(rules, "(annexRoof|lowRoof|sideRoof)")) {  // annexes, of their own tile
      EXPECT_GE(kinds, 2u) << style.text;
    }
    // The storeys called with the door's index, k.
    iff(StyleClass::AlignedRepeat, contains(rules, R"(\{ \w+\(k(, b)?\) \})"));
    // A run with a special tile: two for the aligned door and the storeys
    // above it, one for a special tile.
    EXPECT_EQ(count(rules, " * k : repeatN("),
              (style.has(StyleClass::AlignedRepeat) ? 2u : 0u) + (style.has(StyleClass::SpecialTile) ? 1u : 0u))
        << style.text;
    iff(StyleClass::RecursiveTiers, contains(rules, R"(\(n\) : n > 1 --> .*\(n - 1\))"));
    iff(StyleClass::KeptChoice, contains(rules, R"(\(b\) : b == 1 --> )"));
    iff(StyleClass::ContinuousSizes, contains(rules, R"((~|\| |\{ )(rand|tnormal)\()"));
    implies(StyleClass::MixedSplit, contains(rules, R"(\| [0-9.]+ : (split\(z\)|I\())"));
    // Alternatives with priorities: the roof's kinds, and, a choice per
    // tile, the bays' (a split along x).
    iff(StyleClass::Alternatives, contains(rules, R"(--> (?!split\(x\))[^\n]*(\}|\)) : [0-9]+\n)"));
    iff(StyleClass::TileChoice, contains(rules, R"(--> split\(x\)\{[^\n]*\} : [0-9]+\n)"));
    iff(StyleClass::TurnedRoof, contains(rules, R"(R\(z, pi / 2\))"));
    iff(StyleClass::GroundFloor, contains(rules, R"(I\((shopfront|display|vitrine|glass)\))"));
    iff(StyleClass::Wings, contains(rules, R"(repeat(N)?\(y, )"));
    implies(StyleClass::NilGap, contains(rules, R"( : nil)"));
  }
}

// Every style derives valid buildings that fill their plot, and derives its
// own buildings on their extents: it can judge precision and recall.
TEST(RandomStyle, StylesMakeValidBuildingsAndJudgeThemselves) {
  PrecisionRecallOptions o;
  o.samples = 3;
  o.threads = 1;
  double smallest = 1e9;
  std::string smallest_at;
  for (std::uint64_t s : run_seeds(5, 200)) {
    const RandomStyle style = random_style(s);
    const Grammar g = parse_grammar(style.text, "style");
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      DeriveOptions d;
      d.seed = seed;
      const Derivation building = derive(g, d);
      ASSERT_TRUE(building.warnings.empty()) << building.warnings.front() << "\n" << style.text;
      const LayoutFaults f = find_faults(building);
      EXPECT_TRUE(f.valid()) << f.first << "\n" << style.text;
      glm::dvec3 lo(1e300), hi(-1e300);
      for (const test::LabelledBox& b : test::boxes(building)) {
        lo = glm::min(lo, b.min);
        hi = glm::max(hi, b.max);
        const glm::dvec3 size = b.max - b.min;
        const double least = std::min({size.x, size.y, size.z});
        if (least < smallest) {
          smallest = least;
          smallest_at = b.label + " in style seed " + std::to_string(s);
        }
      }
      const glm::dvec3 plot = building.start.size;
      for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(lo[a], 0, 1e-9 * plot[a]) << "axis " << a << "\n" << style.text;
        EXPECT_NEAR(hi[a], plot[a], 1e-9 * plot[a]) << "axis " << a << "\n" << style.text;
      }
    }
    const Share self = self_recall(g, o);
    EXPECT_EQ(self.hits, self.total) << self.first_miss << "\n" << style.text;
  }
  // Nothing squeezed to nothing: parts in metres fit their containers, so
  // the thinnest part is a pillar or lintel, at most halved by a stretched
  // tile (0.125 m over these styles).
  EXPECT_GE(smallest, 0.05) << smallest_at;
}

}  // namespace
}  // namespace vern
