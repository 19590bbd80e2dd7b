// Loading labelled examples: OBJ and glTF parts, Blender suffixes, folders,
// and the errors a user sees for files inference cannot use.
#include "inverse/load/example.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "base/error.hpp"
#include "graph/parser.hpp"
#include "io/gltf_container.hpp"
#include "io/gltf_writer.hpp"
#include "io/obj_writer.hpp"
#include "support/example_helpers.hpp"
#include "support/run_command.hpp"

namespace vern {
namespace {

using test::TempFolder;
using test::write_text;

// An axis-aligned box as an OBJ object (relative indices: position free).
std::string box_obj(const std::string& name, glm::dvec3 a, glm::dvec3 b) {
  std::string text = "o " + name + "\n";
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 p((i & 1) ? b.x : a.x, (i & 2) ? b.y : a.y, (i & 4) ? b.z : a.z);
    text += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
  }
  // Corners -8..-1 are vertices 0..7 above.
  text += "f -8 -6 -5 -7\nf -4 -3 -1 -2\nf -8 -7 -3 -4\nf -6 -2 -1 -5\nf -8 -4 -2 -6\nf -7 -5 -1 -3\n";
  return text;
}

// The message of the error that loading throws, checking its kind.
std::string load_error(const std::filesystem::path& path, ErrorKind kind = ErrorKind::Input) {
  try {
    load_example(path);
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), kind) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no error loading " << path;
  return {};
}

std::string files_error(const std::vector<std::string>& args, ErrorKind kind) {
  try {
    example_files(args);
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), kind) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return {};
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The OBJ texts below are written z-up, as grammars are; files that do not
// say so are read y-up, as Blender writes them (ObjFilesWithoutADeclaration...).
ExampleLimits z_up() {
  ExampleLimits limits;
  limits.obj_up = UpAxis::Z;
  return limits;
}

TEST(Example, ObjObjectsArePartsWithBoxesLabelsAndLines) {
  TempFolder dir;
  write_text(dir / "house.obj", "# a wall with two windows\n" + box_obj("wall", {0, 0, 0}, {6, 0.5, 3}) +
                                    box_obj("window.001", {1, -0.25, 1}, {2, 0, 2}) +
                                    box_obj("window.002", {4, -0.25, 1}, {5, 0, 2}));
  const Example ex = load_example(dir / "house.obj", z_up());
  EXPECT_EQ(ex.source, (dir / "house.obj").string());
  ASSERT_EQ(ex.boxes.size(), 3u);
  // The whole mesh of each label's first part; every part's positions.
  ASSERT_EQ(ex.meshes.size(), 2u);
  ASSERT_EQ(ex.positions.size(), 3u);
  EXPECT_EQ(ex.boxes[0].label, "wall");
  EXPECT_EQ(ex.boxes[1].label, "window");
  EXPECT_EQ(ex.boxes[2].label, "window");
  EXPECT_EQ(ex.boxes[1].object, "window.001");
  EXPECT_EQ(ex.boxes[0].line, 2u);
  EXPECT_EQ(ex.boxes[1].line, 17u);
  EXPECT_EQ(ex.boxes[1].mesh, 1u);
  EXPECT_EQ(ex.boxes[2].mesh, Mesh::kNone);
  EXPECT_EQ(ex.boxes[1].min, glm::dvec3(1, -0.25, 1));
  EXPECT_EQ(ex.boxes[1].max, glm::dvec3(2, 0, 2));
  // Meshes and positions stay in world space.
  EXPECT_EQ(ex.meshes[1].min_corner(), glm::dvec3(1, -0.25, 1));
  EXPECT_EQ(ex.meshes[0].face_sizes.size(), 6u);
  std::vector<glm::dvec3> positions;
  ex.positions.get(2, ex.boxes[2].min, ex.boxes[2].max, positions);
  EXPECT_EQ(positions.size(), 8u);
  EXPECT_EQ(*std::min_element(positions.begin(), positions.end(), [](auto& a, auto& b) { return a.x < b.x; }),
            glm::dvec3(4, -0.25, 1));
  EXPECT_EQ(ex.min, glm::dvec3(0, -0.25, 0));
  EXPECT_EQ(ex.max, glm::dvec3(6, 0.5, 3));
  EXPECT_EQ(example_size(ex), glm::dvec3(6, 0.75, 3));
  EXPECT_DOUBLE_EQ(default_tolerance(ex), 6e-6);
  EXPECT_EQ(describe_object(ex.boxes[1]), "'window.001' (line 17)");
}

