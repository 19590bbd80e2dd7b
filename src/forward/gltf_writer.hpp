// Writing derived buildings as glTF 2.0 (binary .glb or text .gltf).
//
// Instancing keeps files small: each (primitive, material) pair in use is
// one glTF mesh, shared by all its terminals; its triangles (polygons fanned
// from their first corner; primitive faces are convex) are stored once. The
// node tree is one root per variant, named after it and translated by its
// offset, with one child per terminal named by its label whose matrix maps
// the unit box onto the terminal's scope (columns frame[i] * size[i], then
// the origin). Materials match the OBJ writer's (palette.hpp).
// Same scene, same bytes.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "forward/primitive_library.hpp"
#include "forward/terminal.hpp"

namespace vern {

// The scene as a GLB file's bytes.
std::string glb_bytes(const Scene& scene, const PrimitiveLibrary& library);

// The scene as glTF JSON text with the buffer embedded as a base64 data URI.
std::string gltf_text(const Scene& scene, const PrimitiveLibrary& library);

// Writes a .glb (binary) or .gltf (text) file, chosen by the extension,
// atomically. Throws vern::Error: Usage for another extension, Io when the
// file cannot be written.
void write_gltf(const Scene& scene, const PrimitiveLibrary& library, const std::filesystem::path& path);

// What a glTF file holds, read back through tinygltf: for tests and checks.
struct GltfSummary {
  struct Node {
    std::string name;
    int mesh = -1;
    std::vector<int> children;
    std::array<double, 16> matrix{};     // column-major; identity when absent
    std::array<double, 3> translation{};  // zero when absent
  };
  struct MeshInfo {
    std::string name;
    int material = -1;
    int position_accessor = -1;  // equal for meshes that share geometry
    std::size_t vertices = 0;    // POSITION count
    std::size_t indices = 0;   // 3 per triangle
    std::array<double, 3> min{}, max{};  // POSITION bounds as stored
  };
  struct MaterialInfo {
    std::string name;
    std::array<double, 4> colour{};  // baseColorFactor
  };
  std::string generator;
  std::vector<int> roots;  // the default scene's nodes
  std::vector<Node> nodes;
  std::vector<MeshInfo> meshes;
  std::vector<MaterialInfo> materials;
};

// Parses GLB bytes or glTF text (told apart by the "glTF" magic) and
// summarises it. Throws vern::Error (Input) with tinygltf's message when the
// data is not valid glTF.
GltfSummary summarize_gltf(std::string_view bytes);

}  // namespace vern
