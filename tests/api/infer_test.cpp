// vernacular::infer and check (src/api/infer.cpp, src/api/check.cpp): the
// round trip a user makes, examples -> grammar -> verdicts and variants.
#include <gtest/gtest.h>

#include <filesystem>
#include <vernacular/vernacular.hpp>

namespace fs = std::filesystem;

namespace {

const fs::path kGarage = fs::path(VERN_SOURCE_DIR) / "data/examples/garage";

TEST(ApiInfer, TheGaragesStyleDerivesEveryGarageAndSavesBesideItsMeshes) {
  const std::vector<vernacular::Example> examples = vernacular::read_examples({kGarage});
  const vernacular::InferResult style = vernacular::infer(examples);
  EXPECT_EQ(style.examples, examples.size());
  EXPECT_GT(style.tolerance, 0);
  EXPECT_EQ(style.grammar.start(), "building");
  for (const vernacular::Example& e : examples) {
    const vernacular::Verdict v = vernacular::check(style.grammar, e);
    EXPECT_TRUE(v.derivable) << e.source() << ": " << v.reason;
    EXPECT_FALSE(v.witness.empty());
  }
  const fs::path dir = fs::temp_directory_path() / "vern_api_infer";
  fs::create_directories(dir);
  style.save(dir / "garage.grm");
  EXPECT_TRUE(fs::exists(dir / "garage.prims.obj"));
  const vernacular::Grammar read = vernacular::Grammar::read(dir / "garage.grm");
  for (const vernacular::Example& e : examples) EXPECT_TRUE(vernacular::check(read, e).derivable) << e.source();
  fs::remove_all(dir);
}

TEST(ApiInfer, AnExampleOfAnotherStyleIsNotDerivableAndSaysWhere) {
  const std::vector<vernacular::Example> garages = vernacular::read_examples({kGarage});
  const vernacular::Grammar tower =
      vernacular::Grammar::parse("building --> repeat(z, 3){ I(box) }\n", "tower.grm");
  const vernacular::Verdict v = vernacular::check(tower, garages.front());
  EXPECT_FALSE(v.derivable);
  EXPECT_FALSE(v.reason.empty());
  EXPECT_TRUE(v.witness.empty());
}

TEST(ApiInfer, WrongArgumentsAreUsageErrors) {
  EXPECT_THROW(
      {
        try {
          vernacular::infer({});
        } catch (const vernacular::Failure& f) {
          EXPECT_EQ(f.error().kind, vernacular::ErrorKind::Usage);
          throw;
        }
      },
      vernacular::Failure);
  const std::vector<vernacular::Example> examples = vernacular::read_examples({kGarage});
  vernacular::InferOptions o;
  o.start = "split";
  try {
    vernacular::infer(examples, o);
    FAIL() << "a start rule named 'split' was taken";
  } catch (const vernacular::Failure& f) {
    EXPECT_EQ(f.error().kind, vernacular::ErrorKind::Usage);
    EXPECT_FALSE(f.error().hint.empty());
  }
}

}  // namespace