// Boxes joined into one object (Blender's Array modifier, Ctrl+J): the
// first with its `o` line, the others' faces in the same object.
std::string joined_boxes(const std::string& name, const std::vector<std::pair<glm::dvec3, glm::dvec3>>& boxes) {
  std::string text;
  for (const auto& [a, b] : boxes) {
    const std::string box = box_obj(name, a, b);
    text += text.empty() ? box : box.substr(box.find('\n') + 1);
  }
  return text;
}

TEST(Example, AnObjectOfLooseBoxesIsOnePartPerBox) {
  TempFolder dir;
  write_text(dir / "house.obj", box_obj("wall", {0, 0, 0}, {9, 0.5, 3}) +
                                    joined_boxes("window", {{{1, -0.25, 1}, {2, 0, 2}},
                                                            {{4, -0.25, 1}, {5, 0, 2}},
                                                            {{7, -0.25, 1}, {8, 0, 2}}}));
  const Example ex = load_example(dir / "house.obj", z_up());
  ASSERT_EQ(ex.boxes.size(), 4u);
  for (std::size_t i = 1; i < 4; ++i) {
    EXPECT_EQ(ex.boxes[i].label, "window");
    EXPECT_EQ(ex.boxes[i].line, 16u);
    EXPECT_EQ(ex.boxes[i].min, glm::dvec3(1 + 3.0 * static_cast<double>(i - 1), -0.25, 1));
    EXPECT_EQ(ex.boxes[i].max, glm::dvec3(2 + 3.0 * static_cast<double>(i - 1), 0, 2));
  }
  EXPECT_EQ(ex.boxes[2].object, "window (loose part 2 of 3)");
  // The primitive is one window, not three.
  ASSERT_EQ(ex.meshes.size(), 2u);
  EXPECT_EQ(ex.meshes[1].positions.size(), 8u);
  EXPECT_EQ(ex.meshes[1].face_sizes.size(), 6u);
  EXPECT_EQ(ex.meshes[1].max_corner(), glm::dvec3(2, 0, 2));
  ASSERT_EQ(ex.positions.size(), 4u);
  // Three windows in one object infer as three windows in three objects.
  write_text(dir / "apart.obj", box_obj("wall", {0, 0, 0}, {9, 0.5, 3}) + box_obj("window", {1, -0.25, 1}, {2, 0, 2}) +
                                    box_obj("window", {4, -0.25, 1}, {5, 0, 2}) +
                                    box_obj("window", {7, -0.25, 1}, {8, 0, 2}));
  const Example apart = load_example(dir / "apart.obj", z_up());
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(ex.boxes[i].min, apart.boxes[i].min);
    EXPECT_EQ(ex.boxes[i].max, apart.boxes[i].max);
  }
}

TEST(Example, LoosePiecesWhoseBoxesMeetStayOnePart) {
  TempFolder dir;
  // A frame with a pane inside it, and two boxes sharing a face (an Array
  // modifier's copies touching): neither can be cut apart into boxes.
  write_text(dir / "window.obj",
             joined_boxes("window", {{{0, 0, 0}, {1, 0.2, 1}}, {{0.2, 0.05, 0.2}, {0.8, 0.15, 0.8}}}) +
                 joined_boxes("shelf", {{{3, 0, 0}, {4, 1, 1}}, {{4, 0, 0}, {5, 1, 1}}}));
  const Example ex = load_example(dir / "window.obj", z_up());
  ASSERT_EQ(ex.boxes.size(), 2u);
  EXPECT_EQ(ex.boxes[0].object, "window");
  EXPECT_EQ(ex.boxes[0].loose_pieces, 2u);
  EXPECT_EQ(ex.boxes[0].max, glm::dvec3(1, 0.2, 1));
  // Touching boxes share their corner positions: one piece.
  EXPECT_EQ(ex.boxes[1].loose_pieces, 1u);
  EXPECT_EQ(ex.boxes[1].max, glm::dvec3(5, 1, 1));
}

