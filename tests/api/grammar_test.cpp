// vernacular::Grammar (src/api/grammar.cpp), through the public API only.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <vernacular/vernacular.hpp>

namespace fs = std::filesystem;

namespace {

const char* kHouse =
    "@start house\n"
    "house --> split(z){ 3 : wall | ~1 : roof }\n"
    "wall --> I(box)\n"
    "roof --> I(roof)\n";

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("vern_api_" + name + "_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  fs::create_directories(dir);
  return dir;
}

TEST(ApiGrammar, ParsedTextWritesBackAsTheSameGrammar) {
  const vernacular::Grammar g = vernacular::Grammar::parse(kHouse, "house.grm");
  EXPECT_EQ(g.start(), "house");
  EXPECT_EQ(g.rule_count(), 3u);
  const vernacular::Grammar again = vernacular::Grammar::parse(g.text());
  EXPECT_EQ(again.text(), g.text());
  EXPECT_NE(g.text().find("split(z)"), std::string::npos);
}

TEST(ApiGrammar, SavedAndReadBackAsAFile) {
  const fs::path dir = scratch("grammar");
  const vernacular::Grammar g = vernacular::Grammar::parse(kHouse);
  g.save(dir / "house.grm");
  const vernacular::Grammar read = vernacular::Grammar::read(dir / "house.grm");
  EXPECT_EQ(read.text(), g.text());
  EXPECT_EQ(read.file(), dir / "house.grm");
  fs::remove_all(dir);
}

TEST(ApiGrammar, ASyntaxErrorIsAValueWithItsLineAndColumn) {
  try {
    vernacular::Grammar::parse("house --> split(z){ 3 : wall |\nroof --> I(roof)\n", "bad.grm");
    FAIL() << "a broken grammar was read";
  } catch (const vernacular::Failure& f) {
    const vernacular::Error& e = f.error();
    EXPECT_EQ(e.kind, vernacular::ErrorKind::Input);
    EXPECT_EQ(e.location.file, "bad.grm");
    EXPECT_GE(e.location.line, 1u);
    EXPECT_GT(e.location.column, 0u);
    EXPECT_FALSE(e.message.empty());
    EXPECT_EQ(e.message.find("error:"), std::string::npos) << e.message;
    EXPECT_EQ(std::string(f.what()), e.text());
  }
}

TEST(ApiGrammar, AMissingFileIsAnIoError) {
  try {
    vernacular::Grammar::read("/nonexistent/style.grm");
    FAIL() << "a missing file was read";
  } catch (const vernacular::Failure& f) {
    EXPECT_EQ(f.error().kind, vernacular::ErrorKind::Io);
    EXPECT_NE(f.error().text().find("/nonexistent/style.grm"), std::string::npos) << f.what();
  }
}

}  // namespace

namespace {

TEST(ApiGrammar, AFailureSaysWhatTheFinderWroteAndHoldsItTakenApart) {
  try {
    vernacular::Grammar::parse("house --> split(z){ 3 : wall }\n", "house.grm");
    FAIL() << "an unknown rule was read";
  } catch (const vernacular::Failure& f) {
    const std::string text = f.what();
    // The words as written, hint and all, and each piece of them apart.
    EXPECT_EQ(text.rfind("house.grm:1:", 0), 0u) << text;
    EXPECT_NE(text.find("error: " + f.error().message), std::string::npos) << text;
    EXPECT_FALSE(f.error().hint.empty()) << text;
    EXPECT_NE(text.find("\n  hint: " + f.error().hint), std::string::npos) << text;
  }
}

}  // namespace
