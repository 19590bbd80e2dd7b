// Which way is up in a file, and the quarter turn between the two ways.
//
// Grammars, scopes and inference work z-up: a split(z) stacks storeys.
// glTF is y-up by its specification, and so is Blender's OBJ importer and
// exporter by default (forward -Z, up Y). Files are turned on the way out
// and back on the way in by the same quarter turn about x, which keeps
// handedness (no mirror) and is exact in floating point (a permutation
// with one sign change):
//   grammar (x, y, z)  ->  y-up file (x, z, -y)
// so a grammar's height becomes the file's +y, and Blender, turning y-up
// files back to its own z-up, shows the building standing with its x and y
// where the grammar has them.
#pragma once

#include <optional>
#include <string_view>

#include <glm/glm.hpp>

namespace vern {

enum class UpAxis { Y, Z };

// `0.0 - v` rather than `-v`: a coordinate 0 stays 0, never -0 (which a
// file would print as "-0").
inline glm::dvec3 z_up_to_y_up(const glm::dvec3& v) { return {v.x, v.z, 0.0 - v.y}; }
inline glm::dvec3 y_up_to_z_up(const glm::dvec3& v) { return {v.x, 0.0 - v.z, v.y}; }

// A point or direction of a file with that up axis in the grammar's frame, and back.
inline glm::dvec3 to_z_up(const glm::dvec3& v, UpAxis file) { return file == UpAxis::Y ? y_up_to_z_up(v) : v; }
inline glm::dvec3 from_z_up(const glm::dvec3& v, UpAxis file) { return file == UpAxis::Y ? z_up_to_y_up(v) : v; }

inline const char* up_axis_name(UpAxis up) { return up == UpAxis::Y ? "y" : "z"; }

// "y" or "z" (either case); nothing for anything else.
inline std::optional<UpAxis> parse_up_axis(std::string_view text) {
  if (text == "y" || text == "Y") return UpAxis::Y;
  if (text == "z" || text == "Z") return UpAxis::Z;
  return std::nullopt;
}

}  // namespace vern
