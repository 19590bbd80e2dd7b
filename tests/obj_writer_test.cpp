// The OBJ writer: one object per terminal at its scope, absolute indices,
// materials, and a round trip through the OBJ reader.
#include "io/obj_writer.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/error.hpp"
#include "graph/label.hpp"
#include "io/obj_reader.hpp"
#include "support/scene_helpers.hpp"

namespace vern {
namespace {

namespace fs = std::filesystem;

using test::kQuarterTurnZ;
using test::terminal;

// A wall box and a window on a frame turned about z.
Scene two_terminal_scene() {
  Scene scene;
  scene.labels = {"rect", "window"};
  Variant v;
  v.name = "variant_000";
  v.terminals.push_back(terminal(0, {1, 2, 3}, {2, 3, 4}));
  v.terminals.push_back(terminal(1, {10, 0, 0}, {4, 0.5, 2}, kQuarterTurnZ));
  scene.variants.push_back(v);
  return scene;
}

// World bounds of a scope's eight corners, moved by offset.
std::pair<glm::dvec3, glm::dvec3> scope_bounds(const Scope& s, glm::dvec3 offset = glm::dvec3(0.0)) {
  glm::dvec3 lo(1e300), hi(-1e300);
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 p = s.to_world(glm::dvec3(i & 1, (i >> 1) & 1, (i >> 2) & 1)) + offset;
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return {lo, hi};
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<ObjObject> read_back(const std::string& text) {
  std::istringstream in(text);
  return read_obj(in, "written.obj");
}

void expect_near(glm::dvec3 a, glm::dvec3 b) {
  EXPECT_NEAR(a.x, b.x, 1e-12);
  EXPECT_NEAR(a.y, b.y, 1e-12);
  EXPECT_NEAR(a.z, b.z, 1e-12);
}

TEST(ObjWriter, OneObjectPerTerminalWithItsMaterial) {
  const std::string text = obj_text(two_terminal_scene(), PrimitiveLibrary::builtin(), "house.mtl");
  const auto lines = lines_of(text);
  std::vector<std::string> statements;  // everything but v/vt/vn/f
  for (const std::string& l : lines) {
    if (!l.starts_with("v") && !l.starts_with("f")) statements.push_back(l);
  }
  EXPECT_EQ(statements, (std::vector<std::string>{
                            "# Written by Vernacular: one object per terminal, named by its label.",
                            "# up y", "mtllib house.mtl", "g variant_000", "o rect", "usemtl rect", "o window",
                            "usemtl window"}));
}

TEST(ObjWriter, VerticesSitAtTheScopeCornersWithAbsoluteIndices) {
  const PrimitiveLibrary lib = PrimitiveLibrary::builtin();
  const std::string text = obj_text(two_terminal_scene(), lib, "", UpAxis::Z);
  const auto lines = lines_of(text);
  // The box's vertices are exactly the scope's corners (z-up: as the grammar has them).
  std::vector<std::string> box_vertices;
  std::size_t i = 0;
  while (lines[i] != "o rect") ++i;
  for (++i; lines[i] != "o window"; ++i) {
    if (lines[i].starts_with("v ")) box_vertices.push_back(lines[i]);
  }
  ASSERT_EQ(box_vertices.size(), 8u);
  for (const char* corner : {"v 1 2 3", "v 3 2 3", "v 1 5 3", "v 3 5 7", "v 1 2 7"}) {
    EXPECT_NE(std::find(box_vertices.begin(), box_vertices.end(), corner), box_vertices.end()) << corner;
  }
  // The window's faces use indices after the box's 8 vertices, up to its own count.
  const std::size_t window_vertices = lib.find("window")->positions.size();
  std::size_t lowest = SIZE_MAX, highest = 0;
  for (++i; i < lines.size(); ++i) {
    if (!lines[i].starts_with("f ")) continue;
    std::istringstream corners(lines[i].substr(2));
    for (std::string c; corners >> c;) {
      const std::size_t v = std::stoul(c.substr(0, c.find('/')));
      lowest = std::min(lowest, v);
      highest = std::max(highest, v);
    }
  }
  EXPECT_EQ(lowest, 9u);
  EXPECT_EQ(highest, 8u + window_vertices);
}

TEST(ObjWriter, ReadsBackAsTheSameLabelsAndScopeBounds) {
  const Scene scene = two_terminal_scene();
  const auto objects = read_back(obj_text(scene, PrimitiveLibrary::builtin(), "house.mtl"));
  ASSERT_EQ(objects.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const Terminal& t = scene.variants[0].terminals[i];
    EXPECT_EQ(objects[i].name, scene.labels[t.label]);
    const auto [lo, hi] = scope_bounds(t.scope);
    expect_near(objects[i].mesh.min_corner(), lo);
    expect_near(objects[i].mesh.max_corner(), hi);
  }
  // The turned window spans x in [9.5, 10], y in [0, 4].
  expect_near(objects[1].mesh.min_corner(), {9.5, 0, 0});
  expect_near(objects[1].mesh.max_corner(), {10, 4, 2});
}

// Labels OBJ cannot hold as they are ('#' starts a comment, a final '\'
// continues the line, ".2" reads as a copy number) come back the same from
// the reader (graph/label.hpp), and each label has a material of its own.
TEST(ObjWriter, EveryLabelReadsBackAsItselfWithAMaterialOfItsOwn) {
  Scene scene;
  scene.labels = {"#x", "a b", "a_b", "a#b", "v1.2", "50%", "back\\", "colour_ff0000", "label_colour_ff0000",
                  "fen\xC3\xAAtre", "fen__tre", "window"};
  Variant v;
  v.name = "variant_000";
  for (std::size_t i = 0; i < scene.labels.size(); ++i)
    v.terminals.push_back(terminal(static_cast<LabelId>(i), {2.0 * static_cast<double>(i), 0, 0}, {1, 1, 1}));
  Terminal red = terminal(0, {-2, 0, 0}, {1, 1, 1});
  red.coloured = true;
  red.colour = {1, 0, 0};
  v.terminals.push_back(red);
  scene.variants.push_back(v);

  const std::string text = obj_text(scene, PrimitiveLibrary::builtin(), "x.mtl");
  const auto objects = read_back(text);
  ASSERT_EQ(objects.size(), scene.labels.size() + 1) << text;
  for (std::size_t i = 0; i < scene.labels.size(); ++i)
    EXPECT_EQ(label_of_part_name(objects[i].name), scene.labels[i]) << objects[i].name;

  std::vector<std::string> materials;
  for (const std::string& line : lines_of(text))
    if (line.starts_with("usemtl ")) materials.push_back(line.substr(7));
  ASSERT_EQ(materials.size(), scene.labels.size() + 1);
  EXPECT_EQ(materials[1], "a%20b");
  EXPECT_EQ(materials[2], "a_b");
  EXPECT_EQ(materials[3], "a%23b");
  EXPECT_EQ(materials[7], "label_colour_ff0000");
  EXPECT_EQ(materials[8], "label_label_colour_ff0000");
  EXPECT_EQ(materials[11], "window");
  EXPECT_EQ(materials.back(), "colour_ff0000");
  std::sort(materials.begin(), materials.end());
  EXPECT_EQ(std::adjacent_find(materials.begin(), materials.end()), materials.end()) << "two labels share a material";
  for (const std::string& m : materials) EXPECT_EQ(m.find_first_of(" #"), std::string::npos) << m;
  const std::string mtl = mtl_text(scene);
  std::size_t defined = 0;
  for (const std::string& line : lines_of(mtl)) defined += line.starts_with("newmtl ") ? 1 : 0;
  EXPECT_EQ(defined, materials.size()) << mtl;
}

// Every face's normal is a unit vector perpendicular to the face and on the
// side its winding says.
void expect_normals_fit_faces(const Mesh& m, const std::string& what) {
  std::size_t c = 0;
  for (std::uint32_t size : m.face_sizes) {
    const glm::dvec3 n = m.normals.at(m.corners[c].normal);
    EXPECT_NEAR(glm::length(n), 1.0, 1e-12) << what;
    glm::dvec3 winding(0.0);
    for (std::uint32_t k = 0; k < size; ++k) {
      const glm::dvec3 a = m.positions[m.corners[c + k].position];
      const glm::dvec3 b = m.positions[m.corners[c + (k + 1) % size].position];
      EXPECT_NEAR(glm::dot(b - a, n), 0.0, 1e-9) << what;
      winding += glm::cross(a, b);
    }
    if (glm::length(winding) > 1e-9) {
      EXPECT_GT(glm::dot(winding, n), 0.0) << what;
    }
    c += size;
  }
}

TEST(ObjWriter, NormalsFollowRotationAndStretching) {
  Scene scene;
  scene.labels = {"window", "roof", "hip"};
  Variant v;
  v.name = "v";
  v.terminals.push_back(terminal(0, {10, 0, 0}, {4, 0.5, 2}, kQuarterTurnZ));
  v.terminals.push_back(terminal(1, {0, 0, 5}, {10, 4, 2}));               // stretched: slopes change
  v.terminals.push_back(terminal(2, {0, 0, 5}, {6, 3, 1}, kQuarterTurnZ));  // both
  v.terminals.push_back(terminal(0, {0, 0, 0}, {2, 0, 3}));                 // flat: zero depth
  scene.variants.push_back(v);
  const auto objects = read_back(obj_text(scene, PrimitiveLibrary::builtin(), ""));
  ASSERT_EQ(objects.size(), 4u);
  for (std::size_t i = 0; i < 3; ++i) expect_normals_fit_faces(objects[i].mesh, objects[i].name);
  // The window's front (unit -y) faces world +x after the quarter turn.
  const auto& n = objects[0].mesh.normals;
  EXPECT_NE(std::find_if(n.begin(), n.end(), [](auto& x) { return glm::distance(x, glm::dvec3(1, 0, 0)) < 1e-12; }),
            n.end());
  // A zero-depth scope still has finite unit normals.
  for (const glm::dvec3& x : objects[3].mesh.normals) EXPECT_NEAR(glm::length(x), 1.0, 1e-12);
}

TEST(ObjWriter, VariantOffsetsUnknownLabelsAndColours) {
  Scene scene;
  scene.labels = {"balcony", "rect"};
  Variant a;
  a.name = "variant_000";
  a.terminals.push_back(terminal(0, {0, 0, 0}, {1, 1, 1}));
  Variant b;
  b.name = "variant_001";
  b.offset = {100, 0, 0};
  Terminal red = terminal(1, {0, 0, 0}, {1, 2, 3});
  red.coloured = true;
  red.colour = {1, 0, 0};
  b.terminals.push_back(red);
  b.terminals.push_back(terminal(0, {0, 0, 0}, {1, 1, 1}));
  scene.variants = {a, b};

  const PrimitiveLibrary lib = PrimitiveLibrary::builtin();
  const std::string text = obj_text(scene, lib, "x.mtl");
  EXPECT_NE(text.find("g variant_000\no balcony\nusemtl balcony\n"), std::string::npos) << text;
  EXPECT_NE(text.find("g variant_001\no rect\nusemtl colour_ff0000\n"), std::string::npos) << text;
  const auto objects = read_back(text);
  ASSERT_EQ(objects.size(), 3u);
  EXPECT_EQ(objects[0].mesh.positions.size(), lib.box().positions.size());  // unknown: a box
  expect_near(objects[1].mesh.min_corner(), {100, 0, 0});
  expect_near(objects[1].mesh.max_corner(), {101, 2, 3});

  const std::string mtl = mtl_text(scene);
  EXPECT_NE(mtl.find("newmtl balcony\nKd "), std::string::npos) << mtl;
  EXPECT_NE(mtl.find("newmtl colour_ff0000\nKd 1 0 0\n"), std::string::npos) << mtl;
  EXPECT_EQ(mtl.find("newmtl balcony", mtl.find("newmtl balcony") + 1), std::string::npos) << "defined twice";
}

TEST(ObjWriter, SameSceneSameBytes) {
  const PrimitiveLibrary lib = PrimitiveLibrary::builtin();
  EXPECT_EQ(obj_text(two_terminal_scene(), lib, "a.mtl"), obj_text(two_terminal_scene(), lib, "a.mtl"));
}

TEST(ObjWriter, WritesObjAndSiblingMtl) {
  const fs::path dir = fs::temp_directory_path() / ("vern-objwriter-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const Scene scene = two_terminal_scene();
  write_obj(scene, PrimitiveLibrary::builtin(), dir / "house.obj");
  ASSERT_TRUE(fs::exists(dir / "house.mtl"));
  const auto objects = read_obj_file(dir / "house.obj");
  EXPECT_EQ(objects.size(), 2u);
  std::ifstream obj(dir / "house.obj");
  std::string first, second, third;
  std::getline(obj, first);
  std::getline(obj, second);
  std::getline(obj, third);
  EXPECT_EQ(second, "# up y");
  EXPECT_EQ(third, "mtllib house.mtl");
  std::ifstream mtl(dir / "house.mtl");
  const std::string mtl_contents((std::istreambuf_iterator<char>(mtl)), {});
  EXPECT_EQ(mtl_contents, mtl_text(scene));
  // A folder that is not there: an Io error, nothing written.
  EXPECT_THROW(write_obj(scene, PrimitiveLibrary::builtin(), dir / "missing" / "house.obj"), Error);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vern
