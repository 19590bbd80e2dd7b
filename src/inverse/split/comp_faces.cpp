#include "inverse/split/comp_faces.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "forward/scope.hpp"

namespace vern {

namespace {

// The face a part flat along `axis` lies on, at the container's low or
// high end of that axis (face_scope: left at x = min, front at y = min,
// bottom at z = min).
Face face_at(int axis, bool high) {
  switch (axis) {
    case 0: return high ? Face::Right : Face::Left;
    case 1: return high ? Face::Back : Face::Front;
    default: return high ? Face::Top : Face::Bottom;
  }
}

// The order faces are written in: front and back, the sides, top, bottom.
constexpr std::array<Face, 6> kOrder{Face::Front, Face::Back, Face::Left, Face::Right, Face::Top, Face::Bottom};

// The leaves below t (a face's tree), without recursion: trees are deep.
std::vector<const SplitTree*> leaves_below(const SplitTree& t) {
  std::vector<const SplitTree*> out, stack{&t};
  while (!stack.empty()) {
    const SplitTree* n = stack.back();
    stack.pop_back();
    if (n->kind == SplitTree::Kind::Leaf) out.push_back(n);
    for (const SplitTree& c : n->children) stack.push_back(&c);
  }
  return out;
}

}  // namespace

void orient_face_parts(const SplitTree& tree, const Example& example, const PrimitiveLibrary& canonical,
                       double tolerance, std::vector<Orientation>& turns) {
  std::vector<const SplitTree*> stack{&tree};
  std::vector<glm::dvec3> positions;
  while (!stack.empty()) {
    const SplitTree& t = *stack.back();
    stack.pop_back();
    if (t.kind != SplitTree::Kind::Comp) {
      for (const SplitTree& c : t.children) stack.push_back(&c);
      continue;
    }
    const Scope container{t.min, glm::dmat3(1.0), t.max - t.min};
    for (std::size_t f = 0; f < t.children.size(); ++f) {
      const Scope s = face_scope(container, t.faces[f]);
      const glm::dmat3 to_local = glm::transpose(s.frame);
      for (const SplitTree* leaf : leaves_below(t.children[f])) {
        const std::uint32_t b = leaf->box;
        if (b >= example.positions.size() || b >= turns.size()) continue;
        const LabelledBox& box = example.boxes[b];
        const Mesh* mesh = canonical.find(box.label);
        if (mesh == nullptr) continue;
        example.positions.get(b, box.min, box.max, positions);
        for (glm::dvec3& p : positions) p = to_local * (p - s.origin);
        turns[b] = find_orientation(*mesh, positions, leaf->min, leaf->max, vertex_tolerance(box, tolerance))
                       .value_or(Orientation{});
      }
    }
  }
}

std::optional<std::vector<FaceParts>> comp_faces(const std::vector<LabelledBox>& boxes,
                                                 const std::vector<std::uint32_t>& group, glm::dvec3 min,
                                                 glm::dvec3 max, double tolerance) {
  const double tol = std::max(tolerance, 1e-9 * std::max({1.0, glm::length(min), glm::length(max)}));
  std::array<std::vector<std::uint32_t>, 6> on;  // by Face
  for (const std::uint32_t b : group) {
    const LabelledBox& box = boxes[b];
    int flat = -1;
    for (int a = 0; a < 3; ++a) {
      if (box.max[a] - box.min[a] > tol) continue;
      if (flat >= 0) return std::nullopt;  // flat along two axes: a line, on no one face
      flat = a;
    }
    if (flat < 0) return std::nullopt;
    const bool low = std::abs(box.min[flat] - min[flat]) <= tol, high = std::abs(box.max[flat] - max[flat]) <= tol;
    if (low == high) return std::nullopt;  // inside, or a container flat along that axis itself
    on[static_cast<std::size_t>(face_at(flat, high))].push_back(b);
  }
  std::vector<FaceParts> out;
  const Scope container{min, glm::dmat3(1.0), max - min};
  for (const Face f : kOrder) {
    const auto& parts = on[static_cast<std::size_t>(f)];
    if (parts.empty()) continue;
    const Scope s = face_scope(container, f);
    FaceParts face;
    face.face = f;
    face.boxes = parts;
    face.size = s.size;
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    const glm::dmat3 to_local = glm::transpose(s.frame);
    for (const std::uint32_t b : parts) {
      LabelledBox local = boxes[b];
      const glm::dvec3 p = to_local * (boxes[b].min - s.origin), q = to_local * (boxes[b].max - s.origin);
      local.min = glm::min(p, q);
      local.max = glm::max(p, q);
      local.min.z = local.max.z = 0;  // on the face
      lo = glm::min(lo, local.min);
      hi = glm::max(hi, local.max);
      face.local.push_back(std::move(local));
    }
    // The face's parts cover it from end to end (a facade and its walls):
    // its split begins at the face's corner.
    for (int a = 0; a < 2; ++a)
      if (std::abs(lo[a]) > tol || std::abs(hi[a] - s.size[a]) > tol) return std::nullopt;
    out.push_back(std::move(face));
  }
  if (out.size() < 2) return std::nullopt;
  return out;
}

}  // namespace vern
