// Reading labelled OBJ: objects, corner forms, re-indexing, and the errors
// a user sees for broken files.
#include "io/obj_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>

#include "base/error.hpp"

namespace vern {
namespace {

bool same_objects(const std::vector<ObjObject>& a, const std::vector<ObjObject>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Mesh &m = a[i].mesh, &n = b[i].mesh;
    if (a[i].name != b[i].name || a[i].line != b[i].line || m.positions != n.positions || m.normals != n.normals ||
        m.uvs != n.uvs || m.corners != n.corners || m.face_sizes != n.face_sizes)
      return false;
  }
  return true;
}

// Coordinates as written: most tests here are about statements, not about
// which way is up (UpAxisIsDeclaredOrAssumed below).
ObjLimits as_written() {
  ObjLimits limits;
  limits.undeclared_up = UpAxis::Z;
  return limits;
}

// Read with the lines read ahead on a second thread.
std::vector<ObjObject> parse_ahead(const std::string& text, const ObjLimits& limits = as_written()) {
  std::istringstream in(text);
  std::vector<ObjObject> objects;
  read_obj(in, "test.obj", limits, [&](const ObjObject& o) { objects.push_back(o); }, true);
  return objects;
}

// Read both ways, which must agree.
std::vector<ObjObject> parse(const std::string& text, const ObjLimits& limits = as_written()) {
  std::istringstream in(text);
  std::vector<ObjObject> objects = read_obj(in, "test.obj", limits);
  EXPECT_TRUE(same_objects(objects, parse_ahead(text, limits)));
  return objects;
}

// The message of the error that reading text throws (empty, and a test
// failure, when it reads fine); reading ahead gives the same.
std::string error_of(const std::string& text) {
  std::string ahead;
  try {
    parse_ahead(text);
  } catch (const Error& e) {
    ahead = e.what();
  }
  try {
    std::istringstream in(text);
    read_obj(in, "test.obj");
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Input) << e.what();
    EXPECT_EQ(ahead, e.what());
    return e.what();
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return {};
}

TEST(ObjReader, ObjectsOwnTheirVerticesReindexed) {
  const auto objects = parse(
      "# two labelled parts sharing the global vertex list\n"
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 5 5 5\n"
      "vt 0 0\nvt 1 0\nvt 1 1\n"
      "vn 0 0 1\n"
      "o wall\n"
      "f 1/1/1 2/2/1 3/3/1\n"
      "o window.001\n"
      "f 5//1 3//1 4//1\n");
  ASSERT_EQ(objects.size(), 2u);
  EXPECT_EQ(objects[0].name, "wall");
  EXPECT_EQ(objects[0].line, 11u);
  EXPECT_EQ(objects[1].name, "window.001");  // Blender's suffix is kept
  EXPECT_EQ(objects[1].line, 13u);

  const Mesh& wall = objects[0].mesh;
  EXPECT_EQ(wall.positions.size(), 3u);
  EXPECT_EQ(wall.uvs.size(), 3u);
  EXPECT_EQ(wall.normals.size(), 1u);
  ASSERT_EQ(wall.face_sizes, std::vector<std::uint32_t>{3});
  EXPECT_EQ(wall.corners[2], (Mesh::Corner{2, 0, 2}));
  EXPECT_EQ(wall.uvs[2], glm::dvec2(1, 1));

  // Only the vertices it uses, numbered in order of first use.
  const Mesh& window = objects[1].mesh;
  ASSERT_EQ(window.positions.size(), 3u);
  EXPECT_EQ(window.positions[0], glm::dvec3(5, 5, 5));
  EXPECT_EQ(window.positions[1], glm::dvec3(1, 1, 0));
  EXPECT_EQ(window.positions[2], glm::dvec3(0, 1, 0));
  EXPECT_TRUE(window.uvs.empty());
  EXPECT_EQ(window.corners[0], (Mesh::Corner{0, 0, Mesh::kNone}));
  EXPECT_EQ(window.min_corner(), glm::dvec3(0, 1, 0));
  EXPECT_EQ(window.max_corner(), glm::dvec3(5, 5, 5));
}

TEST(ObjReader, NegativeIndicesCountBackFromTheLatest) {
  const auto objects = parse(
      "o quad\n"
      "v 0 0 0\nv 2 0 0\nv 2 3 0\nv 0 3 0\n"
      "vt 0 0\nvt 1 1\n"
      "f -4/-2 -3/-1 -2/-1 -1/-2\n");
  ASSERT_EQ(objects.size(), 1u);
  const Mesh& m = objects[0].mesh;
  ASSERT_EQ(m.face_sizes, std::vector<std::uint32_t>{4});
  EXPECT_EQ(m.positions[1], glm::dvec3(2, 0, 0));
  EXPECT_EQ(m.positions[3], glm::dvec3(0, 3, 0));
  EXPECT_EQ(m.corners[0].uv, 0u);
  EXPECT_EQ(m.corners[1].uv, 1u);
  EXPECT_EQ(m.uvs[1], glm::dvec2(1, 1));
}

TEST(ObjReader, GroupsNameObjectsOnlyInFilesWithoutO) {
  const std::string geometry = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const auto grouped = parse(geometry + "g roof\nf 1 2 3\ng wall\nf 3 2 1\n");
  ASSERT_EQ(grouped.size(), 2u);
  EXPECT_EQ(grouped[0].name, "roof");
  EXPECT_EQ(grouped[1].name, "wall");

  // With `o` present, groups (materials, smoothing sets) are ignored.
  const auto objects = parse(geometry + "o house\ng roof\nf 1 2 3\ng wall\nf 3 2 1\n");
  ASSERT_EQ(objects.size(), 1u);
  EXPECT_EQ(objects[0].name, "house");
  EXPECT_EQ(objects[0].mesh.face_sizes.size(), 2u);
}

// Objects say which group they start in: how many `g` statements came
// before their `o` (generate writes a group per building; an object
// before any group is in none, 0). Without `o`, each group is its own.
TEST(ObjReader, ObjectsCarryTheGroupTheyStartIn) {
  const std::string geometry = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const auto objects = parse(geometry + "o door\nf 1 2 3\ng variant_000\no wall\nf 1 2 3\nusemtl red\no roof\nf 1 2 3\n"
                                        "g variant_001\no wall\nf 1 2 3\n");
  ASSERT_EQ(objects.size(), 4u);
  EXPECT_EQ(objects[0].group, 0u);
  EXPECT_EQ(objects[1].group, 1u);
  EXPECT_EQ(objects[2].group, 1u);
  EXPECT_EQ(objects[3].group, 2u);
  const auto grouped = parse(geometry + "g roof\nf 1 2 3\ng wall\nf 3 2 1\n");
  ASSERT_EQ(grouped.size(), 2u);
  EXPECT_EQ(grouped[0].group, 1u);
  EXPECT_EQ(grouped[1].group, 2u);
}

TEST(ObjReader, FacesBeforeAnyNameFormAnUnnamedObject) {
  const auto objects = parse("v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 3\no door\nf 1 3 2\n");
  ASSERT_EQ(objects.size(), 2u);
  EXPECT_EQ(objects[0].name, "");
  EXPECT_EQ(objects[0].line, 5u);  // its first face
  EXPECT_EQ(objects[1].name, "door");
}

TEST(ObjReader, RepeatedNamesStaySeparateAndEmptyObjectsAreDropped) {
  const auto objects =
      parse("v 0 0 0\nv 1 0 0\nv 0 1 0\no window\nf 1 2 3\no empty\no window\nf 1 2 3\n");
  ASSERT_EQ(objects.size(), 2u);
  EXPECT_EQ(objects[0].name, "window");
  EXPECT_EQ(objects[1].name, "window");
  EXPECT_EQ(objects[1].line, 7u);
}

TEST(ObjReader, IgnoresMaterialsSmoothingLinesCommentsAndLineEndings) {
  const auto objects = parse(
      "\xEF\xBB\xBF# exported\r\n"
      "mtllib house.mtl\r\n"
      "o  big wall  # trailing comment\r\n"
      "v 0 0 0\r\nv +1 0 0 1.0\r\nv 0 1e0 0 0.5 0.5 0.5\r\n"
      "usemtl plaster\r\n"
      "s off\r\n"
      "l 1 2\r\n"
      "p 1\r\n"
      "f 1 \\\r\n 2 3\r\n");
  ASSERT_EQ(objects.size(), 1u);
  EXPECT_EQ(objects[0].name, "big wall");
  ASSERT_EQ(objects[0].mesh.face_sizes, std::vector<std::uint32_t>{3});
  EXPECT_EQ(objects[0].mesh.positions[1], glm::dvec3(1, 0, 0));
  EXPECT_EQ(objects[0].mesh.positions[2], glm::dvec3(0, 1, 0));
}

// Blender writes OBJ y-up (forward -Z, up Y) and says nothing about it;
// Vernacular's files say which with `# up`. Either way objects come out
// z-up, the grammar's frame: (x, y, z) of a y-up file is (x, -z, y).
TEST(ObjReader, UpAxisIsDeclaredOrAssumed) {
  const std::string body = "o wall\nv 1 2 3\nv 4 5 6\nv 7 8 9\nvn 0 1 0\nf 1//1 2//1 3//1\n";
  const ObjLimits y_up;  // the default, as Blender exports
  std::vector<ObjObject> objects = parse(body, y_up);
  ASSERT_EQ(objects.size(), 1u);
  EXPECT_EQ(objects[0].mesh.positions[0], glm::dvec3(1, -3, 2));
  EXPECT_EQ(objects[0].mesh.normals[0], glm::dvec3(0, 0, 1));  // the file's up is up
  // 0 stays 0, not -0 (which a grammar would print as "-0").
  EXPECT_FALSE(std::signbit(parse("o a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", y_up)[0].mesh.positions[0].y));

  EXPECT_EQ(parse("# up z\n" + body, y_up)[0].mesh.positions[0], glm::dvec3(1, 2, 3));
  EXPECT_EQ(parse("# exported\n#   up   Y  \n" + body, as_written())[0].mesh.positions[0], glm::dvec3(1, -3, 2));
  // Files an earlier Vernacular wrote, before it declared the axis, are z-up;
  // a declaration after that first line still counts.
  const std::string old_header = "# Written by Vernacular: one object per terminal, named by its label.\n";
  EXPECT_EQ(parse(old_header + body, y_up)[0].mesh.positions[0], glm::dvec3(1, 2, 3));
  EXPECT_EQ(parse(old_header + "# up y\n" + body, as_written())[0].mesh.positions[0], glm::dvec3(1, -3, 2));
  EXPECT_EQ(parse("# Vernacular built-in primitive 'x'\n" + body, y_up)[0].mesh.positions[0], glm::dvec3(1, 2, 3));
  // Other comments that start with "up" are only comments.
  EXPECT_EQ(parse("# up to date\n" + body, y_up)[0].mesh.positions[0], glm::dvec3(1, -3, 2));

  std::string e = error_of("# up x\n" + body);
  EXPECT_NE(e.find("test.obj:1:6: error: '# up x' declares an up axis other than y or z"), std::string::npos) << e;
  e = error_of("o wall\nv 1 2 3\n# up z\nv 4 5 6\nv 7 8 9\nf 1 2 3\n");
  EXPECT_NE(e.find("test.obj:3:1: error: the up axis is declared after vertices"), std::string::npos) << e;
  EXPECT_NE(e.find("move the `# up z` line to the top"), std::string::npos) << e;
}

TEST(ObjReader, ErrorsNameFileLineAndColumn) {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  std::string e = error_of(tri + "o a\nf 1 2 4\n");
  EXPECT_NE(e.find("test.obj:5:7: error:"), std::string::npos) << e;
  EXPECT_NE(e.find("vertex 4, but 3 vertices are defined"), std::string::npos) << e;
  EXPECT_NE(e.find("hint:"), std::string::npos) << e;

  e = error_of(tri + "f 1 0 2\n");
  EXPECT_NE(e.find("test.obj:4:5:"), std::string::npos) << e;
  EXPECT_NE(e.find("index of 0"), std::string::npos) << e;

  e = error_of(tri + "f -1 -2 -4\n");
  EXPECT_NE(e.find("test.obj:4:"), std::string::npos) << e;

  e = error_of(tri + "vn 0 0 1\nf 1//2 2//1 3//1\n");
  EXPECT_NE(e.find("normal 2"), std::string::npos) << e;

  e = error_of("v 0 zero 0\n");
  EXPECT_NE(e.find("test.obj:1:5:"), std::string::npos) << e;
  EXPECT_NE(e.find("'zero'"), std::string::npos) << e;

  e = error_of("v 0 1.5x 0\n");
  EXPECT_NE(e.find("'1.5x'"), std::string::npos) << e;

  e = error_of(tri + "v nan 0 0\n");
  EXPECT_NE(e.find("test.obj:4:3:"), std::string::npos) << e;
  EXPECT_NE(e.find("not a finite number"), std::string::npos) << e;

  e = error_of("vt inf\n");
  EXPECT_NE(e.find("not a finite number"), std::string::npos) << e;

  e = error_of("v 1 2\n");
  EXPECT_NE(e.find("needs 3 numbers"), std::string::npos) << e;

  e = error_of(tri + "f 1 2\n");
  EXPECT_NE(e.find("test.obj:4:1:"), std::string::npos) << e;
  EXPECT_NE(e.find("at least 3 corners"), std::string::npos) << e;

  e = error_of(tri + "f 1/x 2 3\n");
  EXPECT_NE(e.find("'x'"), std::string::npos) << e;
}

TEST(ObjReader, RejectsWhatIsNotObjText) {
  std::string glb("glTF\x02\0\0\0", 8);
  std::string e = error_of(glb + "\nmore");
  EXPECT_NE(e.find("test.obj:1:"), std::string::npos) << e;
  EXPECT_NE(e.find("NUL"), std::string::npos) << e;

  // Said without quoting the line: a file that is not OBJ may hold anything.
  e = error_of("# a comment first is fine\nsolid cube\n  facet normal 0 0 1\n");
  EXPECT_NE(e.find("test.obj:2:1:"), std::string::npos) << e;
  EXPECT_NE(e.find("this line is not an OBJ statement, nor is any line before it"), std::string::npos) << e;
  EXPECT_EQ(e.find("solid"), std::string::npos) << e;

  // Once the file has shown itself to be OBJ, unknown extensions pass.
  EXPECT_EQ(parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nvendor_thing 1 2\no a\nf 1 2 3\n").size(), 1u);
}

TEST(ObjReader, MissingFileAndFolderAreIoErrors) {
  const auto dir = std::filesystem::temp_directory_path();
  try {
    read_obj_file(dir / "vern-no-such-file.obj");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Io);
    EXPECT_NE(std::string(e.what()).find("vern-no-such-file.obj"), std::string::npos);
  }
  try {
    read_obj_file(dir);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Io);
    EXPECT_NE(std::string(e.what()).find("folder"), std::string::npos);
  }
}

