// Writers given buildings one at a time (what `generate` does): the same
// bytes as given the whole scene, and memory that does not grow with the
// number of buildings (issue 16, item 15: `generate -n 5000` of the city
// peaked at 4.4 GB).
#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "base/spill_file.hpp"
#include "forward/derive.hpp"
#include "forward/program.hpp"
#include "forward/variants.hpp"
#include "graph/parser.hpp"
#include "io/gltf_writer.hpp"
#include "io/obj_writer.hpp"
#include "support/scene_helpers.hpp"

namespace vern {
namespace {

namespace fs = std::filesystem;
using test::terminal;

// Streams keep a reference to their library.
const PrimitiveLibrary& library() {
  static const PrimitiveLibrary builtin = PrimitiveLibrary::builtin();
  return builtin;
}

// `count` variants of 300 boxes each, some windows, some coloured.
Scene town(std::uint32_t count) {
  Scene scene;
  scene.labels = {"rect", "window"};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> size(0.5, 4.0);
  for (std::uint32_t v = 0; v < count; ++v) {
    Variant variant;
    variant.name = variant_name(v);
    variant.offset = {20.0 * v, 0, 0};
    for (int i = 0; i < 300; ++i) {
      Terminal t = terminal(static_cast<LabelId>(i % 3 == 0), {i * 0.5, 0, 0}, {size(rng), size(rng), size(rng)});
      if (i % 7 == 0) t.coloured = true, t.colour = {0.5f, 0.25f, static_cast<float>(v % 3) / 2.0f};
      variant.terminals.push_back(t);
    }
    scene.variants.push_back(std::move(variant));
  }
  return scene;
}

struct TempFolder {
  fs::path path = fs::temp_directory_path() / ("vern_stream_" + std::to_string(::getpid()));
  TempFolder() { fs::create_directories(path); }
  ~TempFolder() { fs::remove_all(path); }
};

TEST(SceneStreaming, GltfStreamHoldsTheSameForFiftyOrFourHundredBuildings) {
  const TempFolder folder;
  const Scene scene = town(400);
  for (const bool instancing : {false, true}) {
    GltfStream stream(scene.labels, library(), {instancing}, folder.path, "town.glb");
    std::size_t held_50 = 0, held_400 = 0;
    for (std::size_t v = 0; v < scene.variants.size(); ++v) {
      stream.add(scene.variants[v]);
      (v < 50 ? held_50 : held_400) = std::max(v < 50 ? held_50 : held_400, stream.held_bytes());
    }
    std::string streamed;
    stream.glb([&](std::string_view piece) { streamed.append(piece); });
    // Eight times the buildings, not twice the memory; and far less than
    // the file (16 MB plain, 5 MB instanced): the rest waits on disk.
    EXPECT_LE(held_400, 2 * held_50) << "instancing " << instancing;
    EXPECT_LE(held_400, streamed.size() / 2) << "instancing " << instancing;
    EXPECT_TRUE(streamed == glb_bytes(scene, library(), {instancing})) << "instancing " << instancing;
  }
}

TEST(SceneStreaming, GltfTextStreamedIsTheSameText) {
  const TempFolder folder;
  for (const bool instancing : {false, true}) {
    const Scene scene = town(40);
    GltfStream stream(scene.labels, library(), {instancing}, folder.path, "town.gltf");
    for (const Variant& v : scene.variants) stream.add(v);
    std::string streamed;
    stream.gltf([&](std::string_view piece) { streamed.append(piece); });
    EXPECT_TRUE(streamed == gltf_text(scene, library(), {instancing})) << "instancing " << instancing;
  }
}

TEST(SceneStreaming, ObjStreamHoldsAboutAMegabyteOfText) {
  const Scene scene = town(200);  // some 60 MB of OBJ text
  std::string streamed;
  ObjStream stream(scene.labels, library(), "town.mtl",
                   [&](std::string_view piece) { streamed.append(piece); });
  for (const Variant& v : scene.variants) {
    stream.add(v);
    EXPECT_LE(stream.held_bytes(), std::size_t{4} << 20);
  }
  stream.flush();
  EXPECT_TRUE(streamed == obj_text(scene, library(), "town.mtl"));
  EXPECT_EQ(stream.mtl_text(), mtl_text(scene));
}

TEST(SceneStreaming, SpillFileGivesBackWhatWasAppendedAcrossItsThreshold) {
  const TempFolder folder;
  SpillFile spill(folder.path, "out.glb", 1000);
  std::string expected;
  for (int i = 0; i < 500; ++i) {
    const std::string piece = std::string(static_cast<std::size_t>(i % 37), static_cast<char>('a' + i % 26)) + ",";
    spill.append(piece);
    expected += piece;
    EXPECT_LE(spill.held_bytes(), 2000u);
  }
  spill.append(std::string(5000, 'z'));  // larger than the threshold: straight to disk
  expected += std::string(5000, 'z');
  std::string back;
  spill.read([&](std::string_view piece) { back.append(piece); });
  EXPECT_EQ(spill.size(), expected.size());
  EXPECT_TRUE(back == expected);
  EXPECT_TRUE(fs::is_empty(folder.path)) << "the spill file has no name";
}

// A one-file layout places variants by their start sizes, now drawn before
// the buildings are derived: where lay_out puts the derivations.
TEST(SceneStreaming, StartSizesAndOffsetsAreThoseOfTheDerivations) {
  const Grammar g = parse_grammar("@scope rand(5, 30), rand(4, 20), 10\nstart --> split(x){ ~1 : I(rect) | ~1 : nil }\n");
  VariantOptions options;
  options.count = 11;
  options.derive.seed = 5;
  const std::vector<glm::dvec3> sizes = start_sizes(g, options);
  const Scene laid = lay_out(derive_variants(g, options), 3.0);
  const std::vector<glm::dvec3> offsets = layout_offsets(sizes, 3.0);
  ASSERT_EQ(laid.variants.size(), offsets.size());
  std::vector<std::uint32_t> order;
  derive_variants_in_order(g, options, 4, [&](std::uint32_t i, Derivation&& d) {
    order.push_back(i);
    EXPECT_EQ(d.start.size, sizes[i]);
    EXPECT_EQ(laid.variants[i].offset, offsets[i]);
  });
  EXPECT_EQ(order, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10}));
  EXPECT_NE(sizes[0], sizes[1]);
}

}  // namespace
}  // namespace vern