TEST(Example, FlatPartsAreAllowed) {
  TempFolder dir;
  // A 2-D facade as in the thesis's example files: every part at y = 0.
  write_text(dir / "facade.obj",
             "o rect\nv 0 0 0\nv 3.33333 0 0\nv 3.33333 0 6.66667\nv 0 0 6.66667\nf 1 2 3 4\n"
             "o triangle.001\nv 0 0 6.66667\nv 3.33333 0 6.66667\nv 1.6 0 10\nf 5 6 7\n");
  const Example ex = load_example(dir / "facade.obj", z_up());
  ASSERT_EQ(ex.boxes.size(), 2u);
  EXPECT_EQ(ex.boxes[1].label, "triangle");
  EXPECT_EQ(example_size(ex).y, 0.0);
}

// A house 6 wide, 4 deep and 3 high as Blender exports it by default,
// OBJ and glTF alike (y up, -z forward): read with its height on z.
TEST(Example, ObjFilesWithoutADeclarationAndGltfAreYUp) {
  TempFolder dir;
  write_text(dir / "blender.obj", "# Blender 3.4.1\n" + box_obj("wall", {0, 0, -4}, {6, 3, 0}));
  Example ex = load_example(dir / "blender.obj");
  EXPECT_EQ(ex.min, glm::dvec3(0, 0, 0));
  EXPECT_EQ(ex.max, glm::dvec3(6, 4, 3));
  // --up z reads it as written; a file's own `# up` line wins over either.
  EXPECT_EQ(example_size(load_example(dir / "blender.obj", z_up())), glm::dvec3(6, 3, 4));
  write_text(dir / "declared.obj", "# up y\n" + box_obj("wall", {0, 0, -4}, {6, 3, 0}));
  EXPECT_EQ(example_size(load_example(dir / "declared.obj", z_up())), glm::dvec3(6, 4, 3));

  // What the writers produce, with the grammar's z up, reads back z-up.
  Scene scene;
  scene.labels = {"wall"};
  Terminal t;
  t.label = 0;
  t.scope.size = glm::dvec3(6, 4, 3);
  scene.variants.push_back({"house", glm::dvec3(0.0), {t}});
  const PrimitiveLibrary library = PrimitiveLibrary::builtin();
  write_gltf(scene, library, dir / "house.glb");
  write_obj(scene, library, dir / "house.obj");
  write_obj(scene, library, dir / "house_z.obj", UpAxis::Z);
  for (const char* name : {"house.glb", "house.obj", "house_z.obj"}) {
    SCOPED_TRACE(name);
    ex = load_example(dir / name);
    EXPECT_EQ(ex.min, glm::dvec3(0, 0, 0));
    EXPECT_EQ(ex.max, glm::dvec3(6, 4, 3));
  }
  EXPECT_TRUE(contains(test::read_file(dir / "house.obj"), "\nv 6 3 -4\n"));  // y-up in the file
}

TEST(Example, EmptyFilesAndFilesWithoutObjectsAreErrors) {
  TempFolder dir;
  write_text(dir / "empty.obj", "");
  std::string e = load_error(dir / "empty.obj");
  EXPECT_TRUE(contains(e, "empty.obj: error: has no labelled objects; each part must be an OBJ object `o name`")) << e;

  write_text(dir / "comments.obj", "# nothing here\nmtllib x.mtl\nv 0 0 0\n");
  e = load_error(dir / "comments.obj");
  EXPECT_TRUE(contains(e, "has no labelled objects")) << e;
}

TEST(Example, UnnamedGeometryIsAnErrorAtItsLine) {
  TempFolder dir;
  write_text(dir / "unnamed.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\n\nf 1 2 3\n" + box_obj("wall", {0, 0, 0}, {1, 1, 1}));
  const std::string e = load_error(dir / "unnamed.obj");
  EXPECT_TRUE(contains(e, "unnamed.obj:5:1: error: these faces have no name")) << e;
  EXPECT_TRUE(contains(e, "hint: start each part with `o <label>`")) << e;
}

TEST(Example, APartThatIsASinglePointIsAnError) {
  TempFolder dir;
  write_text(dir / "point.obj", box_obj("wall", {0, 0, 0}, {4, 1, 3}) + "o speck.001\nv 2 2 2\nf -1 -1 -1\n");
  const std::string e = load_error(dir / "point.obj");
  EXPECT_TRUE(contains(e, "point.obj:16:1: error: object 'speck.001' (line 16) is a single point")) << e;
}