TEST(ObjReader, ReadsManyObjectsLinearly) {
  // 20000 one-triangle objects: re-indexing must stay linear, not quadratic.
  std::string text;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    text += "o part" + std::to_string(i) + "\nv " + std::to_string(i) + " 0 0\nv 0 1 0\nv 0 0 1\nf -3 -2 -1\n";
  }
  const auto objects = parse(text);
  ASSERT_EQ(objects.size(), static_cast<std::size_t>(n));
  EXPECT_EQ(objects.back().name, "part19999");
  EXPECT_EQ(objects.back().mesh.positions.size(), 3u);
  EXPECT_EQ(objects.back().mesh.positions[0], glm::dvec3(n - 1, 0, 0));
}

// Large texts span many read-ahead batches (a quarter megabyte each): the
// objects, the line numbers in them and in errors, and a `\` continued
// statement across a batch's edge come out as when read on one thread.
std::string many_boxes(std::size_t boxes) {
  std::string text;
  for (std::size_t b = 0; b < boxes; ++b) {
    const std::size_t first = 8 * b + 1;
    text += "o part." + std::to_string(b) + "\n";
    for (int c = 0; c < 8; ++c)
      text += "v " + std::to_string(b) + "." + std::to_string(c & 1) + " " + std::to_string((c >> 1) & 1) + " -" +
              std::to_string(c >> 2) + ".25\n";
    for (int f = 0; f < 6; ++f)
      text += "f " + std::to_string(first + f % 8) + " " + std::to_string(first + (f + 1) % 8) + " " +
              std::to_string(first + (f + 2) % 8) + "\n";
    if (b % 5000 == 17) text += "v 1 2 \\\n3\r\n# a comment\n\nvn 0 0 1\nf 1//1 2//1 3//1\n";
  }
  return text;
}

