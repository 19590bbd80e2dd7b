// The glTF writer: variant roots, terminal nodes with scope matrices, meshes
// shared by instances, materials, and byte-identical output.
#include "io/gltf_writer.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "base/error.hpp"
#include "io/gltf_summary.hpp"
#include "io/palette.hpp"
#include "support/scene_helpers.hpp"

namespace vern {
namespace {

namespace fs = std::filesystem;

using test::kQuarterTurnZ;
using test::terminal;

// Three walls and a turned window; a second variant with one more wall.
Scene street() {
  Scene scene;
  scene.labels = {"rect", "window"};
  Variant a;
  a.name = "variant_000";
  a.terminals.push_back(terminal(0, {0, 0, 0}, {4, 0.3, 3}));
  a.terminals.push_back(terminal(0, {0, 0, 3}, {4, 0.3, 3}));
  a.terminals.push_back(terminal(1, {10, 0, 0}, {4, 0.5, 2}, kQuarterTurnZ));
  a.terminals.push_back(terminal(0, {0, 0, 6}, {4, 0.3, 1}));
  Variant b;
  b.name = "variant_001";
  b.offset = {50, 0, 0};
  b.terminals.push_back(terminal(0, {1, 2, 3}, {2, 2, 2}));
  scene.variants = {a, b};
  return scene;
}

TEST(GltfWriter, OneRootPerVariantAndOneChildPerTerminal) {
  const GltfSummary s = summarize_gltf(glb_bytes(street(), PrimitiveLibrary::builtin()));
  EXPECT_EQ(s.generator, "Vernacular");
  ASSERT_EQ(s.roots.size(), 2u);
  const GltfSummary::Node& a = s.nodes.at(static_cast<std::size_t>(s.roots[0]));
  const GltfSummary::Node& b = s.nodes.at(static_cast<std::size_t>(s.roots[1]));
  EXPECT_EQ(a.name, "variant_000");
  EXPECT_EQ(b.name, "variant_001");
  EXPECT_EQ(a.mesh, -1);
  // Each root turns the grammar's z-up to glTF's y-up, (x, y, z) -> (x, z, -y),
  // and moves the variant by its offset.
  EXPECT_EQ(a.matrix, (std::array<double, 16>{1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1}));
  EXPECT_EQ(b.matrix, (std::array<double, 16>{1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 50, 0, 0, 1}));
  std::vector<std::string> names;
  for (int c : a.children) names.push_back(s.nodes.at(static_cast<std::size_t>(c)).name);
  EXPECT_EQ(names, (std::vector<std::string>{"rect", "rect", "window", "rect"}));
  ASSERT_EQ(b.children.size(), 1u);
  EXPECT_EQ(s.nodes.size(), 7u);
}

TEST(GltfWriter, InstancesShareOneMeshPerPrimitive) {
  const GltfSummary s = summarize_gltf(glb_bytes(street(), PrimitiveLibrary::builtin()));
  ASSERT_EQ(s.meshes.size(), 2u);  // 4 walls -> 1 mesh, 1 window -> 1 mesh
  const auto child = [&](int root, std::size_t k) {
    return s.nodes.at(static_cast<std::size_t>(s.nodes.at(static_cast<std::size_t>(root)).children.at(k)));
  };
  const int rect = child(s.roots[0], 0).mesh;
  EXPECT_EQ(child(s.roots[0], 1).mesh, rect);
  EXPECT_EQ(child(s.roots[0], 3).mesh, rect);
  EXPECT_EQ(child(s.roots[1], 0).mesh, rect);
  EXPECT_NE(child(s.roots[0], 2).mesh, rect);

  const GltfSummary::MeshInfo& box = s.meshes.at(static_cast<std::size_t>(rect));
  EXPECT_EQ(box.name, "rect");
  EXPECT_EQ(box.vertices, 24u);  // 6 flat faces x 4 corners
  EXPECT_EQ(box.indices, 36u);   // 12 triangles
  EXPECT_EQ(box.min, (std::array<double, 3>{0, 0, 0}));
  EXPECT_EQ(box.max, (std::array<double, 3>{1, 1, 1}));
}

TEST(GltfWriter, TerminalMatricesMapTheUnitBoxOntoTheScope) {
  const GltfSummary s = summarize_gltf(glb_bytes(street(), PrimitiveLibrary::builtin()));
  const auto& root = s.nodes.at(static_cast<std::size_t>(s.roots[0]));
  const auto& window = s.nodes.at(static_cast<std::size_t>(root.children.at(2)));
  // Columns: frame x * 4, frame y * 0.5, frame z * 2, origin.
  const std::array<double, 16> expected = {0, 4, 0, 0, -0.5, 0, 0, 0, 0, 0, 2, 0, 10, 0, 0, 1};
  EXPECT_EQ(window.matrix, expected);
  const auto& wall = s.nodes.at(static_cast<std::size_t>(root.children.at(1)));
  EXPECT_EQ(wall.matrix, (std::array<double, 16>{4, 0, 0, 0, 0, 0.3, 0, 0, 0, 0, 3, 0, 0, 0, 3, 1}));
}

TEST(GltfWriter, ZeroSizeAxesBecomeInvisiblyThinSoMatricesStayInvertible) {
  Scene scene;
  scene.labels = {"window"};
  scene.variants.push_back({"variant_000", glm::dvec3(0.0), {terminal(0, {1, 0, 0}, {2, 0, 3})}});
  const GltfSummary s = summarize_gltf(glb_bytes(scene, PrimitiveLibrary::builtin()));
  const auto& m = s.nodes.at(static_cast<std::size_t>(s.nodes.at(0).children.at(0))).matrix;
  EXPECT_EQ(m[0], 2.0);
  EXPECT_EQ(m[10], 3.0);
  EXPECT_GT(m[5], 0.0);     // a glTF matrix must decompose into TRS: no zero scale
  EXPECT_LT(m[5], 1e-5);    // but thin enough not to show
  EXPECT_EQ(m[12], 1.0);
}

TEST(GltfWriter, ColouredTerminalsGetTheirOwnMaterialAndShareGeometry) {
  Scene scene = street();
  Terminal red = terminal(0, {0, 5, 0}, {1, 1, 1});
  red.coloured = true;
  red.colour = {1, 0, 0};
  scene.variants[0].terminals.push_back(red);
  const GltfSummary s = summarize_gltf(glb_bytes(scene, PrimitiveLibrary::builtin()));
  ASSERT_EQ(s.meshes.size(), 3u);
  EXPECT_EQ(s.meshes[2].name, "rect colour_ff0000");
  EXPECT_EQ(s.meshes[2].position_accessor, s.meshes[0].position_accessor);  // same triangles
  ASSERT_EQ(s.materials.size(), 3u);
  EXPECT_EQ(s.materials[0].name, "rect");
  const std::array<double, 3> plaster = colour_components(label_colour("rect"));
  EXPECT_EQ(s.materials[0].colour, (std::array<double, 4>{plaster[0], plaster[1], plaster[2], 1}));
  EXPECT_EQ(s.materials[2].name, "colour_ff0000");
  EXPECT_EQ(s.materials[2].colour, (std::array<double, 4>{1, 0, 0, 1}));
  EXPECT_EQ(s.meshes[2].material, 2);
}

TEST(GltfWriter, GlbContainerAndTextFormAgree) {
  const PrimitiveLibrary lib = PrimitiveLibrary::builtin();
  const std::string glb = glb_bytes(street(), lib);
  ASSERT_GE(glb.size(), 20u);
  EXPECT_EQ(glb.substr(0, 4), "glTF");
  std::uint32_t version = 0, length = 0;
  std::memcpy(&version, glb.data() + 4, 4);
  std::memcpy(&length, glb.data() + 8, 4);
  EXPECT_EQ(version, 2u);
  EXPECT_EQ(length, glb.size());
  EXPECT_EQ(glb.size() % 4, 0u);

  const std::string text = gltf_text(street(), lib);
  EXPECT_EQ(text.front(), '{');
  EXPECT_NE(text.find("data:application/octet-stream;base64,"), std::string::npos);
  const GltfSummary a = summarize_gltf(glb), b = summarize_gltf(text);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    EXPECT_EQ(a.nodes[i].name, b.nodes[i].name);
    EXPECT_EQ(a.nodes[i].matrix, b.nodes[i].matrix);
  }
  EXPECT_EQ(a.meshes.size(), b.meshes.size());
}

TEST(GltfWriter, SameSceneSameBytes) {
  const PrimitiveLibrary lib = PrimitiveLibrary::builtin();
  EXPECT_EQ(glb_bytes(street(), lib), glb_bytes(street(), lib));
  EXPECT_EQ(gltf_text(street(), lib), gltf_text(street(), lib));
}

TEST(GltfWriter, EmptySceneIsStillAFile) {
  Scene scene;
  scene.variants.push_back({"variant_000", glm::dvec3(0.0), {}});
  const GltfSummary s = summarize_gltf(glb_bytes(scene, PrimitiveLibrary::builtin()));
  ASSERT_EQ(s.roots.size(), 1u);
  EXPECT_TRUE(s.meshes.empty());
}

TEST(GltfWriter, WriteChoosesTheFormatByExtension) {
  const fs::path dir = fs::temp_directory_path() / ("vern-gltfwriter-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const PrimitiveLibrary lib = PrimitiveLibrary::builtin();
  write_gltf(street(), lib, dir / "street.glb");
  write_gltf(street(), lib, dir / "street.gltf");
  auto contents = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), {});
  };
  EXPECT_EQ(contents(dir / "street.glb"), glb_bytes(street(), lib));
  EXPECT_EQ(contents(dir / "street.gltf"), gltf_text(street(), lib));
  try {
    write_gltf(street(), lib, dir / "street.obj");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Usage);
  }
  EXPECT_FALSE(fs::exists(dir / "street.obj"));
  fs::remove_all(dir);
}