TEST(Example, BinaryFilesAreNotObj) {
  TempFolder dir;
  write_text(dir / "model.obj", std::string("\x7f" "ELF\x02\x01\x01\x00\x00\x00", 10) + "\x03\x00\x3e");
  std::string e = load_error(dir / "model.obj");
  EXPECT_TRUE(contains(e, "not an OBJ")) << e;

  write_text(dir / "noise.obj", "\x89PNG\r\n\x1a\n garbage");
  e = load_error(dir / "noise.obj");
  EXPECT_TRUE(contains(e, "does not look like an OBJ file")) << e;
}

TEST(Example, MissingFilesFoldersAndOtherExtensions) {
  TempFolder dir;
  EXPECT_TRUE(contains(load_error(dir / "nope.obj", ErrorKind::Io), "no such file"));
  EXPECT_TRUE(contains(load_error(dir.path(), ErrorKind::Io), "is a folder"));
  write_text(dir / "house.stl", "solid x\n");
  EXPECT_TRUE(contains(load_error(dir / "house.stl", ErrorKind::Usage), "examples are labelled .obj, .glb or .gltf"));
}

TEST(Example, FolderArgumentsExpandToTheirExampleFilesSorted) {
  TempFolder dir;
  std::filesystem::create_directories(dir / "set/sub");
  for (const char* name : {"set/b.obj", "set/a.GLB", "set/c.gltf", "set/notes.txt", "set/sub/d.obj", "z.obj", "y.obj"})
    write_text(dir / name, "");
  const std::vector<std::filesystem::path> files =
      example_files({(dir / "z.obj").string(), (dir / "set").string(), (dir / "y.obj").string()});
  EXPECT_EQ(files, (std::vector<std::filesystem::path>{dir / "z.obj", dir / "set/a.GLB", dir / "set/b.obj",
                                                       dir / "set/c.gltf", dir / "y.obj"}));

  std::string e = files_error({(dir / "missing").string()}, ErrorKind::Io);
  EXPECT_TRUE(contains(e, "missing: error: no such file or folder")) << e;
  e = files_error({(dir / "set/sub/..").string(), (dir / "set/sub").string(), (dir / "set/notes.txt").string()},
                  ErrorKind::Usage);
  EXPECT_TRUE(contains(e, "notes.txt: error: is not an example file")) << e;
  std::filesystem::create_directories(dir / "empty");
  e = files_error({(dir / "empty").string()}, ErrorKind::Io);
  EXPECT_TRUE(contains(e, "holds no example files")) << e;
}

// What the writers produce reads back as the same parts.
TEST(Example, GltfAndObjWrittenByTheWritersReadBackToTheSameBoxes) {
  const Grammar g = read_grammar_file(VERN_SOURCE_DIR "/data/grammars/better_roofs.grm");
  DeriveOptions o;
  o.seed = 4;
  const Derivation d = derive(g, o);
  ASSERT_GT(d.terminals.size(), 10u);
  Scene scene;
  scene.labels = d.labels;
  const glm::dvec3 offset(5, -2, 1);
  scene.variants.push_back({"house", offset, d.terminals});
  const auto expected = test::translated(test::derived_parts(d), offset);

  TempFolder dir;
  const PrimitiveLibrary library = PrimitiveLibrary::builtin();
  for (const std::string name : {"house.glb", "house.gltf", "house.obj"}) {
    SCOPED_TRACE(name);
    if (name.ends_with(".obj")) write_obj(scene, library, dir / name);
    else write_gltf(scene, library, dir / name);
    const Example ex = load_example(dir / name);
    EXPECT_EQ(ex.boxes.size(), d.terminals.size());
    EXPECT_EQ(ex.positions.size(), d.terminals.size());
    EXPECT_TRUE(test::same_boxes(expected, ex.boxes, 1e-6));
    if (!name.ends_with(".obj")) {
      EXPECT_EQ(ex.boxes[0].line, 0u);
      EXPECT_EQ(ex.boxes[0].object, ex.boxes[0].label);
    }
  }
}


