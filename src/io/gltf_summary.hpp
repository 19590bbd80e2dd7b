// What a glTF file holds, read back through tinygltf: the facts tests and
// checks look at (nodes, their transforms and instances, meshes, materials).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace vern {

struct GltfSummary {
  struct Node {
    std::string name;
    int mesh = -1;
    std::vector<int> children;
    std::array<double, 16> matrix{};      // column-major; identity when absent
    std::array<double, 3> translation{};  // zero when absent
    // EXT_mesh_gpu_instancing: each instance's transform T * R * S,
    // column-major, as stored (floats). Empty for a plain node.
    std::vector<std::array<double, 16>> instances;
  };
  struct MeshInfo {
    std::string name;
    int material = -1;
    int position_accessor = -1;          // equal for meshes that share geometry
    std::size_t vertices = 0;            // POSITION count
    std::size_t indices = 0;             // 3 per triangle
    std::array<double, 3> min{}, max{};  // POSITION bounds as stored
  };
  struct MaterialInfo {
    std::string name;
    std::array<double, 4> colour{};  // baseColorFactor
  };
  std::string generator;
  std::vector<std::string> extensions_required;
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
