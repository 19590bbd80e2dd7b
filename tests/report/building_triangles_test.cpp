// The triangles pictures are drawn from: derived terminals in their
// scopes, example parts with their own meshes as read.
#include "report/building_triangles.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "inverse/load/layered_parts.hpp"
#include "io/palette.hpp"
#include "support/run_command.hpp"

namespace vern {
namespace {

glm::dvec3 as_vector(Rgb c) { return {c.red, c.green, c.blue}; }

bool within(const glm::dvec3& p, const glm::dvec3& min, const glm::dvec3& max) {
  return glm::all(glm::greaterThanEqual(p, min - 1e-9)) && glm::all(glm::lessThanEqual(p, max + 1e-9));
}

TEST(BuildingTriangles, ATerminalIsItsPrimitiveInItsScopeInItsLabelsColour) {
  Derivation d;
  d.labels = {"rect", "no_such_mesh"};
  Terminal wall;
  wall.label = 0;
  wall.scope.origin = {1, 2, 3};
  wall.scope.size = {2, 3, 4};
  Terminal other = wall;
  other.label = 1;
  other.scope.origin = {10, 0, 0};
  d.terminals = {wall, other};
  const PrimitiveLibrary library = PrimitiveLibrary::builtin();
  const auto tris = derived_triangles(d, library);
  ASSERT_EQ(tris.size(), 24u);  // two boxes: a name the library lacks is the unit box
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const glm::dvec3 lo = i < 12 ? glm::dvec3(1, 2, 3) : glm::dvec3(10, 0, 0);
    for (const glm::dvec3& p : {tris[i].a, tris[i].b, tris[i].c}) EXPECT_TRUE(within(p, lo, lo + glm::dvec3(2, 3, 4)));
    EXPECT_EQ(tris[i].part, i < 12 ? 0u : 1u);
  }
  EXPECT_EQ(tris[0].colour, as_vector(label_colour("rect")));
  EXPECT_EQ(tris[12].colour, as_vector(label_colour("no_such_mesh")));
}

TEST(BuildingTriangles, ExamplePartsKeepTheirOwnMeshesAndCopiesFollowTheFirst) {
  test::TempFolder dir;
  // A gable roof (a prism: two triangles and three quads, eight triangles),
  // its copy 5 m along x, and a part of the same label that is a box.
  const std::string prism = "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nv 0.5 1 0\nv 0.5 1 1\n";
  std::string obj = "# up z\no roof\n" + prism + "f 1 2 5\nf 4 6 3\nf 1 4 3 2\nf 1 5 6 4\nf 2 3 6 5\n";
  obj += "o roof.001\nv 5 0 0\nv 6 0 0\nv 6 0 1\nv 5 0 1\nv 5.5 1 0\nv 5.5 1 1\n";
  obj += "f 7 8 11\nf 10 12 9\nf 7 10 9 8\nf 7 11 12 10\nf 8 9 12 11\n";
  obj += "o roof.002\nv 10 0 0\nv 11 0 0\nv 11 1 0\nv 10 1 0\nv 10 0 1\nv 11 0 1\nv 11 1 1\nv 10 1 1\n";
  obj += "f 13 14 15 16\nf 17 18 19 20\nf 13 14 18 17\nf 14 15 19 18\nf 15 16 20 19\nf 16 13 17 20\n";
  test::write_text(dir / "roofs.obj", obj);
  const Example example = load_example(dir / "roofs.obj");
  ASSERT_EQ(example.boxes.size(), 3u);
  const auto tris = example_triangles(example);
  const auto of_part = [&](std::uint32_t part) {
    std::vector<RasterTriangle> out;
    std::copy_if(tris.begin(), tris.end(), std::back_inserter(out), [&](const RasterTriangle& t) { return t.part == part; });
    return out;
  };
  ASSERT_EQ(of_part(0).size(), 8u);
  ASSERT_EQ(of_part(1).size(), 8u);
  ASSERT_EQ(of_part(2).size(), 12u);
  // The copy's triangles are the first's, 5 m along x: its ridge is there.
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_NEAR(glm::distance(of_part(1)[i].a, of_part(0)[i].a + glm::dvec3(5, 0, 0)), 0.0, 1e-9);
    EXPECT_NEAR(glm::distance(of_part(1)[i].c, of_part(0)[i].c + glm::dvec3(5, 0, 0)), 0.0, 1e-9);
  }
  const auto ridge = std::count_if(tris.begin(), tris.end(), [](const RasterTriangle& t) {
    return t.part == 1 && (glm::distance(t.a, glm::dvec3(5.5, 1, 0)) < 1e-9 || glm::distance(t.b, glm::dvec3(5.5, 1, 0)) < 1e-9 ||
                           glm::distance(t.c, glm::dvec3(5.5, 1, 0)) < 1e-9);
  });
  EXPECT_GT(ridge, 0);
  for (const RasterTriangle& t : of_part(2))
    for (const glm::dvec3& p : {t.a, t.b, t.c}) EXPECT_TRUE(within(p, {10, 0, 0}, {11, 1, 1}));
  EXPECT_EQ(tris[0].colour, as_vector(label_colour("roof")));
}

TEST(BuildingTriangles, PiecesOfAWallAroundItsWindowAreDrawnAsThePiecesNotTheWall) {
  test::TempFolder dir;
  auto box = [](int first, glm::dvec3 lo, glm::dvec3 hi) {
    std::string out;
    for (int c = 0; c < 8; ++c)
      out += "v " + std::to_string(c & 1 ? hi.x : lo.x) + " " + std::to_string(c & 2 ? hi.y : lo.y) + " " +
             std::to_string(c & 4 ? hi.z : lo.z) + "\n";
    const int f[6][4] = {{1, 3, 4, 2}, {5, 6, 8, 7}, {1, 2, 6, 5}, {3, 7, 8, 4}, {1, 5, 7, 3}, {2, 4, 8, 6}};
    for (const auto& q : f)
      out += "f " + std::to_string(first + q[0]) + " " + std::to_string(first + q[1]) + " " + std::to_string(first + q[2]) +
             " " + std::to_string(first + q[3]) + "\n";
    return out;
  };
  test::write_text(dir / "wall.obj", "# up z\no wall\n" + box(0, {0, 0, 0}, {4, 0.3, 3}) + "o window\n" +
                                         box(8, {1.5, 0, 1}, {2.5, 0.3, 2}));
  const Example read = load_example(dir / "wall.obj");
  const Example pieces = visible_parts(read, Layering{{}, example_tolerance(read, 0)});
  ASSERT_GT(pieces.boxes.size(), 2u);  // the wall around its window
  const auto tris = example_triangles(pieces);
  for (const RasterTriangle& t : tris) {
    const LabelledBox& part = pieces.boxes.at(t.part);
    for (const glm::dvec3& p : {t.a, t.b, t.c}) EXPECT_TRUE(within(p, part.min, part.max)) << part.label << " " << t.part;
  }
  EXPECT_EQ(tris.size(), 12 * pieces.boxes.size());
}

}  // namespace
}  // namespace vern
