// The glTF 2.0 rules the example loader checks beyond tinygltf
// (io/gltf_rules.hpp): a valid file loads; each file that breaks one
// rule, and only that one, is refused as bad input naming the node, mesh,
// primitive or accessor.
#include "io/gltf_rules.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "inverse/load/example.hpp"
#include "io/gltf_container.hpp"
#include "support/run_command.hpp"

namespace vern {
namespace {

using test::TempFolder;
using test::write_text;

// A valid file: node 0 'wall' and its child 1 'roof' (lifted by 2) share a
// mesh of two triangles, indexed by UNSIGNED_BYTE: accessor 0 holds
// `vertices` positions (the first four the corners of a unit square
// standing on the xy plane, more on its edge), accessor 1 six indices,
// accessor 2 a spare VEC2 of four elements.
struct Gltf {
  std::string json;

  explicit Gltf(std::uint32_t vertices = 4) {
    std::vector<float> p = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    for (std::uint32_t i = 4; i < vertices; ++i) p.insert(p.end(), {0.5f, 0.0f, 0.0f});
    std::string bytes(p.size() * sizeof(float), '\0');
    std::memcpy(bytes.data(), p.data(), bytes.size());
    const std::size_t positions = bytes.size();
    bytes += std::string("\0\1\2\0\2\3\0\0", 8);  // the indices, padded to 4 bytes
    json = R"({"asset": {"version": "2.0"},
  "buffers": [{"byteLength": )" + std::to_string(bytes.size()) + R"(, "uri": "data:application/octet-stream;base64,)" +
           base64(bytes) + R"("}],
  "bufferViews": [{"buffer": 0, "byteLength": )" + std::to_string(positions) + R"(},
                  {"buffer": 0, "byteOffset": )" + std::to_string(positions) + R"(, "byteLength": 6}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" + std::to_string(vertices) +
           R"(, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5121, "count": 6, "type": "SCALAR"},
                {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC2"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],
  "nodes": [{"name": "wall", "mesh": 0, "children": [1]}, {"name": "roof", "mesh": 0, "translation": [0, 2, 0]}],
  "scenes": [{"nodes": [0]}], "scene": 0})";
  }

  // The file with its first `from` replaced by `to` (the test fails when
  // there is no `from`).
  Gltf with(const std::string& from, const std::string& to) const {
    Gltf out = *this;
    const std::size_t at = out.json.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) out.json.replace(at, from.size(), to);
    return out;
  }
};

// The error loading `file` gives (and that it is bad input), or "" when it loads.
std::string error_of(const Gltf& file) {
  TempFolder dir;
  write_text(dir / "file.gltf", file.json);
  try {
    load_example(dir / "file.gltf");
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Input) << e.what();
    EXPECT_NE(std::string(e.what()).find("\n  hint: "), std::string::npos) << e.what();
    return e.what();
  }
  return "";
}

void expect_refused(const Gltf& file, const std::string& message) {
  const std::string error = error_of(file);
  EXPECT_NE(error.find("file.gltf: error: " + message), std::string::npos) << "expected: " << message << "\n" << error;
}

TEST(GltfRules, TheValidFileLoadsAndStripsAndFansToo) {
  EXPECT_EQ(error_of(Gltf()), "");
  EXPECT_EQ(error_of(Gltf().with(R"("mode": 4)", R"("mode": 5)")), "");
  EXPECT_EQ(error_of(Gltf().with(R"("mode": 4)", R"("mode": 6)")), "");
  // Extensions that only change how a surface looks may be required.
  EXPECT_EQ(error_of(Gltf().with(R"("asset")", R"("extensionsUsed": ["KHR_materials_unlit"],)"
                                                R"( "extensionsRequired": ["KHR_materials_unlit"], "asset")")),
            "");
  // A later minor version reads as 2.0; a matrix of rotation and scale is fine.
  EXPECT_EQ(error_of(Gltf().with(R"("version": "2.0")", R"("version": "2.1", "minVersion": "2.0")")), "");
  EXPECT_EQ(error_of(Gltf().with(R"("translation": [0, 2, 0])",
                                 R"("matrix": [0, 2, 0, 0, -2, 0, 0, 0, 0, 0, 2, 0, 0, 2, 0, 1])")),
            "");
}

