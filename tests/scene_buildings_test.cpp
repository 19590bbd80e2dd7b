// Files of several buildings read as several examples
// (inverse/load/scene_buildings.hpp): which pieces are buildings, what each
// building holds, and what the user is told.
#include "inverse/load/scene_buildings.hpp"

#include <gtest/gtest.h>

#include "support/example_helpers.hpp"

namespace vern {
namespace {

using test::example_of;

// Part `index` of the file, in group `group` (each part its own by default,
// as Blender exports objects). Each label's first part holds its mesh.
LabelledBox part(const std::string& label, glm::dvec3 min, glm::dvec3 max, std::uint32_t index,
                 std::uint32_t group) {
  LabelledBox b = test::part(label, min, max, index);
  b.mesh = Mesh::kNone;
  b.group = group;
  return b;
}

// A house of a wall with a window set into its face and a roof on top,
// its corner at x0 along x and y0 along y; parts numbered from `first`.
std::vector<LabelledBox> house(double x0, double y0, std::uint32_t first, bool grouped = false) {
  const auto g = [&](std::uint32_t k) { return grouped ? first : first + k; };
  return {part("wall", {x0, y0, 0}, {x0 + 6, y0 + 4, 3}, first, g(0)),
          part("window", {x0 + 2, y0, 1}, {x0 + 3, y0 + 0.2, 2}, first + 1, g(1)),
          part("roof", {x0, y0, 3}, {x0 + 6, y0 + 4, 5}, first + 2, g(2))};
}

// A file of these parts, each label's first part holding a mesh of its own.
Example file_of(std::vector<LabelledBox> boxes) {
  Example e = example_of(std::move(boxes), "street.obj");
  for (LabelledBox& b : e.boxes) {
    bool first = true;
    for (const LabelledBox& other : e.boxes) {
      if (&other == &b) break;
      if (other.label == b.label) first = false;
    }
    if (!first) continue;
    b.mesh = static_cast<std::uint32_t>(e.meshes.size());
    Mesh m;
    m.positions = {b.min, b.max};
    e.meshes.push_back(m);
  }
  return e;
}

// The building as a file of its own would give it.
Example b_alone(Example e) {
  e.file_tolerance = 0;
  return e;
}

std::vector<LabelledBox> joined(std::vector<LabelledBox> a, const std::vector<LabelledBox>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(SceneBuildings, HousesStandingApartAreAnExampleEach) {
  // Three houses: two in a row along x, the third behind the second along
  // y; a fourth part of the first house listed last, as a file may.
  std::vector<LabelledBox> parts = joined(joined(house(0, 0, 0), house(10, 0, 3)), house(10, 9, 6));
  parts.push_back(part("chimney", {1, 1, 5}, {2, 2, 6}, 9, 9));
  const SceneBuildings s = scene_buildings(file_of(parts), BuildingsMode::Apart, 1e-6);
  ASSERT_EQ(s.buildings.size(), 3u);
  EXPECT_EQ(s.buildings[0].source, "street.obj (building 1 of 3)");
  EXPECT_EQ(s.buildings[2].source, "street.obj (building 3 of 3)");
  ASSERT_EQ(s.buildings[0].boxes.size(), 4u);
  EXPECT_EQ(s.buildings[0].boxes[3].label, "chimney");
  EXPECT_EQ(s.buildings[1].boxes.size(), 3u);
  EXPECT_EQ(s.buildings[1].min, glm::dvec3(10, 0, 0));
  EXPECT_EQ(s.buildings[2].min, glm::dvec3(10, 9, 0));
  EXPECT_EQ(s.buildings[2].max, glm::dvec3(16, 13, 5));
  // Each building's first part of a label holds the label's mesh, as a
  // file of that building alone would.
  for (const Example& b : s.buildings) {
    for (std::size_t k = 0; k < 3; ++k) {
      ASSERT_NE(b.boxes[k].mesh, Mesh::kNone) << b.source << " part " << k;
      EXPECT_EQ(b.meshes.at(b.boxes[k].mesh).positions.front(), s.buildings[0].boxes[k].min) << b.source;
    }
  }
  // Each keeps the file's float noise: the exporter wrote them together.
  const double file_noise = default_tolerance(file_of(parts));
  for (const Example& b : s.buildings) EXPECT_EQ(default_tolerance(b), file_noise) << b.source;
  EXPECT_LT(default_tolerance(b_alone(s.buildings[0])), file_noise);
  EXPECT_NE(s.note.find("street.obj holds 3 buildings standing apart"), std::string::npos) << s.note;
  EXPECT_NE(s.note.find("--buildings file"), std::string::npos) << s.note;
}

TEST(SceneBuildings, HousesThatTouchAreOneBuilding) {
  // Wall to wall (a terrace), and within the tolerance of touching.
  const SceneBuildings terrace =
      scene_buildings(file_of(joined(house(0, 0, 0), house(6, 0, 3))), BuildingsMode::Apart, 1e-6);
  EXPECT_EQ(terrace.buildings.size(), 1u);
  EXPECT_EQ(terrace.note, "");
  const SceneBuildings near =
      scene_buildings(file_of(joined(house(0, 0, 0), house(6.0005, 0, 3))), BuildingsMode::Apart, 0.001);
  EXPECT_EQ(near.buildings.size(), 1u);
  const SceneBuildings apart =
      scene_buildings(file_of(joined(house(0, 0, 0), house(6.0015, 0, 3))), BuildingsMode::Apart, 0.001);
  EXPECT_EQ(apart.buildings.size(), 2u);
}

TEST(SceneBuildings, PartsFloatingApartAreNotBuildings) {
  // Windows annotated on a facade without its wall: apart from one
  // another, but only the lowest row stands on the ground.
  std::vector<LabelledBox> windows;
  for (std::uint32_t row = 0; row < 3; ++row)
    for (std::uint32_t column = 0; column < 4; ++column)
      windows.push_back(part("window", {column * 3.0, 0, row * 3.0}, {column * 3.0 + 1, 0.2, row * 3.0 + 1.5},
                             row * 4 + column, row * 4 + column));
  const SceneBuildings s = scene_buildings(file_of(windows), BuildingsMode::Apart, 1e-6);
  ASSERT_EQ(s.buildings.size(), 1u);
  EXPECT_EQ(s.buildings[0].source, "street.obj");
  EXPECT_EQ(s.buildings[0].boxes.size(), 12u);
  EXPECT_EQ(s.note, "");
}

TEST(SceneBuildings, AGroupIsNeverDividedButTheUserIsToldWhatItHolds) {
  // One group holding two houses apart (a city the grammar lays out as
  // one building, written as one glTF node).
  std::vector<LabelledBox> parts = joined(house(0, 0, 0), house(10, 0, 3));
  for (LabelledBox& b : parts) b.group = 7;
  const SceneBuildings whole = scene_buildings(file_of(parts), BuildingsMode::Apart, 1e-6);
  ASSERT_EQ(whole.buildings.size(), 1u);
  EXPECT_EQ(whole.buildings[0].boxes.size(), 6u);
  EXPECT_NE(whole.note.find("street.obj looks like 2 buildings standing apart"), std::string::npos) << whole.note;
  EXPECT_NE(whole.note.find("--buildings parts"), std::string::npos) << whole.note;
  // --buildings parts divides it.
  const SceneBuildings divided = scene_buildings(file_of(parts), BuildingsMode::Parts, 1e-6);
  EXPECT_EQ(divided.buildings.size(), 2u);
}

TEST(SceneBuildings, GroupsAreBuildingsWhereverTheyStandAndAFileIsWholeWhenAsked) {
  // Two houses, each a group, one above the other's yard on a podium of
  // its own group: --buildings groups makes three examples of them.
  std::vector<LabelledBox> parts = joined(house(0, 0, 0, true), house(10, 0, 3, true));
  for (std::size_t k = 3; k < 6; ++k) {
    parts[k].min.z += 1;
    parts[k].max.z += 1;
  }
  parts.push_back(part("podium", {10, 0, 0}, {16, 4, 1}, 6, 6));
  const SceneBuildings groups = scene_buildings(file_of(parts), BuildingsMode::Groups, 1e-6);
  ASSERT_EQ(groups.buildings.size(), 3u);
  EXPECT_EQ(groups.buildings[1].boxes.size(), 3u);
  EXPECT_EQ(groups.buildings[2].boxes[0].label, "podium");
  EXPECT_NE(groups.note.find("holds 3 groups"), std::string::npos) << groups.note;
  // Apart, the second house stands on its podium: two buildings.
  EXPECT_EQ(scene_buildings(file_of(parts), BuildingsMode::Apart, 1e-6).buildings.size(), 2u);
  const SceneBuildings file = scene_buildings(file_of(parts), BuildingsMode::File, 1e-6);
  ASSERT_EQ(file.buildings.size(), 1u);
  EXPECT_EQ(file.buildings[0].boxes.size(), 7u);
  EXPECT_EQ(file.note, "");
}

}  // namespace
}  // namespace vern
