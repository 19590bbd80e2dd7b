// Polygon meshes: primitive shapes and what is read from OBJ files.
//
// Positions, normals and texture coordinates are separate arrays indexed per
// face corner, as in OBJ. A primitive's mesh lives in the unit box [0,1]^3;
// an instance is placed by Scope::to_world.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

namespace vern {

struct Mesh {
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

  struct Corner {
    std::uint32_t position = 0;
    std::uint32_t normal = kNone;
    std::uint32_t uv = kNone;
    friend bool operator==(const Corner&, const Corner&) = default;
  };

  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;
  std::vector<glm::dvec2> uvs;
  std::vector<Corner> corners;            // all faces' corners, face after face
  std::vector<std::uint32_t> face_sizes;  // corners in each face (>= 3)

  // Axis-aligned bounds of the positions (both zero when empty).
  glm::dvec3 min_corner() const;
  glm::dvec3 max_corner() const;
};

}  // namespace vern
