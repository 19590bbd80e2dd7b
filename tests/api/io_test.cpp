// vernacular::read_examples and write_buildings (src/api/io.cpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <vernacular/vernacular.hpp>

namespace fs = std::filesystem;

namespace {

const fs::path kGarage = fs::path(VERN_SOURCE_DIR) / "data/examples/garage";

TEST(ApiIo, AFolderIsItsExampleFilesInNameOrder) {
  const std::vector<vernacular::Example> examples = vernacular::read_examples({kGarage});
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(kGarage))
    if (entry.path().extension() == ".obj") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  ASSERT_EQ(examples.size(), files.size());
  for (std::size_t i = 0; i < files.size(); ++i) {
    EXPECT_EQ(fs::path(examples[i].source()).filename(), files[i].filename());
    EXPECT_FALSE(examples[i].parts().empty());
    for (const vernacular::ExamplePart& p : examples[i].parts())
      for (int a = 0; a < 3; ++a) EXPECT_LE(p.min[a], p.max[a]);
  }
}

TEST(ApiIo, AnExampleThatIsNoneIsAnInputErrorNamingItsFile) {
  const fs::path file = fs::temp_directory_path() / "vern_api_io_empty.obj";
  std::ofstream(file) << "# nothing here\n";
  try {
    vernacular::read_examples({file});
    FAIL() << "an empty example was read";
  } catch (const vernacular::Failure& f) {
    EXPECT_EQ(f.error().kind, vernacular::ErrorKind::Input) << f.what();
    EXPECT_EQ(f.error().location.file, file.string()) << f.what();
  }
  fs::remove(file);
}

TEST(ApiIo, BuildingsAreWrittenByTheExtensionAndOtherExtensionsRefused) {
  const vernacular::Grammar g =
      vernacular::Grammar::parse("house --> split(z){ 3 : I(box) | ~1 : I(roof) }\n");
  const std::vector<vernacular::Building> houses = vernacular::derive_many(g, 3);
  const fs::path dir = fs::temp_directory_path() / "vern_api_io_out";
  fs::create_directories(dir);
  vernacular::write_buildings(houses, g, dir / "houses.obj");
  vernacular::write_buildings(houses, g, dir / "houses.glb");
  EXPECT_GT(fs::file_size(dir / "houses.obj"), 0u);
  EXPECT_TRUE(fs::exists(dir / "houses.mtl"));
  std::ifstream glb(dir / "houses.glb", std::ios::binary);
  char magic[4] = {};
  glb.read(magic, 4);
  EXPECT_EQ(std::string(magic, 4), "glTF");
  // Read back as examples: the same parts, three buildings standing apart.
  const std::vector<vernacular::Example> back = vernacular::read_examples({dir / "houses.glb"});
  ASSERT_EQ(back.size(), 3u);
  EXPECT_EQ(back[0].parts().size(), houses[0].parts.size());
  try {
    vernacular::write_buildings(houses, g, dir / "houses.stl");
    FAIL() << "an .stl was written";
  } catch (const vernacular::Failure& f) {
    EXPECT_EQ(f.error().kind, vernacular::ErrorKind::Usage) << f.what();
  }
  EXPECT_FALSE(fs::exists(dir / "houses.stl"));
  fs::remove_all(dir);
}

}  // namespace

namespace {

TEST(ApiIo, AnExampleMadeInMemoryInfersAsItsFileWould) {
  // Three houses as boxes: a wall and a roof, widths 6, 8 and 10.
  std::vector<vernacular::Example> examples;
  for (double width : {6.0, 8.0, 10.0}) {
    std::vector<vernacular::ExamplePart> parts;
    parts.push_back({"wall", "", {0, 0, 0}, {width, 4, 2.7}});
    parts.push_back({"roof", "", {0, 0, 2.7}, {width, 4, 3.9}});
    examples.push_back(vernacular::Example::from_parts(parts, "house_" + std::to_string(int(width))));
  }
  EXPECT_EQ(examples[1].source(), "house_8");
  EXPECT_EQ(examples[1].parts()[1].object, "roof.1");
  const vernacular::InferResult style = vernacular::infer(examples);
  for (const vernacular::Example& e : examples) EXPECT_TRUE(vernacular::check(style.grammar, e).derivable) << e.source();
  EXPECT_NE(style.grammar.text().find("I(roof)"), std::string::npos) << style.grammar.text();
}

TEST(ApiIo, AnExampleInMemoryThatIsNoBoxIsAnInputError) {
  for (const vernacular::ExamplePart& bad :
       {vernacular::ExamplePart{"wall", "", {0, 0, 0}, {-1, 4, 3}}, vernacular::ExamplePart{"wall", "", {0, 0, 0}, {0, 0, 0}},
        vernacular::ExamplePart{"", "", {0, 0, 0}, {1, 1, 1}},
        vernacular::ExamplePart{"wall", "", {0, 0, 0}, {std::numeric_limits<double>::infinity(), 1, 1}}}) {
    try {
      vernacular::Example::from_parts({bad}, "mine");
      FAIL() << "a bad part was taken: " << bad.label;
    } catch (const vernacular::Failure& f) {
      EXPECT_EQ(f.error().kind, vernacular::ErrorKind::Input) << f.what();
      EXPECT_EQ(f.error().location.file, "mine") << f.what();
    }
  }
  EXPECT_THROW(vernacular::Example::from_parts({}, "none"), vernacular::Failure);
}

}  // namespace
