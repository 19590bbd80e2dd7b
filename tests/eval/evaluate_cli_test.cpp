// evaluate --random-styles as a user runs it: the seed is asked for, the
// styles can be written out for inspection, and the table per class prints.
#include <gtest/gtest.h>

#include <string>

#include "eval/random_style.hpp"
#include "support/run_command.hpp"

namespace vern {
namespace {

using test::TempFolder;

TEST(EvaluateCli, RandomStylesNeedASeedChosenWhenMeasuring) {
  const auto r = test::run_program("evaluate", {"--precision-recall", "--random-styles", "3"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("--random-styles needs --seed S, a seed chosen now and never tuned on"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("hint: --random-styles 3 --seed $(date +%s)"), std::string::npos) << r.err;
  // A seed without random styles is a mistake too, not ignored.
  const auto seed = test::run_program("evaluate", {"--precision-recall", "--random", "2", "--seed", "4"});
  EXPECT_EQ(seed.exit_code, 2) << seed.err;
  EXPECT_NE(seed.err.find("--seed goes with --random-styles"), std::string::npos) << seed.err;
}

TEST(EvaluateCli, RandomStylesAreWrittenAsTheGeneratorMakesThem) {
  TempFolder dir;
  const auto r =
      test::run_program("evaluate", {"--random-styles", "3", "--seed", "42", "--random-styles-write", "."}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(test::list_folder(dir.path()),
            (std::vector<std::string>{"random_style_0.grm", "random_style_1.grm", "random_style_2.grm"}));
  for (std::uint32_t i = 0; i < 3; ++i)
    EXPECT_EQ(test::read_file(dir / ("random_style_" + std::to_string(i) + ".grm")),
              random_style(random_style_seed(42, i)).text);
  // A folder that is not there: nothing written, an I/O error.
  const auto missing = test::run_program(
      "evaluate", {"--random-styles", "3", "--seed", "42", "--random-styles-write", "no_such_folder"}, dir.path());
  EXPECT_EQ(missing.exit_code, 5) << missing.err;
  EXPECT_EQ(test::list_folder(dir.path()).size(), 3u);
}

// The table's shape, not its figures: one row per class, one for all
// styles, and the count of styles at 0.25 or below at the largest N.
TEST(EvaluateCli, RandomStylesPrintATablePerClass) {
  const auto r = test::run_program("evaluate", {"--precision-recall", "--random-styles", "2", "--seed", "42",
                                                "--counts", "2,1", "--samples", "2", "--quiet"});
  EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.err;
  EXPECT_NE(r.out.find("| random_style_1 | 1 |"), std::string::npos) << r.out;
  const std::string header = "| class | styles | precision N = 2 | recall N = 2 | precision N = 1 | recall N = 1 |\n";
  const std::size_t table = r.out.find(header);
  ASSERT_NE(table, std::string::npos) << r.out;
  std::size_t at = r.out.find('\n', table + header.size()) + 1;  // past the |---| line
  for (const StyleClassInfo& c : kStyleClasses) {
    EXPECT_EQ(r.out.compare(at, c.name.size() + 4, "| " + std::string(c.name) + " |"), 0) << r.out.substr(at, 80);
    at = r.out.find('\n', at) + 1;
  }
  EXPECT_EQ(r.out.compare(at, 26, "| all random styles | 2 | "), 0) << r.out.substr(at, 80);
  EXPECT_NE(r.out.find("\nRandom styles with precision <= 0.25 at N = 2: "), std::string::npos) << r.out;
}

}  // namespace
}  // namespace vern

namespace vern {
namespace {

// evaluate --report: the table, and per grammar the source's buildings
// beside the learnt grammar's, with the learnt grammar.
TEST(EvaluateCli, AReportShowsEachGrammarsRoundTrip) {
  TempFolder dir;
  const std::string grammars = VERN_SOURCE_DIR "/data/grammars/";
  auto r = test::run_program("evaluate", {grammars + "garage.grm", grammars + "terrace.grm", "-k", "4", "-n", "10",
                                          "--report", "round.html", "--keep", "."},
                             dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string html = test::read_file(dir / "round.html");
  // The table has the printed table's rows: one per grammar.
  for (const char* name : {"garage", "terrace"}) {
    EXPECT_NE(html.find("<tr><td>" + std::string(name) + "</td>"), std::string::npos) << name;
    EXPECT_NE(html.find("<h2>" + std::string(name) + "</h2>"), std::string::npos) << name;
  }
  // Four examples and four variants a grammar, each a picture in the page.
  std::size_t pictures = 0;
  for (std::size_t at = 0; (at = html.find("src=\"data:image/png;base64,", at)) != std::string::npos; ++at) ++pictures;
  EXPECT_EQ(pictures, 16u);
  EXPECT_NE(html.find("seed 1001"), std::string::npos);
  // The learnt grammar shown is the one --keep wrote.
  const std::string kept = test::read_file(dir / "terrace.grm");
  const std::string first_line = kept.substr(0, kept.find('\n'));
  ASSERT_FALSE(first_line.empty());
  std::string shown;
  for (char c : first_line) shown += c == '>' ? std::string("&gt;") : c == '<' ? std::string("&lt;") : std::string(1, c);
  EXPECT_NE(html.find("<span class=\"ln\">1</span>" + shown), std::string::npos) << first_line;
}

TEST(EvaluateCli, AReportGoesWithRoundTripsAndIsAnHtmlFile) {
  TempFolder dir;
  const std::string grammar = VERN_SOURCE_DIR "/data/grammars/garage.grm";
  auto r = test::run_program("evaluate", {grammar, "--precision-recall", "--report", "r.html"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--report goes with the round trips"), std::string::npos) << r.err;
  r = test::run_program("evaluate", {grammar, "--report", "r.txt"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--report must name an .html file"), std::string::npos) << r.err;
  EXPECT_TRUE(test::list_folder(dir.path()).empty());
}

}  // namespace
}  // namespace vern
