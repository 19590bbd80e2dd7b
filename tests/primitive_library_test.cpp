// The primitive library: the built-in meshes are closed solids filling the
// unit box with outward normals; loaded meshes are normalised and replace
// built-ins.
#include "forward/primitive_library.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>

#include "base/error.hpp"

namespace vern {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kBuiltins = {"corner", "door",     "hip",     "pyramid", "rect",
                                            "right_angle_triangle", "roof", "triangle", "trough", "window"};

struct Face {
  std::vector<glm::dvec3> points;
  std::vector<glm::dvec3> normals;
};

std::vector<Face> faces_of(const Mesh& m) {
  std::vector<Face> faces;
  std::size_t c = 0;
  for (std::uint32_t size : m.face_sizes) {
    Face f;
    for (std::uint32_t k = 0; k < size; ++k, ++c) {
      f.points.push_back(m.positions[m.corners[c].position]);
      f.normals.push_back(m.corners[c].normal == Mesh::kNone ? glm::dvec3(0.0) : m.normals[m.corners[c].normal]);
    }
    faces.push_back(std::move(f));
  }
  return faces;
}

glm::dvec3 centroid(const Face& f) {
  glm::dvec3 c(0.0);
  for (const glm::dvec3& p : f.points) c += p;
  return c / static_cast<double>(f.points.size());
}

// Newell's normal: the direction the winding says the face looks.
glm::dvec3 winding_normal(const Face& f) {
  glm::dvec3 n(0.0);
  for (std::size_t i = 0; i < f.points.size(); ++i) {
    const glm::dvec3& a = f.points[i];
    const glm::dvec3& b = f.points[(i + 1) % f.points.size()];
    n += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  return glm::normalize(n);
}

// Distances along the ray at which it crosses the mesh's faces (fanned into
// triangles; Moeller-Trumbore).
std::vector<double> hits(const Mesh& m, const glm::dvec3& from, const glm::dvec3& dir) {
  std::vector<double> out;
  for (const Face& f : faces_of(m)) {
    for (std::size_t k = 1; k + 1 < f.points.size(); ++k) {
      const glm::dvec3 e1 = f.points[k] - f.points[0], e2 = f.points[k + 1] - f.points[0];
      const glm::dvec3 p = glm::cross(dir, e2);
      const double det = glm::dot(e1, p);
      if (std::abs(det) < 1e-12) continue;
      const glm::dvec3 s = from - f.points[0];
      const double u = glm::dot(s, p) / det;
      const glm::dvec3 q = glm::cross(s, e1);
      const double v = glm::dot(dir, q) / det;
      const double t = glm::dot(e2, q) / det;
      if (u >= 0 && v >= 0 && u + v <= 1 && t > 0) out.push_back(t);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Inside a closed surface: a ray from the point crosses it an odd number of
// times. The direction is skewed so that it misses edges and vertices.
bool inside(const Mesh& m, const glm::dvec3& p) {
  return hits(m, p, glm::normalize(glm::dvec3(0.5772, 0.3217, 0.7531))).size() % 2 == 1;
}

TEST(PrimitiveLibrary, HasEveryBuiltinSorted) {
  const PrimitiveLibrary lib = PrimitiveLibrary::builtin();
  const std::vector<std::string> names = lib.names();
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
  for (const std::string& name : kBuiltins) EXPECT_NE(lib.find(name), nullptr) << name;
  EXPECT_EQ(lib.find("no_such_primitive"), nullptr);
  EXPECT_EQ(&lib.box(), lib.find("rect"));
  EXPECT_EQ(lib.box().face_sizes.size(), 6u);
}

TEST(PrimitiveLibrary, BuiltinsAreParsedOnceAndShared) {
  const PrimitiveLibrary a = PrimitiveLibrary::builtin();
  const PrimitiveLibrary b = PrimitiveLibrary::builtin();
  EXPECT_EQ(a.find("window"), b.find("window"));
}

TEST(PrimitiveLibrary, BuiltinsFillTheUnitBoxExactly) {
  const PrimitiveLibrary lib = PrimitiveLibrary::builtin();
  for (const std::string& name : kBuiltins) {
    const Mesh& m = *lib.find(name);
    EXPECT_EQ(m.min_corner(), glm::dvec3(0.0)) << name;
    EXPECT_EQ(m.max_corner(), glm::dvec3(1.0)) << name;
  }
}

TEST(PrimitiveLibrary, BuiltinsAreClosedWithOutwardFlatNormalsAndMatchingWinding) {
  const PrimitiveLibrary lib = PrimitiveLibrary::builtin();
  for (const std::string& name : kBuiltins) {
    const Mesh& m = *lib.find(name);
    ASSERT_FALSE(m.face_sizes.empty()) << name;
    double volume = 0;  // divergence theorem: sum of centroid . normal * area / 3
    const auto faces = faces_of(m);
    for (std::size_t i = 0; i < faces.size(); ++i) {
      const Face& f = faces[i];
      const glm::dvec3 n = f.normals[0];
      for (const glm::dvec3& corner_normal : f.normals) {
        EXPECT_EQ(corner_normal, n) << name << " face " << i << ": not flat";
      }
      EXPECT_NEAR(glm::length(n), 1.0, 1e-12) << name << " face " << i;
      EXPECT_GT(glm::dot(winding_normal(f), n), 1 - 1e-9) << name << " face " << i << ": winding disagrees";
      // Just outside the face is outside the solid, just inside is inside.
      const glm::dvec3 c = centroid(f);
      EXPECT_FALSE(inside(m, c + 1e-4 * n)) << name << " face " << i << ": normal points inwards";
      EXPECT_TRUE(inside(m, c - 1e-4 * n)) << name << " face " << i << ": surface not closed";
      double area2 = 0;
      for (std::size_t k = 1; k + 1 < f.points.size(); ++k) {
        area2 += glm::length(glm::cross(f.points[k] - f.points[0], f.points[k + 1] - f.points[0]));
      }
      volume += glm::dot(c, n) * area2 / 6.0;
    }
    EXPECT_GT(volume, 0.05) << name;
    EXPECT_FALSE(m.uvs.empty()) << name;
    for (const Mesh::Corner& c : m.corners) EXPECT_NE(c.uv, Mesh::kNone) << name;
  }
}

// Height-field roofs: every vertex is on the base or on the named surface.
void expect_surface(const Mesh& m, const char* name, double (*height)(double, double)) {
  for (const glm::dvec3& p : m.positions) {
    if (p.z != 0.0) {
      EXPECT_DOUBLE_EQ(p.z, height(p.x, p.y)) << name << " vertex " << p.x << " " << p.y;
    }
  }
}

TEST(PrimitiveLibrary, RoofShapesAreTheSpecifiedSurfaces) {
  const PrimitiveLibrary lib = PrimitiveLibrary::builtin();
  // Gables: ridge along x at y = 0.5.
  for (const char* gable : {"roof", "triangle"}) {
    expect_surface(*lib.find(gable), gable, [](double, double y) { return 1.0 - 2.0 * std::abs(y - 0.5); });
    EXPECT_EQ(lib.find(gable)->positions.size(), 6u) << gable;
  }
  expect_surface(*lib.find("right_angle_triangle"), "right_angle_triangle", [](double x, double) { return 1.0 - x; });
  expect_surface(*lib.find("pyramid"), "pyramid", [](double x, double y) {
    return 1.0 - 2.0 * std::max(std::abs(x - 0.5), std::abs(y - 0.5));
  });
  expect_surface(*lib.find("corner"), "corner", [](double x, double y) { return std::min(x, y); });
  expect_surface(*lib.find("trough"), "trough", [](double x, double y) { return std::max(x, y); });
  // The hip's ridge runs from (0.25, 0.5) to (0.75, 0.5).
  std::vector<glm::dvec3> top;
  for (const glm::dvec3& p : lib.find("hip")->positions) {
    if (p.z != 0.0) top.push_back(p);
  }
  std::sort(top.begin(), top.end(), [](auto& a, auto& b) { return a.x < b.x; });
  ASSERT_EQ(top.size(), 2u);
  EXPECT_EQ(top[0], glm::dvec3(0.25, 0.5, 1));
  EXPECT_EQ(top[1], glm::dvec3(0.75, 0.5, 1));
  // The corner's only raised vertex is over (1, 1); the trough's top edges
  // are at x = 1 and y = 1.
  for (const glm::dvec3& p : lib.find("corner")->positions) {
    if (p.z != 0.0) {
      EXPECT_EQ(p, glm::dvec3(1, 1, 1));
    }
  }
  EXPECT_EQ(lib.find("trough")->positions.size(), 7u);
}

TEST(PrimitiveLibrary, WindowAndDoorAreFramedRecessedSlabs) {
  const PrimitiveLibrary lib = PrimitiveLibrary::builtin();
  const glm::dvec3 along_y(0, 1, 0);
  for (const char* name : {"window", "door"}) {
    const Mesh& m = *lib.find(name);
    // Through the middle (off the fan diagonals): the slab sits back from
    // the front (y = 0).
    const auto middle = hits(m, glm::dvec3(0.47, -1, 0.53), along_y);
    ASSERT_EQ(middle.size(), 2u) << name;
    EXPECT_GT(middle[0] - 1, 0.3) << name;
    EXPECT_LT(middle[1] - 1, 0.7) << name;
    // Through a side bar (bar width 0.1): solid from front to back.
    const auto bar = hits(m, glm::dvec3(0.04, -1, 0.43), along_y);
    ASSERT_EQ(bar.size(), 2u) << name;
    EXPECT_DOUBLE_EQ(bar[0], 1.0);
    EXPECT_DOUBLE_EQ(bar[1], 2.0);
    EXPECT_TRUE(inside(m, glm::dvec3(0.5, 0.5, 0.95))) << name << ": no top bar";
  }
  // A window has a sill bar; a door's slab reaches the floor.
  EXPECT_TRUE(inside(*lib.find("window"), glm::dvec3(0.5, 0.2, 0.05)));
  EXPECT_FALSE(inside(*lib.find("door"), glm::dvec3(0.5, 0.2, 0.05)));
  EXPECT_TRUE(inside(*lib.find("door"), glm::dvec3(0.5, 0.5, 0.05)));
}

class TempDir {
 public:
  TempDir() {
    path_ = fs::temp_directory_path() /
            ("vern-primlib-" + std::to_string(::getpid()) + "-" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  const fs::path& path() const { return path_; }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(path_ / name, std::ios::binary) << text;
    return path_ / name;
  }

 private:
  fs::path path_;
};

// A 2 x 4 x 6 box at (10, 10, 10), without normals or texture coordinates.
const char* kBigBox =
    "v 10 10 10\nv 12 10 10\nv 12 14 10\nv 10 14 10\n"
    "v 10 10 16\nv 12 10 16\nv 12 14 16\nv 10 14 16\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 3 4 8 7\nf 2 3 7 6\nf 4 1 5 8\n";

TEST(PrimitiveLibrary, LoadedFolderReplacesBuiltinsAndAddsByFileStem) {
  TempDir dir;
  dir.write("rect.obj", std::string("o cube\n") + kBigBox);
  dir.write("balcony.obj",
            "v 0 0 0\nv 3 0 0\nv 3 1 0\nv 0 1 1\n"
            "o slab\nf 1 2 3\no rail\nf 1 3 4\n");
  dir.write("notes.txt", "not a primitive");
  PrimitiveLibrary lib = PrimitiveLibrary::builtin();
  lib.load(dir.path());

  const Mesh* rect = lib.find("rect");
  ASSERT_NE(rect, nullptr);
  EXPECT_EQ(&lib.box(), rect);
  EXPECT_TRUE(rect->uvs.empty());  // the loaded one, not the built-in
  EXPECT_EQ(rect->min_corner(), glm::dvec3(0.0));
  EXPECT_EQ(rect->max_corner(), glm::dvec3(1.0));
  // Flat normals were computed, pointing outwards.
  for (const Face& f : faces_of(*rect)) {
    EXPECT_GT(glm::dot(f.normals[0], centroid(f) - glm::dvec3(0.5)), 0.0);
    EXPECT_GT(glm::dot(f.normals[0], winding_normal(f)), 1 - 1e-9);
  }

  const Mesh* balcony = lib.find("balcony");
  ASSERT_NE(balcony, nullptr);
  EXPECT_EQ(balcony->face_sizes.size(), 2u);  // both objects, merged
  EXPECT_EQ(lib.find("notes"), nullptr);
  EXPECT_NE(lib.find("window"), nullptr);  // other built-ins stay
}

TEST(PrimitiveLibrary, LoadedFileGivesOnePrimitivePerObjectName) {
  TempDir dir;
  const fs::path file = dir.write("style.prims.obj",
                                  "# up z\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                  "f 1 3 2\n"  // before any `o`: named by the file's stem
                                  "o arch\nf 1 2 4\n"
                                  "o pillar\nf 1 4 3\n"
                                  "o arch\nf 2 3 4\n");
  PrimitiveLibrary lib;
  lib.load(file);
  EXPECT_EQ(lib.names(), (std::vector<std::string>{"arch", "pillar", "style.prims"}));
  EXPECT_EQ(lib.find("arch")->face_sizes.size(), 2u);
  // A flat mesh stays flat at 0 on its flat axis; its normal keeps facing along it.
  const Mesh& flat = *lib.find("style.prims");
  EXPECT_EQ(flat.max_corner(), glm::dvec3(1, 1, 0));
  ASSERT_EQ(flat.normals.size(), 1u);
  EXPECT_EQ(flat.normals[0], glm::dvec3(0, 0, -1));
}

TEST(PrimitiveLibrary, NormalisationKeepsGivenNormalsPerpendicular) {
  // A ramp rising 1 over 2 along y; after fitting the unit box it rises 1 over 1.
  Mesh ramp;
  ramp.positions = {{0, 0, 0}, {1, 0, 0}, {1, 2, 1}, {0, 2, 1}};
  ramp.normals = {glm::normalize(glm::dvec3(0, -1, 2))};
  ramp.corners = {{0, 0, Mesh::kNone}, {1, 0, Mesh::kNone}, {2, 0, Mesh::kNone}, {3, 0, Mesh::kNone}};
  ramp.face_sizes = {4};
  const Mesh fitted = normalised_primitive(ramp);
  EXPECT_EQ(fitted.positions[2], glm::dvec3(1, 1, 1));
  const glm::dvec3 expected = glm::normalize(glm::dvec3(0, -1, 1));
  EXPECT_NEAR(glm::distance(fitted.normals[0], expected), 0.0, 1e-12);
}

TEST(PrimitiveLibrary, LoadErrorsSayWhatAndWhere) {
  TempDir dir;
  PrimitiveLibrary lib;
  try {
    lib.load(dir.path() / "missing");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Io);
  }
  try {
    lib.load(dir.path());  // no .obj in it
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Input);
    EXPECT_NE(std::string(e.what()).find("no .obj"), std::string::npos) << e.what();
  }
  dir.write("broken.obj", "v 0 0 0\nf 1 2 3\n");
  try {
    lib.load(dir.path());
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Input);
    EXPECT_NE(std::string(e.what()).find("broken.obj:2:"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(lib.names().empty());
  EXPECT_EQ(lib.box().face_sizes.size(), 6u);  // an empty library still has a box
}

}  // namespace
}  // namespace vern
