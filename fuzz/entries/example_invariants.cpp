#include "example_invariants.hpp"

#include <cmath>

#include "graph/label.hpp"

namespace vern::fuzz {

namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const glm::dvec2& v) { return std::isfinite(v.x) && std::isfinite(v.y); }

}  // namespace

std::string mesh_invariants(const Mesh& mesh) {
  std::size_t total = 0;
  for (std::uint32_t n : mesh.face_sizes) {
    if (n < 3) return "a face with " + std::to_string(n) + " corners";
    total += n;
  }
  if (total != mesh.corners.size())
    return "face sizes add up to " + std::to_string(total) + " corners, the mesh has " +
           std::to_string(mesh.corners.size());
  for (const Mesh::Corner& c : mesh.corners) {
    if (c.position >= mesh.positions.size()) return "a corner's position index is out of range";
    if (c.normal != Mesh::kNone && c.normal >= mesh.normals.size()) return "a corner's normal index is out of range";
    if (c.uv != Mesh::kNone && c.uv >= mesh.uvs.size()) return "a corner's uv index is out of range";
  }
  for (const auto& p : mesh.positions)
    if (!finite(p)) return "a position that is not finite";
  for (const auto& n : mesh.normals)
    if (!finite(n)) return "a normal that is not finite";
  for (const auto& t : mesh.uvs)
    if (!finite(t)) return "a texture coordinate that is not finite";
  return "";
}

std::string example_invariants(const Example& example) {
  if (example.boxes.empty()) return "an example without boxes was accepted";
  if (example.positions.size() != example.boxes.size())
    return std::to_string(example.boxes.size()) + " boxes but " + std::to_string(example.positions.size()) +
           " parts' positions";
  const double tolerance = default_tolerance(example);
  Mesh positions;
  for (const LabelledBox& b : example.boxes) {
    const std::string who = "box " + describe_object(b) + ": ";
    if (b.label.empty() || b.object.empty()) return who + "no label or object name";
    // A label that every writer can write, and that reads back the same (graph/label.hpp).
    if (const auto fault = label_fault(b.label)) return who + "a label that " + *fault + " was accepted";
    if (label_of_part_name(name_in_file(b.label)) != b.label) return who + "a label that does not read back the same";
    if (!finite(b.min) || !finite(b.max)) return who + "bounds that are not finite";
    if (b.min.x > b.max.x || b.min.y > b.max.y || b.min.z > b.max.z) return who + "min above max";
    const glm::dvec3 size = b.max - b.min;
    if (size.x <= tolerance && size.y <= tolerance && size.z <= tolerance) return who + "a single point was accepted";
    if (b.mesh != Mesh::kNone) {
      if (b.mesh >= example.meshes.size()) return who + "mesh index out of range";
      const Mesh& mesh = example.meshes[b.mesh];
      if (std::string broken = mesh_invariants(mesh); !broken.empty()) return who + broken;
      if (mesh.min_corner() != b.min || mesh.max_corner() != b.max) return who + "bounds differ from its mesh's";
    }
    example.positions.get(static_cast<std::size_t>(&b - example.boxes.data()), b.min, b.max, positions.positions);
    if (positions.min_corner() != b.min || positions.max_corner() != b.max)
      return who + "bounds differ from its positions'";
    if (glm::any(glm::lessThan(b.min, example.min)) || glm::any(glm::greaterThan(b.max, example.max)))
      return who + "outside the example's bounds";
  }
  return "";
}

std::string library_invariants(const PrimitiveLibrary& library) {
  for (const std::string& name : library.names()) {
    const std::string who = "primitive '" + shown_name(name) + "': ";
    if (const auto fault = label_fault(name)) return who + "a name that " + *fault + " was accepted";
    const Mesh& mesh = *library.find(name);
    if (mesh.face_sizes.empty()) return who + "no faces";
    if (std::string broken = mesh_invariants(mesh); !broken.empty()) return who + broken;
    const glm::dvec3 lo = mesh.min_corner(), hi = mesh.max_corner();
    for (glm::length_t i = 0; i < 3; ++i)
      if (lo[i] != 0.0 || (hi[i] != 0.0 && hi[i] != 1.0)) return who + "does not fill the unit box";
  }
  return "";
}

}  // namespace vern::fuzz
