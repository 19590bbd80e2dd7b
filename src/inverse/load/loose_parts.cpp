#include "inverse/load/loose_parts.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

#include "graph/expr.hpp"

namespace vern {

namespace {

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void join(std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

struct PositionHash {
  std::size_t operator()(const glm::dvec3& p) const {
    std::size_t h = 0;
    for (int i = 0; i < 3; ++i) h = hash_combine(h, std::hash<double>()(p[i] == 0.0 ? 0.0 : p[i]));  // -0 == 0
    return h;
  }
};

// Whether two extents along one axis have insides that meet (see the header).
bool meet(double lo_a, double hi_a, double lo_b, double hi_b, double tolerance) {
  const bool flat_a = hi_a - lo_a <= tolerance, flat_b = hi_b - lo_b <= tolerance;
  if (flat_a && flat_b) return std::abs(lo_a - lo_b) <= tolerance;
  if (flat_a) return lo_b + tolerance < lo_a && lo_a < hi_b - tolerance;
  if (flat_b) return lo_a + tolerance < lo_b && lo_b < hi_a - tolerance;
  return std::min(hi_a, hi_b) - std::max(lo_a, lo_b) > tolerance;
}

}  // namespace

std::vector<Mesh> loose_pieces(const Mesh& mesh) {
  const std::size_t n = mesh.positions.size();
  if (mesh.face_sizes.size() < 2 || n == 0) return {};
  UnionFind sets(n);
  auto join_faces = [&] {
    std::size_t start = 0;
    for (const std::uint32_t size : mesh.face_sizes) {
      for (std::uint32_t k = 1; k < size; ++k) sets.join(mesh.corners[start].position, mesh.corners[start + k].position);
      start += size;
    }
  };
  auto whole = [&] {
    const std::uint32_t first = sets.find(mesh.corners.front().position);
    std::size_t start = 0;
    for (const std::uint32_t size : mesh.face_sizes) {
      if (sets.find(mesh.corners[start].position) != first) return false;
      start += size;
    }
    return true;
  };
  // Faces sharing vertices: most meshes (an OBJ box) are whole by this
  // alone, without hashing every position (a million-part example).
  join_faces();
  if (whole()) return {};
  // Vertices at the same position are one vertex.
  std::unordered_map<glm::dvec3, std::uint32_t, PositionHash> first_at;
  first_at.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const auto [it, fresh] = first_at.try_emplace(mesh.positions[i], i);
    if (!fresh) sets.join(i, it->second);
  }
  // Pieces in order of their first face.
  std::unordered_map<std::uint32_t, std::uint32_t> piece_of_root;
  std::size_t start = 0;
  for (const std::uint32_t size : mesh.face_sizes) {
    piece_of_root.try_emplace(sets.find(mesh.corners[start].position), static_cast<std::uint32_t>(piece_of_root.size()));
    start += size;
  }
  if (piece_of_root.size() < 2) return {};

  std::vector<Mesh> pieces(piece_of_root.size());
  // Per piece, the new index of each old position, normal and uv.
  std::vector<std::unordered_map<std::uint32_t, std::uint32_t>> positions(pieces.size()), normals(pieces.size()),
      uvs(pieces.size());
  auto index = [](std::unordered_map<std::uint32_t, std::uint32_t>& map, std::uint32_t old, auto& values,
                  const auto& from) {
    if (old == Mesh::kNone) return Mesh::kNone;
    const auto [it, fresh] = map.try_emplace(old, static_cast<std::uint32_t>(values.size()));
    if (fresh) values.push_back(from[old]);
    return it->second;
  };
  start = 0;
  for (const std::uint32_t size : mesh.face_sizes) {
    const std::uint32_t p = piece_of_root.at(sets.find(mesh.corners[start].position));
    Mesh& piece = pieces[p];
    for (std::uint32_t k = 0; k < size; ++k) {
      const Mesh::Corner& c = mesh.corners[start + k];
      piece.corners.push_back({index(positions[p], c.position, piece.positions, mesh.positions),
                               index(normals[p], c.normal, piece.normals, mesh.normals),
                               index(uvs[p], c.uv, piece.uvs, mesh.uvs)});
    }
    piece.face_sizes.push_back(size);
    start += size;
  }
  return pieces;
}

bool pieces_apart(const std::vector<Mesh>& pieces, double tolerance) {
  std::vector<std::pair<glm::dvec3, glm::dvec3>> boxes;
  for (const Mesh& m : pieces) boxes.emplace_back(m.min_corner(), m.max_corner());
  // Objects hold a few pieces, rarely hundreds: all pairs.
  for (std::size_t a = 0; a < boxes.size(); ++a) {
    for (std::size_t b = a + 1; b < boxes.size(); ++b) {
      bool all = true;
      for (int i = 0; i < 3 && all; ++i)
        all = meet(boxes[a].first[i], boxes[a].second[i], boxes[b].first[i], boxes[b].second[i], tolerance);
      if (all) return false;
    }
  }
  return true;
}

}  // namespace vern
