#include "report/building_triangles.hpp"

#include <algorithm>
#include <map>
#include <string>

#include "graph/label.hpp"
#include "io/palette.hpp"

namespace vern {

namespace {

glm::dvec3 as_vector(Rgb c) { return {c.red, c.green, c.blue}; }

// A face of n corners as the fan of n - 2 triangles about its first.
template <typename Place>
void add_faces(const Mesh& mesh, const Place& place, const glm::dvec3& colour, std::uint32_t part,
               std::vector<RasterTriangle>& out) {
  std::size_t first = 0;
  for (const std::uint32_t n : mesh.face_sizes) {
    for (std::uint32_t k = 1; k + 1 < n; ++k)
      out.push_back({place(mesh.corners[first].position), place(mesh.corners[first + k].position),
                     place(mesh.corners[first + k + 1].position), colour, part});
    first += n;
  }
}

void add_box(const glm::dvec3& min, const glm::dvec3& max, const glm::dvec3& colour, std::uint32_t part,
             std::vector<RasterTriangle>& out) {
  auto at = [&](int corner) {
    return glm::dvec3(corner & 1 ? max.x : min.x, corner & 2 ? max.y : min.y, corner & 4 ? max.z : min.z);
  };
  // Six faces as corner numbers (bit k: at max on axis k), two triangles each.
  static constexpr int kFaces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  for (const auto& f : kFaces) {
    out.push_back({at(f[0]), at(f[1]), at(f[2]), colour, part});
    out.push_back({at(f[0]), at(f[2]), at(f[3]), colour, part});
  }
}

// A point of the box from min to max in the unit box's coordinates.
glm::dvec3 unit(const glm::dvec3& p, const glm::dvec3& min, const glm::dvec3& max) {
  const glm::dvec3 size = max - min;
  return {size.x > 0 ? (p.x - min.x) / size.x : 0.0, size.y > 0 ? (p.y - min.y) / size.y : 0.0,
          size.z > 0 ? (p.z - min.z) / size.z : 0.0};
}

constexpr double kSame = 1e-6;  // of a box's size

// Whether these positions span exactly the part's box.
bool fills(const std::vector<glm::dvec3>& positions, const LabelledBox& box) {
  if (positions.empty()) return false;
  glm::dvec3 lo = positions.front(), hi = positions.front();
  for (const glm::dvec3& p : positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const double size = std::max(1.0, glm::length(box.max - box.min));
  return glm::length(lo - box.min) <= kSame * size && glm::length(hi - box.max) <= kSame * size;
}

// Whether `copy` is `first`'s vertices, in the same order, moved, scaled or
// turned by quarter turns about z into the part's box: a copy, as
// modelling tools make them, whose faces are the first's. Pieces of a part
// painted over list their box's corners in another order.
bool copies(const std::vector<glm::dvec3>& first, const std::vector<glm::dvec3>& copy, const LabelledBox& box) {
  if (first.size() != copy.size() || first.empty()) return false;
  glm::dvec3 lo = first.front(), hi = first.front();
  for (const glm::dvec3& p : first) lo = glm::min(lo, p), hi = glm::max(hi, p);
  for (int turn = 0; turn < 4; ++turn) {
    bool all = true;
    for (std::size_t i = 0; i < first.size() && all; ++i) {
      const glm::dvec3 u = unit(first[i], lo, hi);
      const glm::dvec3 turned = turn == 0 ? u
                                : turn == 1 ? glm::dvec3(1 - u.y, u.x, u.z)
                                : turn == 2 ? glm::dvec3(1 - u.x, 1 - u.y, u.z)
                                            : glm::dvec3(u.y, 1 - u.x, u.z);
      all = glm::length(turned - unit(copy[i], box.min, box.max)) <= kSame;
    }
    if (all) return true;
  }
  return false;
}

}  // namespace

std::vector<RasterTriangle> derived_triangles(const Derivation& building, const PrimitiveLibrary& library) {
  std::vector<RasterTriangle> out;
  for (std::size_t i = 0; i < building.terminals.size(); ++i) {
    const Terminal& t = building.terminals[i];
    const std::string& label = building.labels.at(t.label);
    const Mesh* found = library.find(label);
    const Mesh& mesh = found ? *found : library.box();
    const glm::dvec3 colour = as_vector(terminal_material(t, label).colour);
    add_faces(mesh, [&](std::uint32_t p) { return t.scope.to_world(mesh.positions[p]); }, colour,
              static_cast<std::uint32_t>(i), out);
  }
  return out;
}

std::vector<RasterTriangle> example_triangles(const Example& example) {
  std::vector<RasterTriangle> out;
  std::map<std::string, std::uint32_t, std::less<>> first_mesh;  // label -> its first part's mesh
  std::vector<glm::dvec3> positions;
  for (std::size_t i = 0; i < example.boxes.size(); ++i) {
    const LabelledBox& box = example.boxes[i];
    const auto part = static_cast<std::uint32_t>(i);
    const glm::dvec3 colour = as_vector(label_colour(label_as_word(box.label)));
    if (box.mesh != Mesh::kNone && box.mesh < example.meshes.size()) {
      first_mesh.emplace(box.label, box.mesh);
      const Mesh& mesh = example.meshes[box.mesh];
      // A piece of a part painted over (layered_parts.hpp) keeps its
      // label's mesh, which is the whole part's: its box is drawn instead.
      if (fills(mesh.positions, box)) {
        add_faces(mesh, [&](std::uint32_t p) { return mesh.positions[p]; }, colour, part, out);
        continue;
      }
    } else if (const auto label_mesh = first_mesh.find(box.label);
               label_mesh != first_mesh.end() && i < example.positions.size()) {
      const Mesh& mesh = example.meshes[label_mesh->second];
      example.positions.get(i, box.min, box.max, positions);
      if (copies(mesh.positions, positions, box)) {
        add_faces(mesh, [&](std::uint32_t p) { return positions[p]; }, colour, part, out);
        continue;
      }
    }
    add_box(box.min, box.max, colour, part, out);
  }
  return out;
}

}  // namespace vern
