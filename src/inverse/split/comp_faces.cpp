#include "inverse/split/comp_faces.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <string>

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

// A part on a face: where, and its vertices and box in the face's frame.
struct FacePart {
  std::size_t example = 0;
  std::uint32_t box = 0;
  std::vector<glm::dvec3> local;
  glm::dvec3 min{0.0}, max{0.0};
};

// The parts on comp faces below one example's tree.
void face_parts(const SplitTree& tree, const Example& example, std::size_t e, std::vector<FacePart>& out) {
  std::vector<const SplitTree*> stack{&tree};
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
        if (leaf->box >= example.positions.size()) continue;
        FacePart p{e, leaf->box, {}, leaf->min, leaf->max};
        const LabelledBox& box = example.boxes[leaf->box];
        example.positions.get(leaf->box, box.min, box.max, p.local);
        for (glm::dvec3& v : p.local) v = to_local * (v - s.origin);
        out.push_back(std::move(p));
      }
    }
  }
}

// The mesh in the unit box turned as R operations turn a scope: what
// placing it unturned then gives what placing `mesh` turned gave.
Mesh turned_mesh(const Mesh& mesh, const Orientation& turns) {
  Scope s;
  s.size = glm::dvec3(1.0);
  for (const QuarterTurn& t : turns) s = rotated(s, t.axis, t.quarters * (std::numbers::pi / 2));
  Mesh out = mesh;
  for (glm::dvec3& p : out.positions) p = s.to_world(p);
  for (glm::dvec3& n : out.normals) n = s.frame * n;
  return out;
}

}  // namespace

void orient_face_parts(const std::vector<SplitTree>& trees, const std::vector<Example>& examples, double tolerance,
                       PartOrientations& oriented) {
  std::vector<FacePart> parts;
  for (std::size_t e = 0; e < trees.size() && e < examples.size(); ++e) face_parts(trees[e], examples[e], e, parts);
  if (parts.empty()) return;
  auto label_of = [&](const FacePart& p) -> const std::string& { return examples[p.example].boxes[p.box].label; };
  auto tol_of = [&](const FacePart& p) { return vertex_tolerance(examples[p.example].boxes[p.box], tolerance); };
  std::map<std::string, std::vector<std::size_t>> by_label;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const FacePart& p = parts[k];
    by_label[label_of(p)].push_back(k);
    if (p.example >= oriented.turns.size() || p.box >= oriented.turns[p.example].size()) continue;
    const Mesh* mesh = oriented.canonical.find(label_of(p));
    if (mesh == nullptr) continue;
    oriented.turns[p.example][p.box] =
        find_orientation(*mesh, p.local, p.min, p.max, tol_of(p)).value_or(Orientation{});
  }
  // Labels whose every part is on a face, turned alike: rebased.
  std::map<std::string, std::size_t> all;
  for (const Example& e : examples)
    for (const LabelledBox& b : e.boxes) ++all[b.label];
  for (const auto& [label, ks] : by_label) {
    const Mesh* mesh = oriented.canonical.find(label);
    if (mesh == nullptr || ks.size() != all[label]) continue;
    auto turns_of = [&](std::size_t k) -> Orientation& { return oriented.turns[parts[k].example][parts[k].box]; };
    const Orientation first = turns_of(ks.front());
    if (first.empty() || !std::ranges::all_of(ks, [&](std::size_t k) { return turns_of(k) == first; })) continue;
    const Mesh rebased = turned_mesh(*mesh, first);
    // Kept only where every part then needs no turn (checked, not assumed).
    const bool unturned = std::ranges::all_of(ks, [&](std::size_t k) {
      const auto t = find_orientation(rebased, parts[k].local, parts[k].min, parts[k].max, tol_of(parts[k]));
      return t && t->empty();
    });
    if (!unturned) continue;
    oriented.canonical.add(label, rebased);
    for (const std::size_t k : ks) turns_of(k).clear();
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