// One triangle (0,0,0) (1,0,0) (0,1,0) under a parent turned a quarter
// about z; the child is moved and scaled: its world box is
// (-2, 1, 0) - (0, 3, 0), y-up as glTF is: (-2, 0, 1) - (0, 0, 3) z-up.
std::string triangle_gltf(const std::string& child_name) {
  const float v[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::string bytes(sizeof v, '\0');
  std::memcpy(bytes.data(), v, sizeof v);
  return R"({"asset": {"version": "2.0"},
  "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,)" + base64(bytes) + R"("}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                 "min": [0, 0, 0], "max": [1, 1, 0]}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "nodes": [{"name": "group", "rotation": [0, 0, 0.7071067811865476, 0.7071067811865476], "children": [1]},
            {)" + child_name + R"("mesh": 0, "translation": [1, 0, 0], "scale": [2, 2, 2]}],
  "scenes": [{"nodes": [0]}], "scene": 0})";
}

TEST(Example, GltfNodesApplyTheirWorldTransform) {
  TempFolder dir;
  write_text(dir / "panel.gltf", triangle_gltf(R"("name": "panel.003", )"));
  const Example ex = load_example(dir / "panel.gltf");
  ASSERT_EQ(ex.boxes.size(), 1u);
  EXPECT_EQ(ex.boxes[0].label, "panel");
  EXPECT_EQ(ex.boxes[0].object, "panel.003");
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(ex.boxes[0].min[i], glm::dvec3(-2, 0, 1)[i], 1e-6);
    EXPECT_NEAR(ex.boxes[0].max[i], glm::dvec3(0, 0, 3)[i], 1e-6);
  }
  EXPECT_EQ(ex.meshes[0].face_sizes, std::vector<std::uint32_t>{3});
}

// generate --instancing writes each mesh's copies as EXT_mesh_gpu_instancing
// instances (float translation, rotation, scale): each instance reads back
// as one part, the same boxes as the plain file's within float precision,
// labels without the colour suffix of coloured meshes' names.
TEST(Example, InstancedGltfReadsBackAsThePlainFile) {
  const Grammar roofs = read_grammar_file(VERN_SOURCE_DIR "/data/grammars/better_roofs.grm");
  // Turned, faced and coloured parts too: rotations and "rect colour_..." names.
  const Grammar painted = parse_grammar(
      "p --> split(x){ ~1 : R(z, 0.3){ I(rect) } | ~1 : comp(f){ front : colour(1, 0, 0) | top : I(window) } | "
      "~1 : R(y, pi/2){ colour(0, 0.5, 1) } }",
      "painted.grm");
  Scene scene;
  for (const Grammar* g : {&roofs, &painted}) {
    DeriveOptions o;
    o.seed = 4;
    o.size = glm::dvec3(12, 8, 6);
    Derivation d = derive(*g, o);
    ASSERT_FALSE(d.terminals.empty());
    scene.labels = d.labels;
    scene.variants = {{"house", glm::dvec3(5, -2, 1), d.terminals}, {"other", glm::dvec3(30, 0, 0), d.terminals}};

    TempFolder dir;
    const PrimitiveLibrary library = PrimitiveLibrary::builtin();
    write_gltf(scene, library, dir / "plain.glb");
    write_gltf(scene, library, dir / "instanced.glb", {.instancing = true});
    write_gltf(scene, library, dir / "instanced.gltf", {.instancing = true});
    const Example plain = load_example(dir / "plain.glb");
    for (const char* name : {"instanced.glb", "instanced.gltf"}) {
      SCOPED_TRACE(name);
      const Example instanced = load_example(dir / name);
      ASSERT_EQ(instanced.boxes.size(), 2 * d.terminals.size());
      EXPECT_TRUE(test::same_boxes(plain.boxes, instanced.boxes, 1e-5));
      for (const LabelledBox& b : instanced.boxes) {
        EXPECT_EQ(b.label.find(' '), std::string::npos) << b.label;
        EXPECT_NE(b.object.find("(instance "), std::string::npos) << b.object;
        // Each part's positions are its own instance's, placed.
        Mesh mesh;
        instanced.positions.get(static_cast<std::size_t>(&b - instanced.boxes.data()), b.min, b.max, mesh.positions);
        for (int i = 0; i < 3; ++i) {
          EXPECT_NEAR(mesh.min_corner()[i], b.min[i], 1e-12);
          EXPECT_NEAR(mesh.max_corner()[i], b.max[i], 1e-12);
        }
      }
    }
  }
}

