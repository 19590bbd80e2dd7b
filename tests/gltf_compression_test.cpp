// Compressed GLB files as web pipelines write them (tests/data/compressed,
// made by glTF-Transform from a GLB generate wrote): read as the plain file
// they compress, derived by its grammar, and, broken, refused naming what.
#include "io/gltf_compression.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "inverse/load/example.hpp"
#include "io/glb_chunks.hpp"
#include "io/gltf_container.hpp"
#include "support/run_command.hpp"

namespace vern {
namespace {

namespace fs = std::filesystem;
using test::TempFolder;

const fs::path kFolder = VERN_SOURCE_DIR "/tests/data/compressed";

std::vector<LabelledBox> sorted_boxes(const Example& ex) {
  std::vector<LabelledBox> boxes = ex.boxes;
  std::sort(boxes.begin(), boxes.end(), [](const LabelledBox& a, const LabelledBox& b) {
    return std::tie(a.min.z, a.min.x, a.min.y, a.label) < std::tie(b.min.z, b.min.x, b.min.y, b.label);
  });
  return boxes;
}

// Each part where the plain file has it, to within the 16-bit grid the
// positions were quantized to (a step of the house's extent / 65535).
TEST(GltfCompression, DracoAndMeshoptFilesReadAsThePlainFileTheyCompress) {
  const Example plain = load_example(kFolder / "house.glb");
  const glm::dvec3 extent = plain.max - plain.min;
  const double step = std::max({extent.x, extent.y, extent.z}) / 65535.0;
  const std::vector<LabelledBox> expected = sorted_boxes(plain);
  ASSERT_GT(expected.size(), 20u);
  for (const char* name : {"house_draco.glb", "house_meshopt.glb"}) {
    const Example ex = load_example(kFolder / name);
    const std::vector<LabelledBox> got = sorted_boxes(ex);
    ASSERT_EQ(got.size(), expected.size()) << name;
    double worst = 0;
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(got[i].label, expected[i].label) << name << " part " << i;
      for (int a = 0; a < 3; ++a) {
        worst = std::max({worst, std::abs(got[i].min[a] - expected[i].min[a]),
                          std::abs(got[i].max[a] - expected[i].max[a])});
      }
    }
    EXPECT_LE(worst, step) << name;
  }
}

// The grammar that made the house derives it from either compressed file,
// within the quantization; inferred from them, a grammar derives them.
TEST(GltfCompression, CompressedExamplesCheckAndInfer) {
  TempFolder dir;
  for (const char* name : {"house_draco.glb", "house_meshopt.glb"}) {
    const auto checked = test::run_program(
        "check", {(kFolder / "house.grm").string(), (kFolder / name).string(), "--tolerance", "0.001"}, dir.path());
    EXPECT_EQ(checked.exit_code, 0) << name << "\n" << checked.out << checked.err;
    EXPECT_NE(checked.out.find("1 of 1 example derivable"), std::string::npos) << checked.out;
  }
  const auto inferred = test::run_program("infer",
                                          {(kFolder / "house_draco.glb").string(),
                                           (kFolder / "house_meshopt.glb").string(), "-o", "style.grm", "-q",
                                           "--tolerance", "0.001"},
                                          dir.path());
  ASSERT_EQ(inferred.exit_code, 0) << inferred.err;
  const auto rechecked =
      test::run_program("check",
                        {"style.grm", (kFolder / "house_draco.glb").string(),
                         (kFolder / "house_meshopt.glb").string(), "--tolerance", "0.001"},
                        dir.path());
  EXPECT_NE(rechecked.out.find("2 of 2 examples derivable"), std::string::npos) << rechecked.out << rechecked.err;
}

// A GLB's JSON and BIN chunks, to break a fixture in one place.
struct Glb {
  nlohmann::json json;
  std::vector<unsigned char> bin;

  explicit Glb(const fs::path& p) {
    const std::string bytes = test::read_file(p);
    const std::span<const unsigned char> all(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
    const GlbChunks chunks = glb_chunks(all);
    json = nlohmann::json::parse(chunks.json.begin(), chunks.json.end());
    bin.assign(chunks.bin.begin(), chunks.bin.end());
  }

  void write(const fs::path& p) const {
    const std::string text = json.dump();
    const std::string bytes(bin.begin(), bin.end());
    test::write_text(p, glb_header(text.size(), bin.size()) + text + glb_between(text.size(), bin.size()) + bytes);
  }
};

std::string load_error(const fs::path& p) {
  try {
    load_example(p);
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Input) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no error for " << p;
  return {};
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(GltfCompression, DataThatDoesNotDecodeIsRefusedNamingItsViewOrPrimitive) {
  TempFolder dir;
  {
    Glb glb(kFolder / "house_draco.glb");
    const int view = glb.json["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["bufferView"];
    const std::size_t at = glb.json["bufferViews"][view].value("byteOffset", 0);
    std::fill_n(glb.bin.begin() + static_cast<std::ptrdiff_t>(at), 8, 0);  // its "DRACO" magic and version
    glb.write(dir / "broken_draco.glb");
    const std::string e = load_error(dir / "broken_draco.glb");
    EXPECT_TRUE(has(e, "primitive 0 of mesh 0 (KHR_draco_mesh_compression): its data does not decode")) << e;
  }
  {
    Glb glb(kFolder / "house_meshopt.glb");
    std::size_t broken = 0;
    for (std::size_t v = 0; v < glb.json["bufferViews"].size(); ++v) {
      auto& view = glb.json["bufferViews"][v];
      if (!view.contains("extensions")) continue;
      const std::size_t at = view["extensions"]["EXT_meshopt_compression"].value("byteOffset", 0);
      glb.bin[at] = 0;  // the codec's header byte
      broken = v;
      break;
    }
    glb.write(dir / "broken_meshopt.glb");
    const std::string e = load_error(dir / "broken_meshopt.glb");
    EXPECT_TRUE(has(e, "buffer view " + std::to_string(broken) + " (EXT_meshopt_compression): its data does not decode"))
        << e;
  }
}

TEST(GltfCompression, AViewReadingAFallbackBufferUncompressedIsRefused) {
  TempFolder dir;
  Glb glb(kFolder / "house_meshopt.glb");
  std::size_t fallback = 0;
  for (std::size_t b = 0; b < glb.json["buffers"].size(); ++b)
    if (glb.json["buffers"][b].contains("extensions")) fallback = b;
  ASSERT_NE(fallback, 0u);
  for (auto& view : glb.json["bufferViews"]) {
    if (!view.contains("extensions")) continue;
    view.erase("extensions");
    break;
  }
  glb.write(dir / "uncompressed_view.glb");
  const std::string e = load_error(dir / "uncompressed_view.glb");
  EXPECT_TRUE(has(e, "reads buffer " + std::to_string(fallback) +
                         ", a fallback of EXT_meshopt_compression that holds no data"))
      << e;
}

}  // namespace
}  // namespace vern