// The instanced layout: per variant one node per mesh, whose instances are
// the terminals of that mesh in order; each instance's T * R * S is the
// plain layout's matrix (to float precision).
TEST(GltfWriter, InstancingGroupsEachVariantsTerminalsByMesh) {
  const PrimitiveLibrary lib = PrimitiveLibrary::builtin();
  Scene scene = street();
  scene.variants[0].terminals[1].scope.frame = kQuarterTurnZ * glm::dmat3(1, 0, 0, 0, 1, 0, 0, 0, -1);  // mirrored
  const GltfSummary plain = summarize_gltf(glb_bytes(scene, lib));
  const GltfSummary s = summarize_gltf(glb_bytes(scene, lib, {.instancing = true}));
  EXPECT_EQ(s.extensions_required, (std::vector<std::string>{"EXT_mesh_gpu_instancing"}));
  ASSERT_EQ(s.roots.size(), 2u);
  const GltfSummary::Node& a = s.nodes.at(static_cast<std::size_t>(s.roots[0]));
  const GltfSummary::Node& b = s.nodes.at(static_cast<std::size_t>(s.roots[1]));
  EXPECT_EQ(a.name, "variant_000");
  EXPECT_EQ(b.matrix, plain.nodes.at(static_cast<std::size_t>(plain.roots[1])).matrix);
  ASSERT_EQ(a.children.size(), 2u);  // rect, window
  ASSERT_EQ(b.children.size(), 1u);  // rect
  const GltfSummary::Node& walls = s.nodes.at(static_cast<std::size_t>(a.children[0]));
  const GltfSummary::Node& window = s.nodes.at(static_cast<std::size_t>(a.children[1]));
  EXPECT_EQ(walls.name, "rect");
  EXPECT_EQ(window.name, "window");
  ASSERT_EQ(walls.instances.size(), 3u);
  ASSERT_EQ(window.instances.size(), 1u);
  EXPECT_EQ(s.nodes.at(static_cast<std::size_t>(b.children[0])).instances.size(), 1u);

  // Instances in terminal order: walls are terminals 0, 1 and 3.
  const GltfSummary::Node& plain_root = plain.nodes.at(static_cast<std::size_t>(plain.roots[0]));
  const auto plain_matrix = [&](std::size_t k) {
    return plain.nodes.at(static_cast<std::size_t>(plain_root.children.at(k))).matrix;
  };
  const std::vector<std::pair<std::array<double, 16>, std::array<double, 16>>> pairs = {
      {walls.instances[0], plain_matrix(0)}, {walls.instances[1], plain_matrix(1)},
      {walls.instances[2], plain_matrix(3)}, {window.instances[0], plain_matrix(2)}};
  for (const auto& [instance, matrix] : pairs) {
    for (std::size_t i = 0; i < 16; ++i) EXPECT_NEAR(instance[i], matrix[i], 1e-6) << "element " << i;
  }
}