// The round trip a user makes: buildings generated with --instancing are
// examples infer learns from and check finds derivable.
TEST(Example, InstancedFilesFromGenerateAreExamplesForInferAndCheck) {
  TempFolder dir;
  const auto generated = test::run_program(
      "generate", {VERN_SOURCE_DIR "/data/grammars/garage.grm", "-n", "3", "--instancing", "--format", "glb", "-o",
                   (dir / "garages").string(), "-q"});
  ASSERT_EQ(generated.exit_code, 0) << generated.err;
  ASSERT_EQ(test::list_folder(dir / "garages"),
            (std::vector<std::string>{"variant_000.glb", "variant_001.glb", "variant_002.glb"}));
  // The files really are instanced.
  EXPECT_TRUE(contains(test::read_file(dir / "garages" / "variant_000.glb"), "EXT_mesh_gpu_instancing"));

  const auto inferred = test::run_program("infer", {(dir / "garages").string(), "-o", (dir / "garage.grm").string()});
  ASSERT_EQ(inferred.exit_code, 0) << inferred.err;
  const auto checked = test::run_program("check", {(dir / "garage.grm").string(), (dir / "garages").string()});
  EXPECT_EQ(checked.exit_code, 0) << checked.out << checked.err;
  EXPECT_TRUE(contains(checked.out, "3 of 3 examples derivable")) << checked.out;
}

// Broken instancing data is named, not silently misread.
TEST(Example, InstancingErrors) {
  TempFolder dir;
  const float v[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::string bytes(sizeof v, '\0');
  std::memcpy(bytes.data(), v, sizeof v);
  auto file = [&](const std::string& attributes) {
    return R"({"asset": {"version": "2.0"},
  "extensionsUsed": ["EXT_mesh_gpu_instancing"],
  "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,)" + base64(bytes) + R"("}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                {"bufferView": 0, "componentType": 5126, "count": 2, "type": "VEC3"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "nodes": [{"name": "panel", "mesh": 0, "extensions": {"EXT_mesh_gpu_instancing": {"attributes": )" +
           attributes + R"(}}}],
  "scenes": [{"nodes": [0]}], "scene": 0})";
  };
  // Three instances translated by the triangle's own corners.
  write_text(dir / "three.gltf", file(R"({"TRANSLATION": 0})"));
  const Example ex = load_example(dir / "three.gltf");
  ASSERT_EQ(ex.boxes.size(), 3u);
  EXPECT_EQ(ex.boxes[1].label, "panel");
  EXPECT_EQ(ex.boxes[1].min, glm::dvec3(1, 0, 0));  // y-up (1, 0, 0) - (2, 1, 0), turned z-up
  EXPECT_EQ(ex.boxes[1].max, glm::dvec3(2, 0, 1));

  write_text(dir / "uneven.gltf", file(R"({"TRANSLATION": 0, "SCALE": 1})"));
  EXPECT_TRUE(contains(load_error(dir / "uneven.gltf"), "attributes hold different numbers of instances"));
  write_text(dir / "none.gltf", file(R"({"COLOUR": 0})"));
  const std::string none = load_error(dir / "none.gltf");
  EXPECT_TRUE(contains(none, "node 0 'panel': its EXT_mesh_gpu_instancing extension names none of TRANSLATION")) << none;
  write_text(dir / "rotation.gltf", file(R"({"ROTATION": 0})"));
  EXPECT_TRUE(contains(load_error(dir / "rotation.gltf"), "ROTATION must hold 4 numbers per instance"));
}

// Two meshes in the xy plane (y-up): "pair", two triangles apart, and
// "quad", two triangles whose corners meet at equal positions (not shared
// indices). Each node of `nodes` names a mesh of `meshes`, a list of
// POSITION accessors: 0 for the pair's, 1 for the quad's; the scene's
// roots are the nodes `roots` lists.
std::string two_meshes_gltf(const std::string& meshes, const std::string& nodes,
                            const std::string& roots = "0, 1, 2, 3") {
  const float v[36] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 3, 0, 0, 4, 0, 0, 3, 1, 0,   // pair
                       0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0};  // quad
  std::string bytes(sizeof v, '\0');
  std::memcpy(bytes.data(), v, sizeof v);
  std::string mesh_list;
  for (const char accessor : meshes) {
    mesh_list += std::string(mesh_list.empty() ? "" : ", ") + R"({"primitives": [{"attributes": {"POSITION": )" +
                 accessor + "}}]}";
  }
  return R"({"asset": {"version": "2.0"},
  "buffers": [{"byteLength": 144, "uri": "data:application/octet-stream;base64,)" + base64(bytes) + R"("}],
  "bufferViews": [{"buffer": 0, "byteLength": 72}, {"buffer": 0, "byteOffset": 72, "byteLength": 72}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 6, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5126, "count": 6, "type": "VEC3"}],
  "meshes": [)" + mesh_list + R"(],
  "nodes": [)" + nodes + R"(],
  "scenes": [{"nodes": [)" + roots + R"(]}], "scene": 0})";
}