TEST(GltfRules, TheAssetIsGltf2AndItsRequiredExtensionsAreImplemented) {
  const Gltf g;
  expect_refused(g.with(R"("version": "2.0")", R"("version": "1.0")"), "asset.version is 1.0: only glTF 2 files");
  expect_refused(g.with(R"("version": "2.0")", R"("version": "two")"), "asset.version 'two' is not a glTF version");
  expect_refused(g.with(R"("version": "2.0")", R"("version": "2.0", "minVersion": "2.1")"),
                 "asset.minVersion '2.1' is not a glTF version at most its version 2.0");
  expect_refused(g.with(R"("version": "2.0")", R"("version": "2.2", "minVersion": "2.1")"),
                 "asset.minVersion is 2.1: the file needs glTF 2.1 features");
  expect_refused(g.with(R"("asset")", R"("extensionsUsed": ["KHR_meshopt_compression"],)"
                                      R"( "extensionsRequired": ["KHR_meshopt_compression"], "asset")"),
                 "requires the extension KHR_meshopt_compression, which this reader does not implement");
  expect_refused(g.with(R"("asset")", R"("extensionsRequired": ["EXT_mesh_gpu_instancing"], "asset")"),
                 "requires the extension EXT_mesh_gpu_instancing but does not list it in extensionsUsed");
}

TEST(GltfRules, ScenesListExistingRootsAndNodesFormTrees) {
  const Gltf g;
  expect_refused(g.with(R"("scene": 0)", R"("scene": 3)"), "the default scene is scene 3, but the file has 1 scene");
  expect_refused(g.with(R"("scenes": [{"nodes": [0]}])", R"("scenes": [{"nodes": [0, 5]}])"),
                 "scene 0 lists node 5, but the file has 2 nodes");
  expect_refused(g.with(R"("scenes": [{"nodes": [0]}])", R"("scenes": [{"nodes": [0, 1]}])"),
                 "scene 0 lists node 1 'roof', the child of node 0 'wall': a scene lists root nodes only");
  expect_refused(g.with(R"("scenes": [{"nodes": [0]}])", R"("scenes": [{"nodes": [0, 0]}])"),
                 "scene 0 lists node 0 'wall' twice");
  // Scenes the loader does not show are checked too.
  expect_refused(g.with(R"("scenes": [{"nodes": [0]}])", R"("scenes": [{"nodes": [0]}, {"nodes": [-1]}])"),
                 "scene 1 lists node -1, but the file has 2 nodes");
  expect_refused(g.with(R"("children": [1])", R"("children": [7])"),
                 "node 0 'wall' lists child 7, but the file has 2 nodes");
  expect_refused(g.with(R"("children": [1])", R"("children": [1, 0])"),
                 "node 0 'wall' is its own ancestor (a cycle through node 0 'wall')");
  expect_refused(g.with(R"("translation": [0, 2, 0]})", R"("translation": [0, 2, 0]}, {"children": [1]})"),
                 "node 1 'roof' is the child of two nodes, node 0 'wall' and node 2: glTF nodes form trees");
  // A cycle no scene reaches is still one.
  expect_refused(g.with(R"("translation": [0, 2, 0]})",
                        R"("translation": [0, 2, 0]}, {"name": "a", "children": [3]}, {"children": [2]})"),
                 "node 2 'a' is its own ancestor (a cycle through node 3)");
  expect_refused(g.with(R"("name": "roof", "mesh": 0)", R"("name": "roof", "mesh": -2)"),
                 "node 1 'roof' refers to mesh -2, but the file has 1 mesh");
}

