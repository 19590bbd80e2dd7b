// vernacular::read_examples and write_buildings (src/api/io.cpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
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