// three.js's exporter names the second node of a name "quad_1" where
// Blender writes "quad.001": the part is a quad all the same. Only in files
// three.js says it wrote: elsewhere "quad_1" is a label of its own.
// Three nodes of the quad's mesh, read from a file three.js's exporter
// wrote and from one another tool wrote.
struct ThreeJsAndOther {
  Example three, other;
};

ThreeJsAndOther three_quads_from_three_js_and_other(const std::string& nodes) {
  TempFolder dir;
  std::string three = two_meshes_gltf("1", nodes, "0, 1, 2");
  three.replace(three.find(R"("version": "2.0")"), 16, R"("version": "2.0", "generator": "THREE.GLTFExporter r160")");
  write_text(dir / "three.gltf", three);
  write_text(dir / "other.gltf", two_meshes_gltf("1", nodes, "0, 1, 2"));
  ThreeJsAndOther out{load_example(dir / "three.gltf"), load_example(dir / "other.gltf")};
  EXPECT_EQ(out.three.boxes.size(), 3u);
  EXPECT_EQ(out.other.boxes.size(), 3u);
  return out;
}

TEST(Example, NodesThreeJsNumberedCarryTheLabelTheyCopy) {
  const std::string nodes = R"({"name": "quad", "mesh": 0}, {"name": "quad_1", "mesh": 0, "translation": [5, 0, 0]},
                              {"name": "quad_2_b", "mesh": 0, "translation": [10, 0, 0]})";
  const auto [from_three, other] = three_quads_from_three_js_and_other(nodes);
  ASSERT_EQ(from_three.boxes.size(), 3u);
  EXPECT_EQ(from_three.boxes[0].label, "quad");
  EXPECT_EQ(from_three.boxes[1].label, "quad");
  EXPECT_EQ(from_three.boxes[2].label, "quad_2_b");  // no copy number: a name of its own
  ASSERT_EQ(other.boxes.size(), 3u);
  EXPECT_EQ(other.boxes[1].label, "quad_1");
}

// three.js keeps the name it read as extras.name and renames the node
// ("window.001" to "window001", "a b" to "a_b", a taken name to "..._1"):
// in its files the kept name is the part's. Elsewhere extras are the
// author's own and the node's name is the part's.
TEST(Example, NodesThreeJsRenamedCarryTheNameItKeptInExtras) {
  const std::string nodes = R"({"name": "window001", "mesh": 0, "extras": {"name": "window.001"}},
                              {"name": "a_b", "mesh": 0, "translation": [5, 0, 0], "extras": {"name": "a b"}},
                              {"name": "quad_1", "mesh": 0, "translation": [10, 0, 0], "extras": {"name": 7}})";
  const auto [from_three, other] = three_quads_from_three_js_and_other(nodes);
  ASSERT_EQ(from_three.boxes.size(), 3u);
  EXPECT_EQ(from_three.boxes[0].label, "window");
  EXPECT_EQ(from_three.boxes[1].label, "a b");
  EXPECT_EQ(from_three.boxes[2].label, "quad");  // extras.name no text: the node's name, its copy number dropped
  ASSERT_EQ(other.boxes.size(), 3u);
  EXPECT_EQ(other.boxes[0].label, "window001");
  EXPECT_EQ(other.boxes[1].label, "a_b");
  EXPECT_EQ(other.boxes[2].label, "quad_1");
}

