// An object's loose pieces: found by shared vertices and by shared
// positions (glTF repeats a box's corners for each face's normal).
#include "inverse/load/loose_parts.hpp"

#include <gtest/gtest.h>

namespace vern {
namespace {

// A box's six quads; `shared`: 8 corners (OBJ), else 4 own corners per face
// with a normal each (how glTF stores a flat-shaded box).
void add_box(Mesh& m, glm::dvec3 a, glm::dvec3 b, bool shared) {
  static const int kFaces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  auto corner = [&](int i) { return glm::dvec3((i & 1) ? b.x : a.x, (i & 2) ? b.y : a.y, (i & 4) ? b.z : a.z); };
  const auto base = static_cast<std::uint32_t>(m.positions.size());
  if (shared)
    for (int i = 0; i < 8; ++i) m.positions.push_back(corner(i));
  for (const auto& face : kFaces) {
    const auto normal = static_cast<std::uint32_t>(m.normals.size());
    m.normals.emplace_back(0, 0, 1);
    for (const int i : face) {
      std::uint32_t p = base + static_cast<std::uint32_t>(i);
      if (!shared) {
        p = static_cast<std::uint32_t>(m.positions.size());
        m.positions.push_back(corner(i));
      }
      m.corners.push_back({p, normal, Mesh::kNone});
    }
    m.face_sizes.push_back(4);
  }
}

TEST(LooseParts, AWholeBoxIsOnePieceWhetherCornersAreSharedOrRepeated) {
  for (const bool shared : {true, false}) {
    Mesh m;
    add_box(m, {0, 0, 0}, {1, 2, 3}, shared);
    EXPECT_TRUE(loose_pieces(m).empty()) << shared;
  }
}

TEST(LooseParts, BoxesApartArePiecesInOrderWithTheirOwnVertices) {
  for (const bool shared : {true, false}) {
    Mesh m;
    add_box(m, {4, 0, 0}, {5, 1, 1}, shared);
    add_box(m, {0, 0, 0}, {1, 1, 1}, shared);
    add_box(m, {2, 0, 0}, {3, 1, 1}, shared);
    const std::vector<Mesh> pieces = loose_pieces(m);
    ASSERT_EQ(pieces.size(), 3u) << shared;
    EXPECT_EQ(pieces[0].min_corner(), glm::dvec3(4, 0, 0));
    EXPECT_EQ(pieces[1].max_corner(), glm::dvec3(1, 1, 1));
    for (const Mesh& p : pieces) {
      EXPECT_EQ(p.positions.size(), shared ? 8u : 24u);
      EXPECT_EQ(p.normals.size(), 6u);
      EXPECT_EQ(p.face_sizes.size(), 6u);
      for (const Mesh::Corner& c : p.corners) EXPECT_LT(c.position, p.positions.size());
    }
    EXPECT_TRUE(pieces_apart(pieces, 1e-6));
  }
}

TEST(LooseParts, PiecesMeetAsBoxSplittingSeesOverlaps) {
  auto pieces_of = [](std::vector<std::pair<glm::dvec3, glm::dvec3>> boxes) {
    Mesh m;
    for (const auto& [a, b] : boxes) add_box(m, a, b, true);
    return loose_pieces(m);
  };
  // Sharing a face only, at a hair's distance: apart.
  EXPECT_TRUE(pieces_apart(pieces_of({{{0, 0, 0}, {1, 1, 1}}, {{1 + 1e-9, 0, 0}, {2, 1, 1}}}), 1e-6));
  // One inside the other, or crossing it: they meet.
  EXPECT_FALSE(pieces_apart(pieces_of({{{0, 0, 0}, {3, 3, 3}}, {{1, 1, 1}, {2, 2, 2}}}), 1e-6));
  EXPECT_FALSE(pieces_apart(pieces_of({{{0, 0, 0}, {2, 1, 1}}, {{1, 0.5, 0.5}, {3, 2, 2}}}), 1e-6));
  // A flat pane inside a solid frame meets it; on the frame's face it does not.
  EXPECT_FALSE(pieces_apart(pieces_of({{{0, 0, 0}, {1, 1, 1}}, {{0.2, 0.5, 0.2}, {0.8, 0.5, 0.8}}}), 1e-6));
  EXPECT_TRUE(pieces_apart(pieces_of({{{0, 0, 0}, {1, 1, 1}}, {{0.2, 1, 0.2}, {0.8, 1, 0.8}}}), 1e-6));
}

}  // namespace
}  // namespace vern
