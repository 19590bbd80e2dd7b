// A mass model's faces read back as comp(f) (comp_faces.hpp): which parts
// lie on which face, in the face's own frame, and what is no mass model.
#include "inverse/split/comp_faces.hpp"

#include <gtest/gtest.h>

#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "inverse/infer.hpp"
#include "support/example_helpers.hpp"

namespace vern {
namespace {

using test::part;

// An open box 10 x 6 x 4: the front of two panels side by side, a left
// wall, a right wall and a roof; no back, no bottom.
std::vector<LabelledBox> open_box() {
  return test::numbered({part("wall", {0, 0, 0}, {4, 0, 4}), part("door", {4, 0, 0}, {10, 0, 4}),
                         part("side", {0, 0, 0}, {0, 6, 4}), part("side", {10, 0, 0}, {10, 6, 4}),
                         part("roof", {0, 0, 4}, {10, 6, 4})});
}

std::vector<std::uint32_t> all(std::size_t n) {
  std::vector<std::uint32_t> out(n);
  for (std::uint32_t i = 0; i < n; ++i) out[i] = i;
  return out;
}

TEST(CompFaces, FlatPartsRoundAnOpenBoxAreItsFacesInTheirOwnFrames) {
  const auto boxes = open_box();
  const auto faces = comp_faces(boxes, all(boxes.size()), {0, 0, 0}, {10, 6, 4}, 1e-9);
  ASSERT_TRUE(faces.has_value());
  ASSERT_EQ(faces->size(), 4u);
  EXPECT_EQ((*faces)[0].face, Face::Front);
  EXPECT_EQ((*faces)[1].face, Face::Left);
  EXPECT_EQ((*faces)[2].face, Face::Right);
  EXPECT_EQ((*faces)[3].face, Face::Top);
  // The front: x along the building's, y up, the door from 4 to 10.
  EXPECT_EQ((*faces)[0].size, glm::dvec3(10, 4, 0));
  EXPECT_EQ((*faces)[0].boxes, (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ((*faces)[0].local[1].min, glm::dvec3(4, 0, 0));
  EXPECT_EQ((*faces)[0].local[1].max, glm::dvec3(10, 4, 0));
  // The left face runs along -y as seen from outside: 6 wide, 4 high.
  EXPECT_EQ((*faces)[1].size, glm::dvec3(6, 4, 0));
  EXPECT_EQ((*faces)[1].local[0].min, glm::dvec3(0, 0, 0));
  EXPECT_EQ((*faces)[1].local[0].max, glm::dvec3(6, 4, 0));
}

TEST(CompFaces, APartOffTheFacesOrAFacePartlyBareIsNoMassModel) {
  auto inside = open_box();
  inside.push_back(part("post", {5, 3, 0}, {5, 4, 4}, 5));  // flat, but inside the box
  EXPECT_FALSE(comp_faces(inside, all(inside.size()), {0, 0, 0}, {10, 6, 4}, 1e-9));
  auto solid = open_box();
  solid.push_back(part("chimney", {8, 4, 4}, {9, 5, 4.5}, 5));  // not flat
  EXPECT_FALSE(comp_faces(solid, all(solid.size()), {0, 0, 0}, {10, 6, 4.5}, 1e-9));
  auto gap = open_box();
  gap[1].min.x = 5;  // a gap in the front between the wall and the door: a nil of the front's split
  EXPECT_TRUE(comp_faces(gap, all(gap.size()), {0, 0, 0}, {10, 6, 4}, 1e-9));
  auto bare = open_box();
  bare[1].max.x = 9;  // the front stops short of its right edge: where would its split end?
  EXPECT_FALSE(comp_faces(bare, all(bare.size()), {0, 0, 0}, {10, 6, 4}, 1e-9));
}

// The CGA idiom: a mass cut into its faces, the front and back in bays of
// a window each, the sides plain, a roof on top.
const char* const kCompHouse =
    "@scope rand(10, 18), rand(8, 12), rand(6, 9)\n"
    "house --> comp(f){ front : facade | back : facade | left : I(wall) | right : I(wall) | top : I(roof) }\n"
    "facade --> repeat(x, 3){ split(x){ ~1 : I(wall) | 1.2 : split(y){ ~1 : I(wall) | 1.4 : I(window) | ~0.6 : "
    "I(wall) } | ~1 : I(wall) } }\n";

TEST(CompFaces, HousesCutIntoFacesByCompInferAsComp) {
  // Flat parts round an open box were a pinwheel ("cannot be separated by
  // straight cuts").
  const Grammar source = parse_grammar(kCompHouse);
  const Inference inferred = infer(test::derived_examples(source, 10), {});
  const std::string text = write_grammar(inferred.grammar);
  EXPECT_NE(text.find("comp(f){"), std::string::npos) << text;
  EXPECT_NE(text.find("1.4 : I(window)"), std::string::npos) << text;  // the window unturned in its face
  // The walls too, on every face: the wall's mesh (from a front wall, in
  // the world) is turned once for all faces, not written turned.
  EXPECT_NE(text.find("left : I(wall)"), std::string::npos) << text;
  EXPECT_EQ(text.find("R("), std::string::npos) << text;
  EXPECT_TRUE(test::source_derives_variants(source, inferred.grammar, 1001, 1040));
}

}  // namespace
}  // namespace vern