// A mesh that several nodes use is read once and placed for each
// (example.cpp, MeshReader): the parts are those copies of it would make,
// loose pieces apart split into parts, a mirrored node's faces turned.
TEST(Example, AMeshSharedByNodesReadsAsCopiesOfIt) {
  TempFolder dir;
  const std::string nodes[4] = {R"("name": "pair")",
                                R"("name": "pair.001", "translation": [10, 0, 0], "scale": [-1, 1, 1])",
                                R"("name": "quad")",
                                R"("name": "quad.001", "translation": [0, 5, 0], "scale": [2, 0.5, 1])"};
  auto node_list = [&](const int (&mesh)[4]) {
    std::string text;
    for (int i = 0; i < 4; ++i)
      text += std::string(i ? ", " : "") + "{" + nodes[i] + ", \"mesh\": " + std::to_string(mesh[i]) + "}";
    return text;
  };
  write_text(dir / "shared.gltf", two_meshes_gltf("01", node_list({0, 0, 1, 1})));
  write_text(dir / "copies.gltf", two_meshes_gltf("0011", node_list({0, 1, 2, 3})));
  const Example shared = load_example(dir / "shared.gltf");
  const Example copies = load_example(dir / "copies.gltf");
  ASSERT_EQ(shared.boxes.size(), 6u);
  ASSERT_EQ(copies.boxes.size(), 6u);
  const char* objects[6] = {"pair (loose part 1 of 2)", "pair (loose part 2 of 2)", "pair.001 (loose part 1 of 2)",
                            "pair.001 (loose part 2 of 2)", "quad", "quad.001"};
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(shared.boxes[i].object, objects[i]);
    EXPECT_EQ(shared.boxes[i].object, copies.boxes[i].object);
    EXPECT_EQ(shared.boxes[i].min, copies.boxes[i].min);
    EXPECT_EQ(shared.boxes[i].max, copies.boxes[i].max);
    EXPECT_EQ(shared.boxes[i].loose_pieces, 1u);
  }
  ASSERT_EQ(shared.meshes.size(), copies.meshes.size());
  for (std::size_t i = 0; i < shared.meshes.size(); ++i) {
    EXPECT_EQ(shared.meshes[i].positions, copies.meshes[i].positions);
    EXPECT_EQ(shared.meshes[i].corners, copies.meshes[i].corners);
  }
}

// A shared mesh is read by its first part, and each node after it is
// placed anew: a vertex placed too far names the node that placed it.
TEST(Example, ASharedMeshFailsAtTheFirstNodeThatCannotBePlaced) {
  TempFolder dir;
  const std::string far = R"("scale": [1e300, 1, 1])";
  write_text(dir / "first.gltf",
             two_meshes_gltf("0", R"({"name": "a", "mesh": 0, )" + far + R"(}, {"name": "b", "mesh": 0})", "0, 1"));
  std::string e = load_error(dir / "first.gltf");
  EXPECT_TRUE(contains(e, "node 0 'a': vertex 1 lies at (1e+300, 0, 0)")) << e;
  write_text(dir / "second.gltf",
             two_meshes_gltf("0", R"({"name": "a", "mesh": 0}, {"name": "b", "mesh": 0, )" + far + "}", "0, 1"));
  e = load_error(dir / "second.gltf");
  EXPECT_TRUE(contains(e, "node 1 'b': vertex 1 lies at (1e+300, 0, 0)")) << e;
}

TEST(Example, GltfErrors) {
  TempFolder dir;
  write_text(dir / "unnamed.gltf", triangle_gltf(""));
  std::string e = load_error(dir / "unnamed.gltf");
  EXPECT_TRUE(contains(e, "unnamed.gltf: error: node 1 has a mesh but no name")) << e;

  write_text(dir / "broken.glb", "glTF not really");
  e = load_error(dir / "broken.glb");
  EXPECT_TRUE(contains(e, "broken.glb: error: is not a valid GLB file")) << e;

  write_text(dir / "bare.gltf", R"({"asset": {"version": "2.0"}, "nodes": [{"name": "empty"}]})");
  e = load_error(dir / "bare.gltf");
  EXPECT_TRUE(contains(e, "has no labelled objects; each part must be a named glTF node with a mesh")) << e;
}

}  // namespace
}  // namespace vern