TEST(GltfRules, NodeTransformsAreTranslationRotationAndScale) {
  const Gltf g;
  const std::string t = R"("translation": [0, 2, 0])";
  expect_refused(g.with(t, R"("translation": [0, 2])"), "node 1 'roof' has a translation of 2 numbers, not 3");
  expect_refused(g.with(t, R"("scale": [1, 1, 1, 1])"), "node 1 'roof' has a scale of 4 numbers, not 3");
  expect_refused(g.with(t, R"("rotation": [0, 0, 1])"), "node 1 'roof' has a rotation of 3 numbers, not 4");
  expect_refused(g.with(t, R"("matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 2, 0])"),
                 "node 1 'roof' has a matrix of 15 numbers, not 16");
  expect_refused(g.with(t, R"("rotation": [0, 0, 0, 2])"),
                 "node 1 'roof''s rotation is not a unit quaternion (its length is 2)");
  expect_refused(g.with(t, R"("rotation": [0, 0, 0, 0])"), "node 1 'roof''s rotation is not a unit quaternion");
  // A projection (last row not 0 0 0 1) and a shear are no TRS.
  expect_refused(g.with(t, R"("matrix": [1, 0, 0, 0.5, 0, 1, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1])"),
                 "node 1 'roof''s matrix is not a translation, rotation and scale");
  expect_refused(g.with(t, R"("matrix": [1, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1])"),
                 "node 1 'roof''s matrix is not a translation, rotation and scale");
}

TEST(GltfRules, PrimitivesDrawWholeTriangles) {
  const Gltf g;
  const std::string p = "node 0 'wall': mesh 0 primitive 0 ";
  expect_refused(g.with(R"("mode": 4)", R"("mode": -1)"), p + "has mode -1, which is not a glTF primitive mode");
  expect_refused(g.with(R"("mode": 4)", R"("mode": 7)"), p + "has mode 7, which is not a glTF primitive mode");
  expect_refused(g.with(R"("mode": 4)", R"("mode": 1)"), p + "has mode 1 (LINES): only triangles");
  expect_refused(g.with(R"("mode": 4)", R"("mode": 0)"), p + "has mode 0 (POINTS): only triangles");
  expect_refused(g.with(R"("count": 6, "type": "SCALAR")", R"("count": 5, "type": "SCALAR")"),
                 p + "draws 5 vertex indices as TRIANGLES: not a multiple of 3");
  // Without indices, the vertices are drawn in order: 4 are no whole triangles.
  expect_refused(g.with(R"(, "indices": 1)", ""), p + "draws 4 vertex indices as TRIANGLES: not a multiple of 3");
  expect_refused(g.with(R"("count": 6, "type": "SCALAR")", R"("count": 2, "type": "SCALAR")")
                     .with(R"("mode": 4)", R"("mode": 5)"),
                 p + "draws 2 vertex indices as a strip or fan: fewer than 3");
  expect_refused(g.with(R"("indices": 1)", R"("indices": -2)"), p + "names indices accessor -2, but the file has");
  expect_refused(g.with(R"("POSITION": 0})", R"("POSITION": 0, "NORMAL": 2})"),
                 p + "has a NORMAL accessor of another type than VEC3");
  expect_refused(g.with(R"("POSITION": 0})", R"("POSITION": 0, "TEXCOORD_0": 1})"),
                 p + "has 4 POSITION elements but 6 TEXCOORD_0 elements");
  expect_refused(g.with(R"("POSITION": 0})", R"("POSITION": 0, "COLOR_0": 8})"),
                 p + "names COLOR_0 accessor 8, but the file has 3 accessors");
  expect_refused(g.with(R"("primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}])",
                        R"("primitives": [])"),
                 "mesh 0 has no primitives");
}