TEST(ObjReader, ReadAheadAgreesOnLargeTexts) {
  const std::string text = many_boxes(40000);
  ASSERT_GT(text.size(), std::size_t{5} << 20);
  std::istringstream in(text);
  const std::vector<ObjObject> objects = read_obj(in, "test.obj");  // y-up, turned by both
  ASSERT_EQ(objects.size(), 40000u);
  EXPECT_TRUE(same_objects(objects, parse_ahead(text, {})));
  // An error far into the file, and a limit, name the same lines.
  const std::size_t middle = text.find('\n', text.size() / 2) + 1;
  for (const std::string& bad : {text + "f 1 2 999999999\n", text.substr(0, middle) + "v 1 x 2\n" + text}) {
    EXPECT_NE(error_of(bad).find("test.obj:"), std::string::npos);
  }
  ObjLimits few_objects, few_faces;
  few_objects.max_objects = 30000;
  few_faces.max_faces = 5;
  for (const ObjLimits& limits : {few_objects, few_faces}) {
    std::string limited, ahead;
    try {
      std::istringstream again(text);
      read_obj(again, "test.obj", limits);
    } catch (const Error& e) {
      limited = e.what();
    }
    try {
      parse_ahead(text, limits);
    } catch (const Error& e) {
      ahead = e.what();
    }
    EXPECT_NE(limited.find(limits.max_faces ? "has more than 5 faces" : "more than 30000 objects"), std::string::npos)
        << limited;
    EXPECT_EQ(limited, ahead);
  }
}

}  // namespace
}  // namespace vern