TEST(GltfWriter, InstancedFilesAreSameBytesAndTextAgrees) {
  const PrimitiveLibrary lib = PrimitiveLibrary::builtin();
  const std::string glb = glb_bytes(street(), lib, {.instancing = true});
  EXPECT_EQ(glb, glb_bytes(street(), lib, {.instancing = true}));
  // Each further terminal costs 40 bytes of floats (the JSON grows only by
  // longer offsets) instead of a JSON node.
  Scene many = street();
  for (int i = 0; i < 1000; ++i) many.variants[0].terminals.push_back(terminal(0, {0, 0, 7.0 + i}, {4, 0.3, 1}));
  const std::size_t instanced = glb_bytes(many, lib, {.instancing = true}).size() - glb.size();
  const std::size_t plain = glb_bytes(many, lib).size() - glb_bytes(street(), lib).size();
  EXPECT_GE(instanced, 40'000u);
  EXPECT_LT(instanced, 40'100u);
  EXPECT_GT(plain, instanced * 3 / 2);
  const GltfSummary a = summarize_gltf(glb);
  const GltfSummary b = summarize_gltf(gltf_text(street(), lib, {.instancing = true}));
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (std::size_t i = 0; i < a.nodes.size(); ++i) EXPECT_EQ(a.nodes[i].instances, b.nodes[i].instances);
}

TEST(GltfWriter, SummaryRejectsWhatIsNotGltf) {
  try {
    summarize_gltf("{ \"not\": \"gltf\" }");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Input);
  }
}

}  // namespace
}  // namespace vern