TEST(GltfRules, AccessorsAreReadAsGltfLaysThemOut) {
  const Gltf g;
  const std::string pos = R"({"bufferView": 0, "componentType": 5126, "count": 4)";
  const std::string position = "node 0 'wall': its POSITION accessor (accessor 0) ";
  expect_refused(g.with(pos, R"({"bufferView": 0, "componentType": 5124, "count": 4)"),
                 position + "has componentType 5124, not one glTF defines");
  expect_refused(g.with(pos, R"({"bufferView": 0, "componentType": 5126, "count": 0)"),
                 position + "has count 0");
  expect_refused(g.with(pos, R"({"bufferView": 0, "componentType": 5126, "normalized": true, "count": 4)"),
                 position + "is normalized, which FLOAT and UNSIGNED_INT components may not be");
  expect_refused(g.with(pos, R"({"bufferView": 0, "byteOffset": 2, "componentType": 5126, "count": 3)"),
                 position + "starts at byteOffset 2 in buffer view 0, not aligned to its components (4 bytes)");
  expect_refused(g.with(R"({"buffer": 0, "byteLength": 48})", R"({"buffer": 0, "byteLength": 48, "byteStride": 4})"),
                 position + "has byteStride 4 (buffer view 0), less than its elements' 12 bytes");
  const std::string index = "node 0 'wall': its index accessor (accessor 1) ";
  expect_refused(g.with(R"("byteOffset": 48, "byteLength": 6})", R"("byteOffset": 48, "byteLength": 60})"),
                 index + "lies in buffer view 1, which is empty or lies past the end of its buffer");
  expect_refused(g.with(R"("byteLength": 6})", R"("byteLength": 8, "byteStride": 4})")
                     .with(R"("count": 6, "type": "SCALAR")", R"("count": 2, "type": "SCALAR")")
                     .with(R"("mode": 4)", R"("mode": 5)"),
                 index + "holds indices in buffer view 1, which has a byteStride");
  expect_refused(g.with(R"("count": 6, "type": "SCALAR")", R"("count": 2, "type": "VEC3")"),
                 index + "holds indices that are not SCALAR");
}

// glTF keeps the largest index of a type for restarting strips: 255 for
// UNSIGNED_BYTE, refused among 300 vertices that index 255 would name.
TEST(GltfRules, IndicesAreNeverTheRestartValue) {
  const Gltf g(300);
  EXPECT_EQ(error_of(g), "");
  expect_refused(g.with(R"(AAECAAID)", R"(AAEC/wID)"), "node 0 'wall': index 3 is 255, the largest of its type");
}

TEST(GltfRules, TheRestartValueOfEachIndexType) {
  EXPECT_TRUE(is_restart_index(TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, 255));
  EXPECT_FALSE(is_restart_index(TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, 254));
  EXPECT_TRUE(is_restart_index(TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, 65535));
  EXPECT_FALSE(is_restart_index(TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, 255));
  EXPECT_TRUE(is_restart_index(TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, 4294967295u));
  EXPECT_FALSE(is_restart_index(TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, 65535));
}

// In a GLB, the buffer without a URI is the BIN chunk: only buffer 0 may
// be it. One of byteLength 0 made tinygltf throw (exit 70).
TEST(GltfRules, OnlyAGlbsFirstBufferIsItsBinChunk) {
  const std::string bin = std::string("\0\0\0\0\0\0\0\0\0\0\0\0", 12);
  auto glb = [&](const std::string& buffers) {
    const std::string json = R"({"asset": {"version": "2.0"}, "buffers": )" + buffers + "}";
    return glb_header(json.size(), bin.size()) + json + glb_between(json.size(), bin.size()) + bin;
  };
  TempFolder dir;
  auto error = [&](const std::string& buffers) {
    write_text(dir / "file.glb", glb(buffers));
    try {
      load_example(dir / "file.glb");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error(R"([{"byteLength": 12}, {"byteLength": 12}])")
                .find("file.glb: error: buffer 1 has no URI: only a GLB's first buffer may be its BIN chunk"),
            std::string::npos);
  EXPECT_NE(error(R"([{"byteLength": 0}])").find("file.glb: error: is not a valid GLB file: tinygltf could not read"),
            std::string::npos);
  // Sound buffers, but no nodes: the loader's own error comes.
  EXPECT_NE(error(R"([{"byteLength": 12}])").find("has no labelled objects"), std::string::npos);
}

}  // namespace
}  // namespace vern
