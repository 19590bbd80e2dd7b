// The bad-input corpus (tests/bad_inputs/README.md): hostile and broken
// input for every command, each run as a user would run it. Each case
// asserts the exact exit code (the error class), that the message names
// where (file:line:col, or file and object, or the option) and what, that
// it carries a hint of what to do, and that the run folder is byte for
// byte what it was: no output created, none changed (some cases put a
// precious file where the output would go).
//
// Inputs are copied from tests/bad_inputs/ into a fresh folder per case;
// binary and large inputs are made there by the case's setup instead.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/gltf_container.hpp"
#include "support/bad_input_helpers.hpp"
#include "support/run_command.hpp"

namespace vern {
namespace {

namespace fs = std::filesystem;
using test::FolderSnapshot;
using test::run_program;
using test::TempFolder;
using test::write_text;

const fs::path kCorpus = VERN_SOURCE_DIR "/tests/bad_inputs";

constexpr int kOk = 0, kUsage = 2, kInput = 3, kLimit = 4, kIo = 5;

struct BadInput {
  const char* name;
  const char* tool;               // generate, infer, check or evaluate
  std::vector<std::string> args;  // run in the case's folder
  int exit_code;
  std::string where;  // the place the message must name ("x.obj:2:3: error: ")
  std::string what;   // and what it must say
  std::vector<std::string> inputs = {};  // corpus files (under tests/bad_inputs/) copied in
  void (*setup)(const fs::path& folder) = nullptr;
  const char* precious = nullptr;  // a file pre-created where the output would go
  std::size_t max_memory_mib = 0;  // when set, the run's peak resident memory is bounded
  std::vector<std::string> creates = {};  // for the cases that must succeed
  std::string unsaid = {};  // what the message must not say (a size of a file it should not read)
  std::size_t address_space_mib = 0;  // when set, the run's memory is capped (setrlimit), to run out of it
  std::size_t max_file_bytes = 0;     // when set, files the run writes are capped there (a full disk)
};

// AddressSanitizer reserves terabytes of address space: a capped run
// cannot start under it.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

// gtest prints a failing case by its name, not as bytes.
void PrintTo(const BadInput& c, std::ostream* os) { *os << c.name; }

void binary_file(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string glb_bytes(const fs::path& folder) {
  test::write_generated_glb(folder, "source.glb");
  std::string bytes = test::read_file(folder / "source.glb");
  fs::remove(folder / "source.glb");
  return bytes;
}

std::string u32(std::uint32_t v) {
  std::string s(4, '\0');
  for (int i = 0; i < 4; ++i) s[static_cast<std::size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xFF);
  return s;
}

// two_parts.gltf with its buffer in the file `uri` of `byte_length` bytes.
std::string gltf_naming(const std::string& uri, std::size_t byte_length) {
  std::string text = test::read_file(kCorpus / "gltf/two_parts.gltf");
  const std::size_t start = text.find("data:");
  text.replace(start, text.find('"', start) - start, uri);
  const std::string length = "\"byteLength\": 48\n  }\n ]";
  text.replace(text.rfind(length), length.size(), "\"byteLength\": " + std::to_string(byte_length) + "\n  }\n ]");
  return text;
}

// The 48 bytes two_parts.gltf's buffer holds: four corners of a unit box.
std::string box_bytes() {
  const float corners[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 1};
  return std::string(reinterpret_cast<const char*>(corners), sizeof corners);
}

// A wall drawn 4 million times (EXT_mesh_gpu_instancing), every copy at
// the origin: its buffer is 48 MB of zeros after the wall's corners, a
// sparse file.
void four_million_instances(const fs::path& d) {
  const std::string count = "4000000", length = "48000000";
  write_text(d / "model.gltf", R"({"asset": {"version": "2.0"}, "extensionsUsed": ["EXT_mesh_gpu_instancing"],
 "buffers": [{"uri": "instances.bin", "byteLength": 48000048}],
 "bufferViews": [{"buffer": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": )" + length + R"(}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
               {"bufferView": 1, "componentType": 5126, "count": )" + count + R"(, "type": "VEC3"}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
 "nodes": [{"name": "wall", "mesh": 0, "extensions": {"EXT_mesh_gpu_instancing": {"attributes": {"TRANSLATION": 1}}}}],
 "scenes": [{"nodes": [0]}], "scene": 0})");
  binary_file(d / "instances.bin", box_bytes());
  fs::resize_file(d / "instances.bin", 48000048);
}

// Eleven nodes share one mesh of a million triangles over four corners
// (indices as bytes: a 3 MB file). Each node places it anew: 11 million
// faces, past --max-total-faces.
void eleven_nodes_share_a_million_triangles(const fs::path& d) {
  const std::size_t triangles = 1'000'000;
  const float corners[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 1};
  std::string bin(reinterpret_cast<const char*>(corners), sizeof corners);
  std::string indices;
  const std::string four = std::string("\0\1\2\0\2\3\0\1\3\1\2\3", 12);
  for (std::size_t t = 0; t < triangles / 4; ++t) indices += four;
  bin += indices;
  std::string nodes;
  for (int i = 0; i <= 10; ++i) {
    nodes += std::string(i ? ", " : "") + R"({"name": "wall.)" + std::to_string(i) +
             R"(", "mesh": 0, "translation": [)" + std::to_string(2 * i) + ", 0, 0]}";
  }
  const std::string json = R"({"asset": {"version": "2.0"},
 "buffers": [{"byteLength": )" + std::to_string(bin.size()) + R"(}],
 "bufferViews": [{"buffer": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": )" +
                     std::to_string(indices.size()) + R"(}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
               {"bufferView": 1, "componentType": 5121, "count": )" + std::to_string(indices.size()) +
                     R"(, "type": "SCALAR"}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
 "nodes": [)" + nodes + R"(], "scenes": [{"nodes": [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10]}], "scene": 0})";
  binary_file(d / "shared.glb",
              glb_header(json.size(), bin.size()) + json + glb_between(json.size(), bin.size()) + bin);
}

// 18 MB of JSON: nine million numbers in `extras`, which tinygltf would
// read into some 1.8 GB.
void json_of_18_mb(const fs::path& d) {
  std::string text = R"({"asset": {"version": "2.0"}, "extras": [1)";
  text.reserve(18'000'100);
  for (int i = 1; i < 9'000'000; ++i) text += ",1";
  binary_file(d / "numbers.gltf", text + "]}");
}

// A grammar of `lines` alternatives of one label, 15 bytes a line.
void many_alternatives(const fs::path& path, std::size_t lines) {
  std::string text;
  text.reserve(15 * lines);
  for (std::size_t i = 0; i < lines; ++i) text += "a --> I(x) : 1\n";
  write_text(path, text);
}

// A rule of `count` parameters, q0 to q(count - 1).
void many_parameters(const fs::path& path, std::size_t count) {
  std::string text = "p --> nil\nr(q0";
  for (std::size_t i = 1; i < count; ++i) text += ", q" + std::to_string(i);
  write_text(path, text + ") --> nil\n");
}

// min() of 65,534 arguments, half of them a parameter, derived 100 times.
void min_of_many_arguments(const fs::path& path) {
  std::string text = "p --> repeatN(x, 100){ q(1) }\nq(v) --> split(x){ ~min(1";
  for (int i = 1; i < 65534; ++i) text += i % 2 ? ", v" : ", 1";
  write_text(path, text + ") : I(rect) }\n");
}

// Files a failed run must leave as they were: the outputs of an earlier run.
void earlier_outputs(const fs::path& d, const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    fs::create_directories((d / name).parent_path());
    write_text(d / name, "an earlier run's " + name + ": must survive a failed run\n");
  }
}

// ex/model.gltf, whose buffer is ../secret.bin.
void secret_beside_the_folder(const fs::path& d) {
  fs::create_directory(d / "ex");
  write_text(d / "ex/model.gltf", gltf_naming("../secret.bin", 48));
  binary_file(d / "secret.bin", box_bytes());
}

// model.gltf, whose buffer is the file `name`: an input no command line names.
void buffer_named(const fs::path& d, const std::string& name) {
  write_text(d / "model.gltf", gltf_naming(name, 48));
  binary_file(d / name, box_bytes());
}

// A --primitives folder `p` holding one mesh, `name`.
void primitives_folder(const fs::path& d, const std::string& name) {
  fs::create_directory(d / "p");
  fs::copy_file(kCorpus / "obj/two_parts.obj", d / "p" / name);
}

void fifo(const fs::path& path) { ASSERT_EQ(mkfifo(path.c_str(), 0644), 0) << path; }

// The grammars copied in moved into g/, with a valid OBJ, secret.obj, beside
// that folder: what a grammar's @primitives may not reach.
void grammar_in_a_folder_beside_a_secret(const fs::path& d) {
  fs::create_directory(d / "g");
  for (const fs::directory_entry& e : fs::directory_iterator(d))
    if (e.path().extension() == ".grm") fs::rename(e.path(), d / "g" / e.path().filename());
  fs::copy_file(kCorpus / "obj/two_parts.obj", d / "secret.obj");
}

// prims/, a primitives folder holding a link that leads to itself.
void link_loop_in_prims(const fs::path& d) {
  fs::create_directory(d / "prims");
  fs::create_symlink("loop.obj", d / "prims/loop.obj");
}

// The file that is not there, the folder given for a file, and the valid
// references the CLI cases start from.
const std::vector<std::string> kValidObj = {"obj/two_parts.obj"};
const std::vector<std::string> kValidGrammar = {"grammar/ok.grm"};
const std::vector<std::string> kGrammarAndObj = {"grammar/ok.grm", "obj/two_parts.obj"};

// clang-format off
const std::vector<BadInput> kCases = {
  // ---- OBJ examples (infer; check reads them the same way) ----
  {"obj_missing_file", "infer", {"missing.obj", "-o", "style.grm"}, kIo,
   "missing.obj: error: ", "no such file"},
  {"obj_a_folder", "infer", {"parts.obj", "-o", "style.grm"}, kIo,
   "parts.obj: error: ", "the folder holds no example files",
   {}, [](const fs::path& d) { fs::create_directory(d / "parts.obj"); }},
  {"obj_empty_file", "infer", {"empty.obj", "-o", "style.grm"}, kInput,
   "empty.obj: error: ", "has no labelled objects", {"obj/empty.obj"}, nullptr, "style.grm"},
  {"obj_binary_garbage", "infer", {"garbage.obj", "-o", "style.grm"}, kInput,
   "garbage.obj:1:8: error: ", "NUL byte",
   {}, [](const fs::path& d) { binary_file(d / "garbage.obj", std::string("\x7f" "ELF\x02\x01\x01\0\0\0\0\0\0\0\0\0\x03\0>\0", 20)); }},
  {"obj_binary_without_nul", "infer", {"noise.obj", "-o", "style.grm"}, kInput,
   "noise.obj:1:1: error: ", "this line is not an OBJ statement, nor is any line before it",
   {}, [](const fs::path& d) { binary_file(d / "noise.obj", "\xff\xfe\xfd\xfc\x80\x81 \x90\n"); }},
  {"obj_nul_in_text", "infer", {"nul.obj", "-o", "style.grm"}, kInput,
   "nul.obj:2:8: error: ", "NUL byte",
   {}, [](const fs::path& d) { binary_file(d / "nul.obj", std::string("o wall\nv 0 0 0\0\n", 16)); }},
  {"obj_non_utf8_name", "infer", {"latin1.obj", "-o", "style.grm"}, kInput,
   "latin1.obj:1:6: error: ", "the name is not UTF-8 text (byte 0xEA)",
   {}, [](const fs::path& d) {
     binary_file(d / "latin1.obj", "o fen\xeatre\nv 0 0 0\nv 1 0 0\nv 1 1 1\nf 1 2 3\n"); }},
  // A name that cannot be a label is refused where it is read (graph/label.hpp).
  {"obj_name_with_control_character", "infer", {"escape.obj", "-o", "style.grm"}, kInput,
   "escape.obj:1:1: error: ", "the object name 'wall\\x1B[2J' cannot be a label: it holds a control character (U+001B)",
   {}, [](const fs::path& d) { binary_file(d / "escape.obj", "o wall\x1b[2J\nv 0 0 0\nv 1 0 0\nv 1 1 1\nf 1 2 3\n"); }},
  {"obj_name_escaping_a_line_break", "infer", {"name_escaping_a_line_break.obj", "-o", "style.grm"}, kInput,
   "name_escaping_a_line_break.obj:2:1: error: ",
   "the object name 'wall%0Af 1 2 3' (read as 'wall\\nf 1 2 3') cannot be a label: it holds a line break",
   {"obj/name_escaping_a_line_break.obj"}},
  {"obj_utf8_name_works", "infer", {"utf8_name.obj", "-o", "style.grm"}, kOk,
   "", "", {"obj/utf8_name.obj"}, nullptr, nullptr, 0, {"style.grm", "style.prims.obj"}},
  {"obj_not_obj_text", "infer", {"not_obj_text.obj", "-o", "style.grm"}, kInput,
   "not_obj_text.obj:1:1: error: ", "this line is not an OBJ statement, nor is any line before it",
   {"obj/not_obj_text.obj"}, nullptr, nullptr, 0, {}, "Dear"},
  {"obj_wrong_extension", "infer", {"notes.txt", "-o", "style.grm"}, kUsage,
   "notes.txt: error: ", "is not an example file", {"obj/notes.txt"}},
  {"obj_faces_before_vertices", "infer", {"faces_before_vertices.obj", "-o", "style.grm"}, kInput,
   "faces_before_vertices.obj:2:3: error: ", "the face refers to vertex 1, but 0 vertices are defined above it",
   {"obj/faces_before_vertices.obj"}},
  {"obj_face_index_out_of_range", "infer", {"face_index_out_of_range.obj", "-o", "style.grm"}, kInput,
   "face_index_out_of_range.obj:11:9: error: ", "vertex 9, but 8 vertices", {"obj/face_index_out_of_range.obj"}},
  {"obj_face_index_zero", "infer", {"face_index_zero.obj", "-o", "style.grm"}, kInput,
   "face_index_zero.obj:11:3: error: ", "a vertex index of 0 is not valid", {"obj/face_index_zero.obj"}},
  {"obj_negative_indices_work", "infer", {"negative_indices_valid.obj", "-o", "style.grm"}, kOk,
   "", "", {"obj/negative_indices_valid.obj"}, nullptr, nullptr, 0, {"style.grm", "style.prims.obj"}},
  {"obj_negative_index_out_of_range", "infer", {"negative_index_out_of_range.obj", "-o", "style.grm"}, kInput,
   "negative_index_out_of_range.obj:5:9: error: ", "vertex -4, but 3 vertices", {"obj/negative_index_out_of_range.obj"}},
  {"obj_texture_index_out_of_range", "infer", {"texture_index_out_of_range.obj", "-o", "style.grm"}, kInput,
   "texture_index_out_of_range.obj:6:13: error: ", "texture coordinate 2, but 1 texture coordinate",
   {"obj/texture_index_out_of_range.obj"}},
  {"obj_normal_index_out_of_range", "infer", {"normal_index_out_of_range.obj", "-o", "style.grm"}, kInput,
   "normal_index_out_of_range.obj:6:16: error: ", "normal -2, but 1 normal", {"obj/normal_index_out_of_range.obj"}},
  {"obj_index_not_a_number", "infer", {"index_not_a_number.obj", "-o", "style.grm"}, kInput,
   "index_not_a_number.obj:5:7: error: ", "expected a vertex index, found 'x'", {"obj/index_not_a_number.obj"}},
  {"obj_index_too_large", "infer", {"index_too_large.obj", "-o", "style.grm"}, kInput,
   "index_too_large.obj:5:7: error: ", "is out of range", {"obj/index_too_large.obj"}},
  {"obj_nan_coordinate", "infer", {"nan_coordinate.obj", "-o", "style.grm"}, kInput,
   "nan_coordinate.obj:8:5: error: ", "'nan' is not a finite number", {"obj/nan_coordinate.obj"}},
  {"obj_inf_coordinate", "infer", {"inf_coordinate.obj", "-o", "style.grm"}, kInput,
   "inf_coordinate.obj:8:7: error: ", "'-inf' is not a finite number", {"obj/inf_coordinate.obj"}},
  {"obj_1e308_coordinate", "infer", {"huge_coordinate.obj", "-o", "style.grm"}, kInput,
   "huge_coordinate.obj:8:3: error: ", "'1e308' is too large", {"obj/huge_coordinate.obj"}},
  {"obj_coordinate_overflows_double", "infer", {"coordinate_overflows_double.obj", "-o", "style.grm"}, kInput,
   "coordinate_overflows_double.obj:8:5: error: ", "'1e999' is out of range", {"obj/coordinate_overflows_double.obj"}},
  {"obj_coordinate_underflows_double", "infer", {"coordinate_underflows_double.obj", "-o", "style.grm"}, kInput,
   "coordinate_underflows_double.obj:8:5: error: ",
   "'1e-400' is too small for a number: nearer to zero than any double", {"obj/coordinate_underflows_double.obj"}},
  // A file's own up axis (io/obj_reader.hpp): y or z, before any vertex.
  {"obj_up_axis_unknown", "infer", {"up_axis_unknown.obj", "-o", "style.grm"}, kInput,
   "up_axis_unknown.obj:1:6: error: ", "'# up x' declares an up axis other than y or z", {"obj/up_axis_unknown.obj"}},
  {"obj_up_declared_after_vertices", "infer", {"up_declared_after_vertices.obj", "-o", "style.grm"}, kInput,
   "up_declared_after_vertices.obj:3:1: error: ", "the up axis is declared after vertices",
   {"obj/up_declared_after_vertices.obj"}},
  {"obj_coordinate_not_a_number", "infer", {"coordinate_not_a_number.obj", "-o", "style.grm"}, kInput,
   "coordinate_not_a_number.obj:2:5: error: ", "found 'zero'", {"obj/coordinate_not_a_number.obj"}},
  {"obj_vertex_with_two_numbers", "infer", {"vertex_with_two_numbers.obj", "-o", "style.grm"}, kInput,
   "vertex_with_two_numbers.obj:2:1: error: ", "a vertex needs 3 numbers, found 2", {"obj/vertex_with_two_numbers.obj"}},
  {"obj_face_with_two_corners", "infer", {"face_with_two_corners.obj", "-o", "style.grm"}, kInput,
   "face_with_two_corners.obj:4:1: error: ", "at least 3 corners", {"obj/face_with_two_corners.obj"}},
  {"obj_objects_without_vertices", "infer", {"objects_without_vertices.obj", "-o", "style.grm"}, kInput,
   "objects_without_vertices.obj: error: ", "each part must be an OBJ object `o name` with its faces", {"obj/objects_without_vertices.obj"}},
  {"obj_unlabelled_geometry", "infer", {"unlabelled_geometry.obj", "-o", "style.grm"}, kInput,
   "unlabelled_geometry.obj:9:1: error: ", "these faces have no name", {"obj/unlabelled_geometry.obj"}},
  {"obj_unlabelled_before_labelled", "infer", {"unlabelled_before_labelled.obj", "-o", "style.grm"}, kInput,
   "unlabelled_before_labelled.obj:9:1: error: ", "these faces have no name", {"obj/unlabelled_before_labelled.obj"}},
  {"obj_single_flat_box_works", "infer", {"single_flat_box.obj", "-o", "style.grm"}, kOk,
   "", "", {"obj/single_flat_box.obj"}, nullptr, nullptr, 0, {"style.grm", "style.prims.obj"}},
  {"obj_single_point", "infer", {"single_point.obj", "-o", "style.grm"}, kInput,
   "single_point.obj:1:1: error: ", "object 'wall' (line 1) is a single point", {"obj/single_point.obj"}},
  // A part far away sets the tolerance: the message says which.
  {"obj_small_part_beside_a_far_one", "infer", {"point_far_away.obj", "-o", "style.grm"}, kInput,
   "point_far_away.obj:17:1: error: ", "object 'pin' (line 17) is 0.001 m across at most, no larger than the "
   "example's tolerance, 0.002001 m: too small to tell from a point (the tolerance is a millionth of its span, "
   "2001 m from 'wall' (line 2) to 'post' (line 32))", {"obj/point_far_away.obj"}},
  {"obj_small_part_under_the_given_tolerance", "check", {"ok.grm", "two_parts.obj", "--tolerance", "5"}, kInput,
   "two_parts.obj:", "no larger than --tolerance 5: too small to tell from a point", kGrammarAndObj},
  // Sizes whose millionth is near the end of what doubles hold.
  {"obj_subnormal_example", "infer", {"subnormal_example.obj", "-o", "style.grm"}, kInput,
   "subnormal_example.obj: error: ", "the example is 3e-308 m across: too small for a building in metres",
   {"obj/subnormal_example.obj"}},
  {"obj_duplicate_coincident_parts", "infer", {"duplicate_coincident.obj", "-o", "style.grm"}, kInput,
   "duplicate_coincident.obj:1:1: error: ", "objects 'wall' (line 1) and 'wall' (line 16) overlap",
   {"obj/duplicate_coincident.obj"}, nullptr, "style.grm"},
  {"obj_overlapping_parts", "infer", {"overlapping.obj", "-o", "style.grm"}, kInput,
   "overlapping.obj:1:1: error: ", "objects 'wall' (line 1) and 'door' (line 16) overlap", {"obj/overlapping.obj"}},
  // Issue 16, item 4: loose pieces that cannot be told apart are one part;
  // when that part overlaps, the hint says how Blender separates them.
  {"obj_loose_pieces_overlap", "infer", {"loose_pieces_overlap.obj", "-o", "style.grm"}, kInput,
   "loose_pieces_overlap.obj:1:1: error: ", "is 2 loose pieces in one object: make each its own object (Blender: Edit Mode, Mesh > Separate > By Loose Parts)",
   {"obj/loose_pieces_overlap.obj"}},
  // Issue 24, item 1: a part inside another is set into it, its container
  // cut around it (layered_parts.hpp); overlaps neither contains need --stack.
  {"obj_part_inside_part_is_set_into_it", "infer", {"contained.obj", "-o", "style.grm"}, kOk,
   "", "", {"obj/contained.obj"}, nullptr, nullptr, 0, {"style.grm", "style.prims.obj"}},
  {"obj_overlap_names_the_stack", "infer", {"overlapping.obj", "-o", "style.grm"}, kInput,
   "overlapping.obj:1:1: error: ", "hint: say which is painted over which, bottom to top: --stack wall,door",
   {"obj/overlapping.obj"}},
  {"stack_with_an_empty_label", "infer", {"overlapping.obj", "-o", "style.grm", "--stack", "wall,,door"}, kUsage,
   "infer: error: ", "--stack 'wall,,door' has an empty label", {"obj/overlapping.obj"}},
  {"stack_listing_a_label_twice", "check", {"ok.grm", "two_parts.obj", "--stack", "wall,door,wall"}, kUsage,
   "check: error: ", "--stack 'wall,door,wall' lists 'wall' twice", kGrammarAndObj},
  // No straight cut separates a pinwheel: inferred all the same, with S
  // placements and a warning naming the parts.
  {"obj_pinwheel_is_placed_with_a_warning", "infer", {"pinwheel.obj", "-o", "style.grm"}, kOk,
   "pinwheel.obj:2:1: warning: ", "no straight cut separates these 5 parts (e.g. a pinwheel): they are placed with "
   "S(...) at their corners: 'a' (line 2), 'b' (line 17)", {"obj/pinwheel.obj"}, nullptr, nullptr, 0,
   {"style.grm", "style.prims.obj"}},
  {"obj_bad_example_in_check", "check", {"ok.grm", "nan_coordinate.obj"}, kInput,
   "nan_coordinate.obj:8:5: error: ", "not a finite number", {"grammar/ok.grm", "obj/nan_coordinate.obj"}},
  {"obj_16mb_line_without_breaks", "infer", {"endless.obj", "-o", "style.grm"}, kInput,
   "endless.obj:1:1: error: ", "a line longer than 1048576 bytes",
   {}, [](const fs::path& d) { test::write_endless_line(d / "endless.obj", std::size_t{16} << 20); }, nullptr, 100},
  // 200 MB that must be read to the end: memory stays far below the size.
  {"obj_200mb_file_is_streamed", "infer", {"huge.obj", "-o", "style.grm"}, kOk,
   "", "", {}, [](const fs::path& d) { test::write_commented_obj(d / "huge.obj", std::size_t{200} << 20); },
   nullptr, 100, {"style.grm", "style.prims.obj"}},
  // 64 MB of parts: reading stops at the first part past the limit.
  {"obj_example_is_a_fifo", "infer", {"pipe.obj", "-o", "style.grm"}, kIo,
   "pipe.obj: error: ", "is a FIFO (named pipe), not a regular file", {}, [](const fs::path& d) { fifo(d / "pipe.obj"); }},
  {"obj_example_is_a_device", "check", {"ok.grm", "zero.obj"}, kIo,
   "zero.obj: error: ", "is a character device, not a regular file", kValidGrammar,
   [](const fs::path& d) { fs::create_symlink("/dev/zero", d / "zero.obj"); }},
  {"obj_too_many_parts", "infer", {"city.obj", "-o", "style.grm"}, kLimit,
   "city.obj:150010:1: error: ", "more than 10000 objects with faces",
   {}, [](const fs::path& d) { test::write_many_parts_obj(d / "city.obj", 200000); }, "style.grm", 100},
  {"obj_out_of_memory_names_the_example", "infer", {"city.obj", "--max-parts", "1000000", "-j", "1", "-o", "style.grm"},
   kLimit, "city.obj: error: ", "out of memory",
   {}, [](const fs::path& d) { test::write_many_parts_obj(d / "city.obj", 200000); }, "style.grm", 0, {}, {}, 150},
  // A part's faces are bounded too: matching its mesh grows with them.
  {"obj_too_many_faces", "infer", {"two_parts.obj", "--max-faces", "5", "-o", "style.grm"}, kLimit,
   "two_parts.obj:16:1: error: ", "'wall' (line 2) has more than 5 faces: reading stopped here\n  hint: raise the "
   "limit with --max-faces (now 5)", kValidObj},
  {"obj_too_many_faces_in_check", "check", {"ok.grm", "two_parts.obj", "--max-faces", "5"}, kLimit,
   "two_parts.obj:16:1: error: ", "has more than 5 faces", kGrammarAndObj},
  {"obj_too_many_parts_in_check", "check", {"ok.grm", "two_parts.obj", "--max-parts", "1"}, kLimit,
   "two_parts.obj:", "more than 1 objects with faces", kGrammarAndObj},

  // ---- glTF and GLB examples ----
  {"glb_truncated", "infer", {"truncated.glb", "-o", "style.grm"}, kInput,
   "truncated.glb: error: ", "is not a valid GLB file",
   {}, [](const fs::path& d) { binary_file(d / "truncated.glb", glb_bytes(d).substr(0, 100)); }},
  {"glb_wrong_magic", "infer", {"magic.glb", "-o", "style.grm"}, kInput,
   "magic.glb: error: ", "is not a valid GLB file: it does not start with the magic 'glTF'",
   {}, [](const fs::path& d) { binary_file(d / "magic.glb", "glTX" + glb_bytes(d).substr(4)); }},
  {"glb_empty", "infer", {"empty.glb", "-o", "style.grm"}, kInput,
   "empty.glb: error: ", "is not a valid GLB file",
   {}, [](const fs::path& d) { binary_file(d / "empty.glb", ""); }},
  {"glb_header_only", "infer", {"header.glb", "-o", "style.grm"}, kInput,
   "header.glb: error: ", "is not a valid GLB file",
   {}, [](const fs::path& d) { binary_file(d / "header.glb", glb_bytes(d).substr(0, 12)); }},
  {"glb_length_past_the_end", "infer", {"length.glb", "-o", "style.grm"}, kInput,
   "length.glb: error: ", "is not a valid GLB file",
   {}, [](const fs::path& d) { const std::string b = glb_bytes(d); binary_file(d / "length.glb", b.substr(0, 8) + u32(1u << 30) + b.substr(12)); }},
  {"glb_chunk_past_the_end", "infer", {"chunk.glb", "-o", "style.grm"}, kInput,
   "chunk.glb: error: ", "is not a valid GLB file",
   {}, [](const fs::path& d) { const std::string b = glb_bytes(d); binary_file(d / "chunk.glb", b.substr(0, 12) + u32(1u << 30) + b.substr(16)); }},
  {"glb_is_gltf_text", "infer", {"text.glb", "-o", "style.grm"}, kInput,
   "text.glb: error: ", "is not a valid GLB file: it does not start with the magic 'glTF'",
   {}, [](const fs::path& d) { fs::copy_file(kCorpus / "gltf/two_parts.gltf", d / "text.glb"); }},
  {"gltf_missing_buffer_file", "infer", {"missing_buffer.gltf", "-o", "style.grm"}, kInput,
   "missing_buffer.gltf: error: ", "missing.bin", {"gltf/missing_buffer.gltf"}, nullptr, "style.grm"},
  {"gltf_no_buffers", "infer", {"no_buffers.gltf", "-o", "style.grm"}, kInput,
   "no_buffers.gltf: error: ", "node 0 'wall': its POSITION accessor has no buffer", {"gltf/no_buffers.gltf"}},
  {"gltf_short_data_uri", "infer", {"short_data_uri.gltf", "-o", "style.grm"}, kInput,
   "short_data_uri.gltf: error: ", "is not a valid glTF file", {"gltf/short_data_uri.gltf"}},
  {"gltf_bad_json", "infer", {"bad_json.gltf", "-o", "style.grm"}, kInput,
   "bad_json.gltf: error: ", "parse error at line 1", {"gltf/bad_json.gltf"}},
  {"gltf_empty", "infer", {"empty.gltf", "-o", "style.grm"}, kInput,
   "empty.gltf: error: ", "is not a valid glTF file", {"gltf/empty.gltf"}},
  {"gltf_not_json", "infer", {"not_json.gltf", "-o", "style.grm"}, kInput,
   "not_json.gltf: error: ", "is not a valid glTF file", {"gltf/not_json.gltf"}},
  {"gltf_accessor_out_of_range", "infer", {"accessor_out_of_range.gltf", "-o", "style.grm"}, kInput,
   "accessor_out_of_range.gltf: error: ", "node 0 'wall': its POSITION accessor reads past the end",
   {"gltf/accessor_out_of_range.gltf"}},
  // Offsets and counts near 2^64: the range check's own arithmetic must not
  // wrap round into a range that fits (a heap read past the buffer, or
  // coordinates taken from outside the accessor's view with exit 0).
  {"gltf_accessor_count_overflows", "infer", {"accessor_count_overflows.gltf", "-o", "style.grm"}, kInput,
   "accessor_count_overflows.gltf: error: ", "node 0 'wall': its POSITION accessor reads past the end of its buffer",
   {"gltf/accessor_count_overflows.gltf"}},
  {"gltf_accessor_offset_wraps", "infer", {"accessor_offset_wraps.gltf", "-o", "style.grm"}, kInput,
   "accessor_offset_wraps.gltf: error: ", "node 0 'wall': its POSITION accessor reads past the end of its buffer",
   {"gltf/accessor_offset_wraps.gltf"}},
  {"gltf_index_count_overflows", "infer", {"index_count_overflows.gltf", "-o", "style.grm"}, kInput,
   "index_count_overflows.gltf: error: ", "node 0 'wall': its index accessor reads past the end of its buffer",
   {"gltf/index_count_overflows.gltf"}},
  {"gltf_buffer_view_out_of_range", "infer", {"buffer_view_out_of_range.gltf", "-o", "style.grm"}, kInput,
   "buffer_view_out_of_range.gltf: error: ", "node 0 'wall': its POSITION accessor has no buffer view",
   {"gltf/buffer_view_out_of_range.gltf"}},
  {"gltf_nan_texture_coordinate", "infer", {"nan_texture_coordinate.gltf", "-o", "style.grm"}, kInput,
   "nan_texture_coordinate.gltf: error: ", "node 0 'wall': its TEXCOORD_0 accessor holds a value that is not a finite number",
   {"gltf/nan_texture_coordinate.gltf"}},
  {"gltf_node_without_name", "infer", {"node_without_name.gltf", "-o", "style.grm"}, kInput,
   "node_without_name.gltf: error: ", "node 1 has a mesh but no name", {"gltf/node_without_name.gltf"}},
  {"gltf_node_name_with_line_break", "infer", {"node_name_with_line_break.gltf", "-o", "style.grm"}, kInput,
   "node_name_with_line_break.gltf: error: ",
   "the name of node 0 'wall\\nf 1 2 3' cannot be a label: it holds a line break",
   {"gltf/node_name_with_line_break.gltf"}},
  {"gltf_mesh_index_out_of_range", "infer", {"mesh_index_out_of_range.gltf", "-o", "style.grm"}, kInput,
   "mesh_index_out_of_range.gltf: error: ", "node 1 'roof' refers to mesh 7", {"gltf/mesh_index_out_of_range.gltf"}},
  {"gltf_node_cycle", "infer", {"node_cycle.gltf", "-o", "style.grm"}, kInput,
   "node_cycle.gltf: error: ", "node 0 'wall' is its own ancestor (a cycle through node 1 'roof')",
   {"gltf/node_cycle.gltf"}},
  {"gltf_huge_transform", "infer", {"huge_transform.gltf", "-o", "style.grm"}, kInput,
   "huge_transform.gltf: error: ", "node 1 'roof': vertex 1 lies at (1e+300, 0, 0)", {"gltf/huge_transform.gltf"}},
  {"gltf_no_nodes", "infer", {"no_nodes.gltf", "-o", "style.grm"}, kInput,
   "no_nodes.gltf: error: ", "has no labelled objects", {"gltf/no_nodes.gltf"}},
  {"gltf_overlapping_nodes", "infer", {"overlapping_nodes.gltf", "-o", "style.grm"}, kInput,
   "overlapping_nodes.gltf: error: ", "objects 'wall' and 'roof' overlap", {"gltf/overlapping_nodes.gltf"}},
  // glTF's rules that tinygltf leaves unchecked (io/gltf_rules.hpp).
  {"gltf_child_out_of_range", "infer", {"child_out_of_range.gltf", "-o", "style.grm"}, kInput,
   "child_out_of_range.gltf: error: ", "node 0 'wall' lists child 5, but the file has 2 nodes",
   {"gltf/child_out_of_range.gltf"}},
  {"gltf_scene_node_out_of_range", "infer", {"scene_node_out_of_range.gltf", "-o", "style.grm"}, kInput,
   "scene_node_out_of_range.gltf: error: ", "scene 0 lists node 7, but the file has 2 nodes",
   {"gltf/scene_node_out_of_range.gltf"}},
  {"gltf_byte_stride_below_element", "infer", {"byte_stride_below_element.gltf", "-o", "style.grm"}, kInput,
   "byte_stride_below_element.gltf: error: ", "node 0 'wall': its POSITION accessor (accessor 0) has byteStride 4 "
   "(buffer view 0), less than its elements' 12 bytes", {"gltf/byte_stride_below_element.gltf"}},
  {"gltf_unknown_required_extension", "infer", {"unknown_required_extension.gltf", "-o", "style.grm"}, kInput,
   "unknown_required_extension.gltf: error: ", "requires the extension KHR_meshopt_compression, which this "
   "reader does not implement", {"gltf/unknown_required_extension.gltf"}},
  {"gltf_primitive_mode_minus_one", "infer", {"primitive_mode_minus_one.gltf", "-o", "style.grm"}, kInput,
   "primitive_mode_minus_one.gltf: error: ", "node 0 'wall': mesh 0 primitive 0 has mode -1, which is not a glTF "
   "primitive mode", {"gltf/primitive_mode_minus_one.gltf"}},
  {"gltf_index_count_not_whole_triangles", "infer", {"index_count_not_whole_triangles.gltf", "-o", "style.grm"},
   kInput, "index_count_not_whole_triangles.gltf: error: ", "node 0 'wall': mesh 0 primitive 0 draws 4 vertex "
   "indices as TRIANGLES: not a multiple of 3", {"gltf/index_count_not_whole_triangles.gltf"}},
  {"glb_version_1", "infer", {"v1.glb", "-o", "style.grm"}, kInput,
   "v1.glb: error: ", "is not a valid GLB file: its header says container version 1; only version 2",
   {}, [](const fs::path& d) {
     const std::string b = glb_bytes(d);
     binary_file(d / "v1.glb", b.substr(0, 4) + u32(1) + b.substr(8)); }},
  // tinygltf reads extras recursively: 200,000 levels overflowed its stack.
  {"gltf_json_nested_too_deep", "infer", {"deep.gltf", "-o", "style.grm"}, kInput,
   "deep.gltf:1:", "its JSON nests arrays and objects more than 64 deep",
   {}, [](const fs::path& d) {
     write_text(d / "deep.gltf", R"({"asset": {"version": "2.0"}, "extras": )" + std::string(200000, '[') +
                                     std::string(200000, ']') + "}"); }},
  // JSON costs up to a few hundred bytes per value read: weighed first.
  {"gltf_json_of_18mb_bounds_memory", "infer", {"numbers.gltf", "-o", "style.grm"}, kLimit,
   "numbers.gltf: error: ", "MiB of memory once read: more than the limit of 256 MiB\n  hint: glTF JSON takes up "
   "to a few hundred bytes per value once read: raise the limit with --max-gltf-mib (now 256)",
   {}, json_of_18_mb, nullptr, 100},
  // Each node places a shared mesh anew: faces are bounded in all.
  {"glb_shared_mesh_past_max_total_faces", "infer", {"shared.glb", "-o", "style.grm"}, kLimit,
   "shared.glb: error: ", "the parts up to node 10 'wall.10' hold more than 10000000 faces in all",
   {}, eleven_nodes_share_a_million_triangles},
  {"gltf_past_max_total_faces", "infer", {"two_parts.gltf", "--max-total-faces", "5", "-o", "style.grm"}, kLimit,
   "two_parts.gltf: error: ", "the parts up to node 1 'roof' hold more than 5 vertices in all (a mesh counts once "
   "for each node that places it)\n  hint: raise the limit with --max-total-faces (now 5; it bounds vertices too)",
   {"gltf/two_parts.gltf"}},
  // Each instance is a part: reading stops at --max-parts before the
  // instances' transforms are made (4 million of 128 bytes: 512 MB).
  {"gltf_instances_past_max_parts", "infer", {"model.gltf", "-o", "style.grm"}, kLimit,
   "model.gltf: error: ", "node 0 'wall' has 4000000 instances, more than 10000 labelled parts",
   {}, four_million_instances, nullptr, 200},
  {"glb_too_many_faces", "infer", {"parts.glb", "--max-faces", "5", "-o", "style.grm"}, kLimit,
   "parts.glb: error: ", "node 1 'rect' has more than 5 faces\n  hint: raise the limit with --max-faces (now 5)",
   {}, [](const fs::path& d) { test::write_generated_glb(d, "parts.glb"); }},
  // Buffer URIs are the file's choice, not the user's: only regular files
  // in the glTF's folder (or below it) are read, none larger than a cap.
  {"gltf_buffer_outside_the_folder", "infer", {"ex/model.gltf", "-o", "style.grm"}, kInput,
   "ex/model.gltf: error: ", "the URI '../secret.bin' names a file outside the glTF's folder",
   {}, secret_beside_the_folder},
  {"gltf_buffer_outside_the_folder_allowed", "infer",
   {"ex/model.gltf", "--allow-outside-files", "-o", "style.grm"}, kOk, "", "",
   {}, secret_beside_the_folder, nullptr, 0, {"style.grm", "style.prims.obj"}},
  {"gltf_buffer_absolute_path", "infer", {"model.gltf", "-o", "style.grm"}, kInput,
   "model.gltf: error: ", "names a file outside the glTF's folder",
   {}, [](const fs::path& d) {
     fs::create_directory(d / "elsewhere");
     binary_file(d / "elsewhere/secret.bin", box_bytes());
     write_text(d / "model.gltf", gltf_naming((d / "elsewhere/secret.bin").string(), 48)); }},
  {"gltf_buffer_symlink_out_of_the_folder", "infer", {"ex/model.gltf", "-o", "style.grm"}, kInput,
   "ex/model.gltf: error: ", "the URI 'link.bin' names a file outside the glTF's folder",
   {}, [](const fs::path& d) {
     fs::create_directory(d / "ex");
     write_text(d / "ex/model.gltf", gltf_naming("link.bin", 48));
     binary_file(d / "secret.bin", box_bytes());
     fs::create_symlink("../secret.bin", d / "ex/link.bin"); }},
  {"gltf_buffer_in_a_subfolder_works", "infer", {"model.gltf", "-o", "style.grm"}, kOk, "", "",
   {}, [](const fs::path& d) {
     fs::create_directory(d / "buffers");
     write_text(d / "model.gltf", gltf_naming("buffers/box.bin", 48));
     binary_file(d / "buffers/box.bin", box_bytes()); }, nullptr, 0, {"style.grm", "style.prims.obj"}},
  {"gltf_buffer_size_is_not_told", "infer", {"model.gltf", "-o", "style.grm"}, kInput,
   "model.gltf: error: ", "the buffer file 'data.bin' does not hold the byteLength its buffer declares",
   {}, [](const fs::path& d) {
     write_text(d / "model.gltf", gltf_naming("data.bin", 48));
     binary_file(d / "data.bin", std::string(12345, 'x')); }, nullptr, 0, {}, "12345"},
  // A sparse file: 1 GiB long, nothing on the disk; never read whole.
  {"gltf_buffer_of_1gib", "infer", {"model.gltf", "-o", "style.grm"}, kLimit,
   "model.gltf: error: ", "the URI 'data.bin' names a file that is larger than 256 MiB",
   {}, [](const fs::path& d) {
     write_text(d / "model.gltf", gltf_naming("data.bin", std::size_t{1} << 30));
     binary_file(d / "data.bin", "");
     fs::resize_file(d / "data.bin", std::uintmax_t{1} << 30); },
   nullptr, 100},
  {"gltf_file_over_the_limit", "infer", {"big.gltf", "--max-gltf-mib", "1", "-o", "style.grm"}, kLimit,
   "big.gltf: error: ", "is larger than 1 MiB\n  hint: glTF files and the files they name are read whole: raise the "
   "limit with --max-gltf-mib (now 1)",
   {}, [](const fs::path& d) {
     binary_file(d / "big.gltf", "");
     fs::resize_file(d / "big.gltf", std::uintmax_t{2} << 20); }},
  {"gltf_buffer_is_a_fifo", "infer", {"model.gltf", "-o", "style.grm"}, kIo,
   "model.gltf: error: ", "the URI 'data.bin' names a file that is a FIFO (named pipe), not a regular file",
   {}, [](const fs::path& d) { write_text(d / "model.gltf", gltf_naming("data.bin", 48)); fifo(d / "data.bin"); }},
  {"gltf_example_is_a_fifo", "infer", {"pipe.glb", "-o", "style.grm"}, kIo,
   "pipe.glb: error: ", "is a FIFO (named pipe), not a regular file", {}, [](const fs::path& d) { fifo(d / "pipe.glb"); }},
  {"gltf_too_many_parts", "infer", {"two_parts.gltf", "--max-parts", "1", "-o", "style.grm"}, kLimit,
   "two_parts.gltf: error: ", "more than 1 labelled parts: reading stopped at node 1 'roof'", {"gltf/two_parts.gltf"}},

  // ---- grammars: the reader (generate) ----
  {"grammar_missing_file", "generate", {"missing.grm", "-o", "out.obj"}, kIo,
   "missing.grm: error: ", "cannot open the grammar file"},
  {"grammar_a_folder", "generate", {"style.grm", "-o", "out.obj"}, kIo,
   "style.grm: error: ", "is a folder", {}, [](const fs::path& d) { fs::create_directory(d / "style.grm"); }},
  {"grammar_is_a_fifo", "generate", {"pipe.grm", "-o", "out.obj"}, kIo,
   "pipe.grm: error: ", "is a FIFO (named pipe), not a regular file", {}, [](const fs::path& d) { fifo(d / "pipe.grm"); }},
  // Read whole, /dev/zero would never end.
  {"grammar_is_a_device", "check", {"zero.grm", "two_parts.obj"}, kIo,
   "zero.grm: error: ", "is a character device, not a regular file", kValidObj,
   [](const fs::path& d) { fs::create_symlink("/dev/zero", d / "zero.grm"); }},
  {"grammar_binary", "generate", {"binary.grm", "-o", "out.obj"}, kInput,
   "binary.grm:1:1: error: ", "unexpected character byte 0x7F",
   {}, [](const fs::path& d) { binary_file(d / "binary.grm", std::string("\x7f" "ELF\x02\x01\x01\0\0\0", 10)); }, "out.obj"},
  {"grammar_nul_byte", "generate", {"nul.grm", "-o", "out.obj"}, kInput,
   "nul.grm:1:10: error: ", "unexpected character byte 0x00",
   {}, [](const fs::path& d) { binary_file(d / "nul.grm", std::string("p --> spl\0it\n", 13)); }},
  {"grammar_string_not_utf8", "generate", {"latin1.grm", "-o", "out.obj"}, kInput,
   "latin1.grm:1:9: error: ", "this string is not UTF-8 text",
   {}, [](const fs::path& d) { binary_file(d / "latin1.grm", "p --> I(\"fen\xeatre\")\n"); }},
  {"grammar_label_with_tab", "generate", {"label_with_tab.grm", "-o", "out.obj"}, kInput,
   "label_with_tab.grm:1:39: error: ", "the primitive name 'a\\tb' cannot be a label: it holds a tab",
   {"grammar/label_with_tab.grm"}},
  {"grammar_label_blank", "generate", {"label_blank.grm", "-o", "out.obj"}, kInput,
   "label_blank.grm:1:39: error: ", "the primitive name ' ' cannot be a label: it starts with white space",
   {"grammar/label_blank.grm"}},
  {"grammar_label_with_nul", "generate", {"nul_label.grm", "-o", "out.obj"}, kInput,
   "nul_label.grm:1:9: error: ", "the primitive name 'a\\x00b' cannot be a label: it holds a NUL byte",
   {}, [](const fs::path& d) { binary_file(d / "nul_label.grm", std::string("p --> I(\"a\0b\")\n", 15)); }},
  {"grammar_directive_without_name", "generate", {"directive_without_name.grm", "-o", "out.obj"}, kInput,
   "directive_without_name.grm:1:1: error: ", "'@' must start a directive", {"grammar/directive_without_name.grm"}},
  {"grammar_number_too_large", "generate", {"number_too_large.grm", "-o", "out.obj"}, kInput,
   "number_too_large.grm:1:17: error: ", "the number 1e999 is too large", {"grammar/number_too_large.grm"}},
  {"grammar_number_too_small", "generate", {"number_too_small.grm", "-o", "out.obj"}, kInput,
   "number_too_small.grm:1:17: error: ", "the number 1e-400 is too small: nearer to zero than any double",
   {"grammar/number_too_small.grm"}},
  {"grammar_number_without_exponent", "generate", {"number_without_exponent.grm", "-o", "out.obj"}, kInput,
   "number_without_exponent.grm:1:17: error: ", "the number 2e has no digits after its exponent 'e'",
   {"grammar/number_without_exponent.grm"}},
  {"grammar_infinity_as_number", "generate", {"infinity_as_number.grm", "-o", "out.obj"}, kInput,
   "infinity_as_number.grm:1:32: error: ", "'inf' is not a number here: a grammar's numbers are finite",
   {"grammar/infinity_as_number.grm"}},
  // Editors on Windows start UTF-8 files with a byte-order mark.
  {"grammar_byte_order_mark_works", "generate", {"bom.grm", "-o", "out.obj"}, kOk,
   "", "", {}, [](const fs::path& d) {
     write_text(d / "bom.grm", "\xEF\xBB\xBF" + test::read_file(kCorpus / "grammar/ok.grm")); },
   nullptr, 0, {"out.obj"}},
  {"grammar_byte_order_mark_inside", "generate", {"byte_order_mark_inside.grm", "-o", "out.obj"}, kInput,
   "byte_order_mark_inside.grm:1:31: error: ", "unexpected byte-order mark (U+FEFF) after the start of the file",
   {"grammar/byte_order_mark_inside.grm"}},
  {"grammar_number_unreadable", "generate", {"number_unreadable.grm", "-o", "out.obj"}, kInput,
   "number_unreadable.grm:1:17: error: ", "cannot read the number '1.2.3'", {"grammar/number_unreadable.grm"}},
  {"grammar_number_runs_into_name", "generate", {"number_runs_into_name.grm", "-o", "out.obj"}, kInput,
   "number_runs_into_name.grm:1:26: error: ", "a number runs into a name", {"grammar/number_runs_into_name.grm"}},
  {"grammar_string_unclosed", "generate", {"string_unclosed.grm", "-o", "out.obj"}, kInput,
   "string_unclosed.grm:1:13: error: ", "this string has no closing '\"'", {"grammar/string_unclosed.grm"}},
  {"grammar_unexpected_character", "generate", {"unexpected_character.grm", "-o", "out.obj"}, kInput,
   "unexpected_character.grm:1:19: error: ", "unexpected character '$'", {"grammar/unexpected_character.grm"}},
  {"grammar_non_ascii_operator", "generate", {"non_ascii_operator.grm", "-o", "out.obj"}, kInput,
   "non_ascii_operator.grm:1:19: error: ", "unexpected character '≈'", {"grammar/non_ascii_operator.grm"}},
  {"grammar_missing_open_paren", "generate", {"missing_open_paren.grm", "-o", "out.obj"}, kInput,
   "missing_open_paren.grm:1:13: error: ", "expected '(' after split, found 'x'", {"grammar/missing_open_paren.grm"},
   nullptr, "out.obj"},
  {"grammar_missing_open_brace", "generate", {"missing_open_brace.grm", "-o", "out.obj"}, kInput,
   "missing_open_brace.grm:1:16: error: ", "expected '{' to open the body of split", {"grammar/missing_open_brace.grm"}},
  {"grammar_missing_colon", "generate", {"missing_colon.grm", "-o", "out.obj"}, kInput,
   "missing_colon.grm:1:20: error: ", "expected ':' between a split size and its operation", {"grammar/missing_colon.grm"}},
  {"grammar_unclosed_split", "generate", {"unclosed_split.grm", "-o", "out.obj"}, kInput,
   "unclosed_split.grm:2:1: error: ", "expected '}' or '|' after a split part, found 'q'", {"grammar/unclosed_split.grm"}},
  {"grammar_extra_close_brace", "generate", {"extra_close_brace.grm", "-o", "out.obj"}, kInput,
   "extra_close_brace.grm:1:27: error: ", "unexpected '}' after a complete line", {"grammar/extra_close_brace.grm"}},
  {"grammar_two_operations_on_a_line", "generate", {"two_operations_on_a_line.grm", "-o", "out.obj"}, kInput,
   "two_operations_on_a_line.grm:1:11: error: ", "unexpected 'nil' after a complete line",
   {"grammar/two_operations_on_a_line.grm"}},
  {"grammar_missing_arrow", "generate", {"missing_arrow.grm", "-o", "out.obj"}, kInput,
   "missing_arrow.grm:1:3: error: ", "expected '-->' in the rule for 'p'", {"grammar/missing_arrow.grm"}},
  {"grammar_missing_arrow_after_condition", "generate", {"missing_arrow_after_condition.grm", "-o", "out.obj"}, kInput,
   "missing_arrow_after_condition.grm:1:14: error: ", "expected '-->' in the rule for 'p'",
   {"grammar/missing_arrow_after_condition.grm"}},
  {"grammar_empty_split_part", "generate", {"empty_split_part.grm", "-o", "out.obj"}, kInput,
   "empty_split_part.grm:1:28: error: ", "expected a value, found '}'", {"grammar/empty_split_part.grm"}},
  {"grammar_missing_operation", "generate", {"missing_operation.grm", "-o", "out.obj"}, kInput,
   "missing_operation.grm:1:22: error: ", "expected an operation, found ':'", {"grammar/missing_operation.grm"}},
  {"grammar_string_as_operation", "generate", {"string_as_operation.grm", "-o", "out.obj"}, kInput,
   "string_as_operation.grm:1:7: error: ", "expected an operation, found a string", {"grammar/string_as_operation.grm"}},
  {"grammar_missing_priority", "generate", {"missing_priority.grm", "-o", "out.obj"}, kInput,
   "missing_priority.grm:1:16: error: ", "expected a value, found the end of the line", {"grammar/missing_priority.grm"}},
  {"grammar_empty_condition", "generate", {"empty_condition.grm", "-o", "out.obj"}, kInput,
   "empty_condition.grm:1:5: error: ", "expected a value, found '-->'", {"grammar/empty_condition.grm"}},
  {"grammar_unclosed_parenthesis", "generate", {"missing_close_paren_in_expression.grm", "-o", "out.obj"}, kInput,
   "missing_close_paren_in_expression.grm:1:24: error: ", "expected ')' to close '(' at 1:17",
   {"grammar/missing_close_paren_in_expression.grm"}},
  {"grammar_unknown_directive", "generate", {"unknown_directive.grm", "-o", "out.obj"}, kInput,
   "unknown_directive.grm:1:1: error: ", "unknown directive '@size'", {"grammar/unknown_directive.grm"}},
  {"grammar_start_without_label", "generate", {"start_without_label.grm", "-o", "out.obj"}, kInput,
   "start_without_label.grm:1:7: error: ", "expected a name after @start", {"grammar/start_without_label.grm"}},
  {"grammar_scope_two_values", "generate", {"scope_two_values.grm", "-o", "out.obj"}, kInput,
   "scope_two_values.grm:1:13: error: ", "expected ',' between the three @scope sizes", {"grammar/scope_two_values.grm"}},
  {"grammar_primitives_unquoted", "generate", {"primitives_unquoted.grm", "-o", "out.obj"}, kInput,
   "primitives_unquoted.grm:1:18: error: ", "unexpected character '.'", {"grammar/primitives_unquoted.grm"}},
  {"grammar_start_unknown_rule", "generate", {"start_unknown_rule.grm", "-o", "out.obj"}, kInput,
   "start_unknown_rule.grm:1:8: error: ", "@start names 'plto', which has no rule", {"grammar/start_unknown_rule.grm"}},
  {"grammar_start_rule_with_parameters", "generate", {"start_rule_with_parameters_directive.grm", "-o", "out.obj"}, kInput,
   "start_rule_with_parameters_directive.grm:1:8: error: ", "the start rule 'wall' takes parameters",
   {"grammar/start_rule_with_parameters_directive.grm"}},
  {"grammar_no_rules", "generate", {"no_rules.grm", "-o", "out.obj"}, kInput,
   "no_rules.grm:1:1: error: ", "the grammar has no rules", {"grammar/no_rules.grm"}},
  {"grammar_empty_file", "generate", {"empty.grm", "-o", "out.obj"}, kInput,
   "empty.grm:1:1: error: ", "the grammar has no rules", {}, [](const fs::path& d) { write_text(d / "empty.grm", ""); }},
  {"grammar_constant_defined_twice", "generate", {"constant_defined_twice.grm", "-o", "out.obj"}, kInput,
   "constant_defined_twice.grm:2:1: error: ", "the constant 'width' is defined twice", {"grammar/constant_defined_twice.grm"}},
  {"grammar_reserved_constant_name", "generate", {"reserved_constant_name.grm", "-o", "out.obj"}, kInput,
   "reserved_constant_name.grm:1:1: error: ", "'x' cannot name a constant", {"grammar/reserved_constant_name.grm"}},
  {"grammar_operation_as_rule_label", "generate", {"operation_as_rule_label.grm", "-o", "out.obj"}, kInput,
   "operation_as_rule_label.grm:1:1: error: ", "'split' is an operation and cannot be a rule label",
   {"grammar/operation_as_rule_label.grm"}},
  {"grammar_parameter_listed_twice", "generate", {"parameter_listed_twice.grm", "-o", "out.obj"}, kInput,
   "parameter_listed_twice.grm:1:9: error: ", "the parameter 'a' is listed twice", {"grammar/parameter_listed_twice.grm"}},
  {"grammar_parameter_not_a_name", "generate", {"parameter_not_a_name.grm", "-o", "out.obj"}, kInput,
   "parameter_not_a_name.grm:1:6: error: ", "expected a name (a parameter name), found the number 1",
   {"grammar/parameter_not_a_name.grm"}},
  {"grammar_parameter_counts_differ", "generate", {"parameter_counts_differ.grm", "-o", "out.obj"}, kInput,
   "parameter_counts_differ.grm:3:1: error: ", "'wall' takes 1 parameters where it was first defined (2:1), here 2",
   {"grammar/parameter_counts_differ.grm"}},
  {"grammar_unknown_rule", "generate", {"unknown_rule.grm", "-o", "out.obj"}, kInput,
   "unknown_rule.grm:1:40: error: ", "unknown rule 'hose'\n  hint: did you mean 'house'?", {"grammar/unknown_rule.grm"}},
  {"grammar_wrong_arity", "generate", {"wrong_arity.grm", "-o", "out.obj"}, kInput,
   "wrong_arity.grm:1:7: error: ", "'wall' takes 1 argument, given 2", {"grammar/wrong_arity.grm"}},
  {"grammar_unknown_name", "generate", {"unknown_name.grm", "-o", "out.obj"}, kInput,
   "unknown_name.grm:1:17: error: ", "unknown name 'widht'", {"grammar/unknown_name.grm"}},
  {"grammar_unknown_name_suggested", "generate", {"unknown_name_suggested.grm", "-o", "out.obj"}, kInput,
   "unknown_name_suggested.grm:2:17: error: ", "unknown name 'widht'\n  hint: did you mean 'width'?",
   {"grammar/unknown_name_suggested.grm"}},
  {"grammar_unknown_function", "generate", {"unknown_function.grm", "-o", "out.obj"}, kInput,
   "unknown_function.grm:1:17: error: ", "unknown function 'flor'\n  hint: did you mean 'floor'?",
   {"grammar/unknown_function.grm"}},
  {"grammar_function_without_arguments", "generate", {"function_without_arguments.grm", "-o", "out.obj"}, kInput,
   "function_without_arguments.grm:1:17: error: ", "the function 'floor' needs its arguments\n  hint: write floor(a)",
   {"grammar/function_without_arguments.grm"}},
  {"grammar_function_arity", "generate", {"function_arity.grm", "-o", "out.obj"}, kInput,
   "function_arity.grm:1:17: error: ", "rand takes 0 or 2 arguments, given 1", {"grammar/function_arity.grm"}},
  {"grammar_too_many_arguments", "generate", {"many.grm", "-o", "out.obj"}, kInput,
   "many.grm:1:17: error: ", "choice is given 70000 arguments, more than 65535",
   {}, [](const fs::path& d) {
     std::string text = "p --> split(x){ choice(1";
     for (int i = 1; i < 70000; ++i) text += ", 1";
     write_text(d / "many.grm", text + ") : nil }\n"); }},
  {"grammar_too_many_parameters", "generate", {"many.grm", "-o", "out.obj"}, kInput,
   "many.grm:2:", "'r' has more than 65535 parameters",
   {}, [](const fs::path& d) { many_parameters(d / "many.grm", 70000); }},
  // Not a timing test: a walk over the arguments per argument took some
  // ten seconds per min(), here derived 100 times, and a "did you mean"
  // over two names of 2,000,000 characters the product of their lengths.
  {"grammar_min_of_many_arguments_works", "generate", {"min.grm", "-o", "out.obj"}, kOk,
   "", "", {}, [](const fs::path& d) { min_of_many_arguments(d / "min.grm"); }, nullptr, 0, {"out.obj"}},
  {"grammar_unknown_rule_very_long_name", "generate", {"long.grm", "-o", "out.obj"}, kInput,
   "long.grm:1:", "unknown rule '" + std::string(40, 'a') + "... (2000000 characters)'",
   {}, [](const fs::path& d) {
     write_text(d / "long.grm", std::string(2000000, 'a') + " --> " + std::string(1999999, 'a') + "b\n"); }},
  {"grammar_nesting_too_deep", "generate", {"deep.grm", "-o", "out.obj"}, kInput,
   "deep.grm:1:", "nested more than 256 deep",
   {}, [](const fs::path& d) {
     std::string text = "p --> ";
     for (int i = 0; i < 100000; ++i) text += "split(x){ ~1 : ";
     write_text(d / "deep.grm", text + "nil\n"); }},
  {"grammar_parentheses_too_deep", "generate", {"parens.grm", "-o", "out.obj"}, kInput,
   "parens.grm:1:", "nested more than 256 deep",
   {}, [](const fs::path& d) {
     write_text(d / "parens.grm", "p --> split(x){ " + std::string(100000, '(') + "1" + std::string(100000, ')') + " : nil }\n"); }},
  {"grammar_expression_chain_too_deep", "generate", {"chain.grm", "-o", "out.obj"}, kInput,
   "chain.grm:1:", "an expression nested more than 256 deep",
   {}, [](const fs::path& d) {
     std::string text = "p --> split(x){ 1";
     for (int i = 0; i < 100000; ++i) text += " + 1";
     write_text(d / "chain.grm", text + " : nil }\n"); }},
  {"grammar_axis_literal_invalid", "generate", {"axis_literal_invalid.grm", "-o", "out.obj"}, kInput,
   "axis_literal_invalid.grm:1:13: error: ", "the axis of split is 5", {"grammar/axis_literal_invalid.grm"}},
  {"grammar_repeat_relative_tile", "generate", {"repeat_relative_tile.grm", "-o", "out.obj"}, kInput,
   "repeat_relative_tile.grm:1:19: error: ", "a repeat's tile size is absolute", {"grammar/repeat_relative_tile.grm"}},
  {"grammar_primitive_without_name", "generate", {"primitive_without_name.grm", "-o", "out.obj"}, kInput,
   "primitive_without_name.grm:1:9: error: ", "expected a primitive name in I(...)", {"grammar/primitive_without_name.grm"}},
  {"grammar_comp_not_f", "generate", {"comp_not_f.grm", "-o", "out.obj"}, kInput,
   "comp_not_f.grm:1:12: error: ", "comp splits into faces", {"grammar/comp_not_f.grm"}},
  {"grammar_comp_unknown_face", "generate", {"comp_unknown_face.grm", "-o", "out.obj"}, kInput,
   "comp_unknown_face.grm:1:16: error: ", "'middle' is not a face", {"grammar/comp_unknown_face.grm"}},
  {"grammar_comp_face_twice", "generate", {"comp_face_twice.grm", "-o", "out.obj"}, kInput,
   "comp_face_twice.grm:1:28: error: ", "the face 'top' is listed twice", {"grammar/comp_face_twice.grm"}},
  {"grammar_colour_bad_hex", "generate", {"colour_bad_hex.grm", "-o", "out.obj"}, kInput,
   "colour_bad_hex.grm:1:14: error: ", "'#12345' is not a colour", {"grammar/colour_bad_hex.grm"}},
  {"grammar_colour_unknown_name", "generate", {"colour_unknown_name.grm", "-o", "out.obj"}, kInput,
   "colour_unknown_name.grm:1:14: error: ", "unknown colour 'reed'\n  hint: did you mean 'red'?",
   {"grammar/colour_unknown_name.grm"}},
  {"grammar_translate_two_values", "generate", {"translate_two_values.grm", "-o", "out.obj"}, kInput,
   "translate_two_values.grm:1:13: error: ", "expected ',' between the three values of T",
   {"grammar/translate_two_values.grm"}},
  {"grammar_rotate_without_angle", "generate", {"rotate_without_angle.grm", "-o", "out.obj"}, kInput,
   "rotate_without_angle.grm:1:10: error: ", "between the axis and the angle of R", {"grammar/rotate_without_angle.grm"}},
  // Type errors found while reading: an axis literal where a number belongs.
  {"grammar_axis_in_arithmetic", "generate", {"axis_in_arithmetic.grm", "-o", "out.obj"}, kInput,
   "axis_in_arithmetic.grm:1:17: error: ", "'+' expects numbers, found the axis x", {"grammar/axis_in_arithmetic.grm"}},
  {"grammar_minus_axis", "generate", {"minus_axis.grm", "-o", "out.obj"}, kInput,
   "minus_axis.grm:1:18: error: ", "'-' expects a number, found an axis", {"grammar/minus_axis.grm"}},
  {"grammar_tilde_not_first", "generate", {"tilde_not_first.grm", "-o", "out.obj"}, kInput,
   "tilde_not_first.grm:1:21: error: ", "'~' marks a relative size and must come first", {"grammar/tilde_not_first.grm"}},
  {"grammar_function_axis_argument", "generate", {"function_axis_argument.grm", "-o", "out.obj"}, kInput,
   "function_axis_argument.grm:1:21: error: ", "abs expects numbers, found an axis", {"grammar/function_axis_argument.grm"}},

  // ---- grammars: deriving (generate) ----
  {"derive_axis_where_number_expected", "generate", {"axis_where_number_expected.grm", "-o", "out.obj"}, kInput,
   "axis_where_number_expected.grm:3:23: error: ", "expected a number here, found axis y\n  rule chain: p > q > wall(axis y)",
   {"grammar/axis_where_number_expected.grm"}, nullptr, "out.obj"},
  {"derive_number_where_axis_expected", "generate", {"number_where_axis_expected.grm", "-o", "out.obj"}, kInput,
   "number_where_axis_expected.grm:2:19: error: ", "the axis of split must be an axis, found 5",
   {"grammar/number_where_axis_expected.grm"}},
  {"derive_colour_axis_component", "generate", {"colour_axis_component.grm", "-o", "out.obj"}, kInput,
   "colour_axis_component.grm:1:14: error: ", "a colour component must be a number, found axis x",
   {"grammar/colour_axis_component.grm"}},
  {"derive_division_by_zero", "generate", {"division_by_zero.grm", "-o", "out.obj"}, kInput,
   "division_by_zero.grm:2:19: error: ", "division by zero (1 / 0)", {"grammar/division_by_zero.grm"}},
  {"derive_remainder_by_zero", "generate", {"remainder_by_zero.grm", "-o", "out.obj"}, kInput,
   "remainder_by_zero.grm:2:25: error: ", "remainder by zero (5 % 0)\n  rule chain: p > wall(0)",
   {"grammar/remainder_by_zero.grm"}},
  {"derive_sqrt_negative", "generate", {"sqrt_negative.grm", "-o", "out.obj"}, kInput,
   "sqrt_negative.grm:1:17: error: ", "sqrt of a negative number (-4)", {"grammar/sqrt_negative.grm"}},
  {"derive_constant_division_by_zero", "generate", {"constant_division_by_zero.grm", "-o", "out.obj"}, kInput,
   "constant_division_by_zero.grm:1:11: error: ", "division by zero (1 / 0) (in the constant 'ratio')",
   {"grammar/constant_division_by_zero.grm"}},
  {"derive_nan_size", "generate", {"nan_size.grm", "-o", "out.obj"}, kInput,
   "nan_size.grm:2:21: error: ", "a split size is NaN, not a finite number", {"grammar/nan_size.grm"}},
  {"derive_inf_offset", "generate", {"inf_offset.grm", "-o", "out.obj"}, kInput,
   "inf_offset.grm:1:15: error: ", "a T offset is inf, not a finite number", {"grammar/inf_offset.grm"}},
  // Numbers each finite whose results are not (sums, products, moves) or
  // do not fit the outputs (32-bit floats end at 3.4e38): said where.
  {"derive_translate_twice_1e308", "generate", {"translate_twice_1e308.grm", "-o", "out.obj"}, kInput,
   "translate_twice_1e308.grm:1:7: error: ", "T moves the scope beyond 1e+38 m from the origin",
   {"grammar/translate_twice_1e308.grm"}},
  {"derive_scale_1e39_instanced", "generate", {"scale_1e39.grm", "--instancing", "-o", "out.glb"}, kInput,
   "scale_1e39.grm:1:7: error: ", "S makes the scope reach beyond 1e+38 m from the origin", {"grammar/scale_1e39.grm"}},
  {"derive_split_sizes_overflow", "generate", {"split_sizes_overflow.grm", "-o", "out.obj"}, kInput,
   "split_sizes_overflow.grm:1:7: error: ", "the sizes of this split add up to more than 1.8e+308",
   {"grammar/split_sizes_overflow.grm"}},
  {"derive_split_shares_overflow", "generate", {"split_shares_overflow.grm", "-o", "out.glb"}, kInput,
   "split_shares_overflow.grm:1:7: error: ", "the sizes of this split add up to more than 1.8e+308",
   {"grammar/split_shares_overflow.grm"}},
  {"derive_priorities_overflow", "generate", {"priorities_overflow.grm", "-o", "out.obj"}, kInput,
   "priorities_overflow.grm:1:1: error: ", "the priorities of the rules of 'p' add up to more than 1.8e+308",
   {"grammar/priorities_overflow.grm"}},
  {"derive_scope_1e308_instanced", "generate", {"scope_1e308.grm", "--instancing", "-o", "out.glb"}, kInput,
   "scope_1e308.grm:1:8: error: ", "the @scope reaches beyond 1e+38 m from the origin", {"grammar/scope_1e308.grm"}},
  {"derive_negative_size", "generate", {"negative_size.grm", "-o", "out.obj"}, kInput,
   "negative_size.grm:1:17: error: ", "a split size is negative (-1)", {"grammar/negative_size.grm"}},
  {"derive_negative_scale", "generate", {"negative_scale.grm", "-o", "out.obj"}, kInput,
   "negative_scale.grm:1:9: error: ", "an S size is negative (-1)", {"grammar/negative_scale.grm"}},
  {"derive_negative_scope", "generate", {"negative_scope.grm", "-o", "out.obj"}, kInput,
   "negative_scope.grm:1:12: error: ", "@scope size -8 is negative", {"grammar/negative_scope.grm"}},
  {"derive_repeat_zero_tile", "generate", {"repeat_zero_tile.grm", "-o", "out.obj"}, kInput,
   "repeat_zero_tile.grm:1:17: error: ", "the tile size of repeat is 0", {"grammar/repeat_zero_tile.grm"}},
  {"derive_randint_empty_range", "generate", {"randint_empty_range.grm", "-o", "out.obj"}, kInput,
   "randint_empty_range.grm:1:17: error: ", "has no whole number in range", {"grammar/randint_empty_range.grm"}},
  {"derive_normal_negative_sigma", "generate", {"normal_negative_sigma.grm", "-o", "out.obj"}, kInput,
   "normal_negative_sigma.grm:1:17: error: ", "normal() needs sigma >= 0", {"grammar/normal_negative_sigma.grm"}},
  {"derive_tnormal_bounds_swapped", "generate", {"tnormal_bounds_swapped.grm", "-o", "out.obj"}, kInput,
   "tnormal_bounds_swapped.grm:1:17: error: ", "tnormal() needs lo <= hi", {"grammar/tnormal_bounds_swapped.grm"}},
  {"derive_start_rule_with_parameters", "generate", {"default_start_rule_with_parameters.grm", "-o", "out.obj"}, kInput,
   "default_start_rule_with_parameters.grm:1:1: error: ", "the start rule 'wall' takes parameters",
   {"grammar/default_start_rule_with_parameters.grm"}},
  {"derive_unknown_primitive_strict", "generate", {"unknown_primitive.grm", "--strict", "-o", "out.obj"}, kInput,
   "unknown_primitive.grm:1:22: error: ", "unknown primitive 'tower'", {"grammar/unknown_primitive.grm"}, nullptr, "out.obj"},
  {"derive_unknown_primitive_warns", "generate", {"unknown_primitive.grm", "-o", "out.obj"}, kOk,
   "", "", {"grammar/unknown_primitive.grm"}, nullptr, nullptr, 0, {"out.obj"}},
  {"derive_no_rule_applies_strict", "generate", {"no_rule_applies.grm", "--strict", "-o", "out.obj"}, kInput,
   "no_rule_applies.grm:2:1: error: ", "no rule of 'q' applies", {"grammar/no_rule_applies.grm"}},
  {"derive_primitives_file_missing", "generate", {"with_primitives_file.grm", "-o", "out.obj"}, kIo,
   "prims.obj: error: ", "no such file or folder", {"grammar/with_primitives_file.grm"}},
  {"derive_primitives_file_is_a_fifo", "generate", {"with_primitives_file.grm", "-o", "out.obj"}, kIo,
   "prims.obj: error: ", "is a FIFO (named pipe), not a regular file", {"grammar/with_primitives_file.grm"},
   [](const fs::path& d) { fifo(d / "prims.obj"); }},
  {"generate_primitives_is_a_fifo", "generate", {"ok.grm", "--primitives", "pipe.obj", "-o", "out.obj"}, kIo,
   "pipe.obj: error: ", "is a FIFO (named pipe), not a regular file", kValidGrammar,
   [](const fs::path& d) { fifo(d / "pipe.obj"); }},
  // A grammar's @primitives is the grammar's choice: its folder or below only.
  {"derive_primitives_absolute_path", "generate", {"primitives_absolute_path.grm", "-o", "out.obj"}, kInput,
   "primitives_absolute_path.grm:1:13: error: ",
   "@primitives names '/etc/passwd', which is outside the grammar's folder", {"grammar/primitives_absolute_path.grm"},
   nullptr, nullptr, 0, {}, "root:"},
  {"derive_primitives_parent_folder", "generate", {"g/primitives_parent_folder.grm", "-o", "out.obj"}, kInput,
   "g/primitives_parent_folder.grm:1:13: error: ",
   "@primitives names '../secret.obj', which is outside the grammar's folder\n  hint: a grammar may name primitives "
   "files in its own folder or below it only", {"grammar/primitives_parent_folder.grm"},
   grammar_in_a_folder_beside_a_secret},
  {"derive_primitives_parent_folder_allowed", "generate",
   {"g/primitives_parent_folder.grm", "--allow-outside-files", "-o", "out.obj"}, kOk, "", "",
   {"grammar/primitives_parent_folder.grm"}, grammar_in_a_folder_beside_a_secret, nullptr, 0, {"out.obj"}},
  {"derive_primitives_link_out_of_the_folder", "generate", {"g/with_primitives_file.grm", "-o", "out.obj"}, kInput,
   "g/with_primitives_file.grm:1:13: error: ", "@primitives names 'prims.obj', which is outside the grammar's folder",
   {"grammar/with_primitives_file.grm"}, [](const fs::path& d) {
     grammar_in_a_folder_beside_a_secret(d);
     fs::create_symlink("../secret.obj", d / "g/prims.obj");
   }},
  {"derive_primitives_folder_holds_a_link_out", "generate", {"g/primitives_folder.grm", "-o", "out.obj"}, kInput,
   "g/prims/tower.obj: error: ", "is a link that leads outside the folder of the grammar that names it",
   {"grammar/primitives_folder.grm"}, [](const fs::path& d) {
     grammar_in_a_folder_beside_a_secret(d);
     fs::create_directory(d / "g/prims");
     fs::create_symlink("../../secret.obj", d / "g/prims/tower.obj");
   }},
  // A NUL ends the path where the system reads it: "prims.obj\0.secret"
  // would read prims.obj, even where outside files are allowed.
  {"derive_primitives_name_holds_a_nul", "generate", {"nul.grm", "--allow-outside-files", "-o", "out.obj"}, kInput,
   "nul.grm:1:13: error: ", "@primitives names 'prims.obj\\x00.secret', which holds a NUL byte", {},
   [](const fs::path& d) {
     write_text(d / "nul.grm", std::string("@primitives \"prims.obj") + '\0' + ".secret\"\np --> I(tower)\n");
     fs::copy_file(kCorpus / "obj/two_parts.obj", d / "prims.obj");
   }},
  {"derive_primitives_not_obj_is_not_quoted", "generate", {"primitives_not_obj.grm", "-o", "out.obj"}, kInput,
   "notes.txt:1:1: error: ", "this line is not an OBJ statement", {"grammar/primitives_not_obj.grm"},
   [](const fs::path& d) { write_text(d / "notes.txt", "hunter2 is the password\n"); }, nullptr, 0, {}, "hunter2"},
  // A link that leads to itself is refused as a file that cannot be read.
  {"derive_primitives_symlink_loop", "generate", {"primitives_folder.grm", "-o", "out.obj"}, kIo,
   "prims/loop.obj: error: ", "cannot read: Too many levels of symbolic links", {"grammar/primitives_folder.grm"},
   link_loop_in_prims},
  {"generate_primitives_symlink_loop", "generate", {"ok.grm", "--primitives", "prims", "-o", "out.obj"}, kIo,
   "prims/loop.obj: error: ", "cannot read: Too many levels of symbolic links", kValidGrammar, link_loop_in_prims},
  {"infer_primitives_symlink_loop", "infer", {"two_parts.obj", "--primitives", "prims", "-o", "style.grm"}, kIo,
   "prims/loop.obj: error: ", "cannot read: Too many levels of symbolic links", kValidObj, link_loop_in_prims},
  {"infer_example_folder_symlink_loop", "infer", {"examples", "-o", "style.grm"}, kIo,
   "examples/loop.obj: error: ", "cannot read: Too many levels of symbolic links", {}, [](const fs::path& d) {
     fs::create_directory(d / "examples");
     fs::copy_file(kCorpus / "obj/two_parts.obj", d / "examples/two_parts.obj");
     fs::create_symlink("loop.obj", d / "examples/loop.obj");
   }},
  // Limits: each names the flag that raises it.
  {"limit_repeatN_1e12", "generate", {"repeatN_1e12.grm", "-o", "out.obj"}, kLimit,
   "repeatN_1e12.grm:1:18: error: ", "repeatN asks for 1e+12 tiles", {"grammar/repeatN_1e12.grm"}, nullptr, "out.obj"},
  {"limit_repeat_tiny_tile", "generate", {"repeat_tiny_tile.grm", "-o", "out.obj"}, kLimit,
   "repeat_tiny_tile.grm:1:7: error: ", "--max-operations", {"grammar/repeat_tiny_tile.grm"}},
  {"limit_infinite_recursion", "generate", {"infinite_recursion.grm", "-o", "out.obj"}, kLimit,
   "infinite_recursion.grm:2:7: error: ", "rule calls nested deeper than 1000", {"grammar/infinite_recursion.grm"}},
  {"limit_recursion_deeper_than_the_stack", "generate",
   {"recursion_through_transforms.grm", "--max-depth", "1000000", "-j", "1", "-o", "out.obj"}, kLimit,
   "recursion_through_transforms.grm:2:58: error: ", "deep fill this thread's", {"grammar/recursion_through_transforms.grm"}},
  {"limit_random_never_terminates", "generate", {"random_never_terminates.grm", "--seed", "4", "-o", "out.obj"}, kLimit,
   "random_never_terminates.grm:", "--max-depth", {"grammar/random_never_terminates.grm"}},
  {"limit_terminals", "generate", {"terminal_explosion.grm", "--max-terminals", "1000", "-o", "out.obj"}, kLimit,
   "terminal_explosion.grm:1:61: error: ", "more than 1000 terminals in one derivation",
   {"grammar/terminal_explosion.grm"}},
  {"limit_terminals_default_bounds_memory", "generate", {"terminal_explosion.grm", "-o", "out.obj"}, kLimit,
   "terminal_explosion.grm:1:61: error: ", "more than 1000000 terminals", {"grammar/terminal_explosion.grm"}, nullptr,
   nullptr, 600},
  // Out of memory (the address space capped): the message names the input.
  {"limit_memory_deriving_names_the_grammar", "generate",
   {"terminal_explosion.grm", "--max-terminals", "100000000000", "-j", "1", "-o", "out.obj"}, kLimit,
   "terminal_explosion.grm: error: ", "out of memory deriving 1 building", {"grammar/terminal_explosion.grm"},
   nullptr, "out.obj", 0, {}, {}, 300},
  {"limit_memory_reading_names_the_grammar", "generate", {"many.grm", "-o", "out.obj"}, kLimit,
   "many.grm: error: ", "out of memory while reading this grammar",
   {}, [](const fs::path& d) { many_alternatives(d / "many.grm", 1000000); }, nullptr, 0, {}, {}, 100},
  // 2.25 MB of alternatives took 196 MB (tokens held whole, a heap block
  // per number, Choose options copied); now 54 MB, and 128 MB under ASan.
  {"grammar_many_alternatives_memory", "generate", {"many.grm", "-o", "out.obj"}, kOk,
   "", "", {}, [](const fs::path& d) { many_alternatives(d / "many.grm", 150000); }, nullptr, 160, {"out.obj"}},
  {"limit_operations", "generate", {"ok.grm", "--max-operations", "2", "-o", "out.obj"}, kLimit,
   "ok.grm:1:", "more than 2 operations in one derivation", kValidGrammar},
  {"limit_repeat_subnormal_tile", "generate", {"repeat_subnormal_tile.grm", "-o", "out.obj"}, kLimit,
   "repeat_subnormal_tile.grm:1:7: error: ", "repeat would make inf tiles", {"grammar/repeat_subnormal_tile.grm"}},

  // ---- grammars checked against an example: the same refusals as generate's, at the same place ----
  {"check_repeat_zero_tile", "check", {"repeat_zero_tile.grm", "two_parts.obj"}, kInput,
   "repeat_zero_tile.grm:1:17: error: ", "the tile size of repeat is 0", {"grammar/repeat_zero_tile.grm", "obj/two_parts.obj"}},
  {"check_repeat_tiny_tile", "check", {"repeat_tiny_tile.grm", "two_parts.obj"}, kLimit,
   "repeat_tiny_tile.grm:1:7: error: ", "more than check's limit of 10000000 matching steps",
   {"grammar/repeat_tiny_tile.grm", "obj/two_parts.obj"}},
  {"check_repeat_200M_tiles_bounds_memory", "check", {"repeat_200M_tiles.grm", "two_parts.obj"}, kLimit,
   "repeat_200M_tiles.grm:1:7: error: ", "repeat would make 2", {"grammar/repeat_200M_tiles.grm", "obj/two_parts.obj"},
   nullptr, nullptr, 100},
  {"check_repeat_count_overflows", "check", {"repeat_count_overflows.grm", "two_parts.obj"}, kLimit,
   "repeat_count_overflows.grm:1:7: error: ", "repeat would make 1.999999998e+19 tiles",
   {"grammar/repeat_count_overflows.grm", "obj/two_parts.obj"}},
  {"check_repeat_subnormal_tile", "check", {"repeat_subnormal_tile.grm", "two_parts.obj"}, kLimit,
   "repeat_subnormal_tile.grm:1:7: error: ", "repeat would make inf tiles",
   {"grammar/repeat_subnormal_tile.grm", "obj/two_parts.obj"}},
  {"check_repeatN_1e12", "check", {"repeatN_1e12.grm", "two_parts.obj"}, kLimit,
   "repeatN_1e12.grm:1:18: error: ", "repeatN asks for 1e+12 tiles", {"grammar/repeatN_1e12.grm", "obj/two_parts.obj"}},
  {"check_repeatN_1e19_bounds_memory", "check", {"repeatN_1e19.grm", "two_parts.obj"}, kLimit,
   "repeatN_1e19.grm:1:18: error: ", "repeatN asks for 1e+19 tiles", {"grammar/repeatN_1e19.grm", "obj/two_parts.obj"},
   nullptr, nullptr, 100},

  // ---- command lines ----
  {"generate_unknown_option", "generate", {"ok.grm", "--sede", "3"}, kUsage,
   "generate: error: ", "unknown option '--sede'\n  hint: did you mean '--seed'?", kValidGrammar},
  {"generate_missing_value", "generate", {"ok.grm", "-n"}, kUsage,
   "generate: error: ", "--count needs 1 value (COUNT)", kValidGrammar},
  {"generate_value_not_a_number", "generate", {"ok.grm", "-n", "many"}, kUsage,
   "generate: error: ", "--count expects a whole number, got 'many'", kValidGrammar},
  {"generate_value_out_of_range", "generate", {"ok.grm", "--max-depth", "0"}, kUsage,
   "generate: error: ", "--max-depth must be between 1 and 1000000, got 0", kValidGrammar},
  {"generate_value_to_a_flag", "generate", {"ok.grm", "--strict=yes"}, kUsage,
   "generate: error: ", "--strict takes 0 values", kValidGrammar},
  // An empty path names no file: said as such, before any work.
  {"generate_output_empty", "generate", {"ok.grm", "-o", ""}, kUsage,
   "generate: error: ", "--output is given an empty value", kValidGrammar},
  {"generate_primitives_empty", "generate", {"ok.grm", "--primitives", "", "-o", "out.obj"}, kUsage,
   "generate: error: ", "--primitives is given an empty value", kValidGrammar},
  {"generate_grammar_empty", "generate", {"", "-o", "out.obj"}, kUsage,
   "generate: error: ", "an empty argument names no file"},
  {"generate_no_grammar", "generate", {}, kUsage, "generate: error: ", "no grammar file given"},
  {"generate_unknown_start", "generate", {"ok.grm", "--start", "pp", "-o", "out.obj"}, kUsage,
   "generate: error: ", "--start names 'pp'", kValidGrammar},
  {"generate_unwritable_output", "generate", {"ok.grm", "-o", "file/out.obj"}, kIo,
   "file/out.obj: error: ", "cannot write here: file is not an existing folder", kValidGrammar,
   [](const fs::path& d) { write_text(d / "file", "a file, not a folder\n"); }},
  {"generate_output_is_a_folder", "generate", {"ok.grm", "-o", "out.obj"}, kIo,
   "out.obj: error: ", "it is an existing folder", kValidGrammar,
   [](const fs::path& d) { fs::create_directory(d / "out.obj"); }},
  {"generate_output_folder_is_a_file", "generate", {"ok.grm", "-o", "buildings"}, kIo,
   "buildings: error: ", "cannot write the buildings into this folder: it is a file", kValidGrammar, nullptr, "buildings"},
  {"generate_output_is_the_grammar", "generate", {"ok.grm", "-o", "./ok.grm"}, kUsage,
   "generate: error: ", "the output ./ok.grm is the grammar file itself", kValidGrammar},
  {"generate_output_is_the_primitives", "generate", {"ok.grm", "--primitives", "prims.obj", "-o", "prims.obj"}, kUsage,
   "generate: error: ", "the output prims.obj is a primitives file itself",
   {"grammar/ok.grm"}, [](const fs::path& d) { fs::copy_file(kCorpus / "obj/two_parts.obj", d / "prims.obj"); }},
  {"generate_output_is_the_grammars_primitives", "generate", {"with_primitives_file.grm", "-o", "prims.obj"}, kUsage,
   "generate: error: ", "the output prims.obj is a primitives file itself",
   {"grammar/with_primitives_file.grm"}, [](const fs::path& d) { fs::copy_file(kCorpus / "obj/two_parts.obj", d / "prims.obj"); }},

  // A run's outputs are replaced together or not at all, and none of them
  // may be an input: not the grammar, not through the .mtl an .obj brings.
  {"generate_obj_fails_after_its_mtl", "generate", {"ok.grm", "-o", "out.obj"}, kIo,
   "out.obj: error: ", "cannot write", kValidGrammar,
   [](const fs::path& d) { earlier_outputs(d, {"out.obj", "out.mtl"}); }, nullptr, 0, {}, {}, 0, 1000},
  {"generate_mtl_is_the_grammar", "generate", {"style.mtl", "-o", "style.obj"}, kUsage,
   "generate: error: ", "the output style.mtl is the grammar file itself",
   {}, [](const fs::path& d) { fs::copy_file(kCorpus / "grammar/ok.grm", d / "style.mtl"); }},
  {"generate_folder_mtl_is_the_grammar", "generate", {"out/variant_001.mtl", "-n", "3", "-o", "out/"}, kUsage,
   "generate: error: ", "the output out/variant_001.mtl is the grammar file itself",
   {}, [](const fs::path& d) {
     fs::create_directory(d / "out");
     fs::copy_file(kCorpus / "grammar/ok.grm", d / "out/variant_001.mtl"); }},
  {"generate_folder_fails_at_the_second_variant", "generate", {"ok.grm", "-n", "3", "-o", "out/"}, kIo,
   "out/variant_001.obj: error: ", "it is an existing folder", kValidGrammar,
   [](const fs::path& d) {
     earlier_outputs(d, {"out/variant_000.obj", "out/variant_000.mtl", "out/variant_002.obj", "out/variant_002.mtl"});
     fs::create_directory(d / "out/variant_001.obj"); }},
  // Variant 0 has one tile (443 bytes), variant 1 seven (2946 bytes).
  {"generate_folder_fails_part_way", "generate", {"rows.grm", "-n", "3", "-o", "out/"}, kIo,
   "out/variant_001.obj: error: ", "cannot write", {},
   [](const fs::path& d) {
     write_text(d / "rows.grm", "p --> repeatN(x, randint(1, 12)){ I(rect) }\n");
     earlier_outputs(d, {"out/variant_000.obj", "out/variant_000.mtl", "out/variant_001.obj", "out/variant_001.mtl"}); },
   nullptr, 0, {}, {}, 0, 2000},
  {"generate_output_folder_holds_the_primitives", "generate",
   {"ok.grm", "--primitives", "out/variant_000.obj", "-o", "out/"}, kUsage,
   "generate: error: ", "the output out/variant_000.obj is a primitives file itself", kValidGrammar,
   [](const fs::path& d) {
     fs::create_directory(d / "out");
     fs::copy_file(kCorpus / "obj/two_parts.obj", d / "out/variant_000.obj"); }},

  // Every file a run reads is an input, named on the command line or not:
  // a glTF's buffer, a mesh of a primitives folder (the run fails at the
  // first output that is one, before anything is renamed).
  {"generate_output_is_in_the_primitives_folder", "generate", {"ok.grm", "--primitives", "p", "-o", "p/x.obj"}, kUsage,
   "p/x.obj: error: ", "this output is a file the run has read", kValidGrammar,
   [](const fs::path& d) { primitives_folder(d, "x.obj"); }},
  {"generate_output_folder_is_the_primitives_folder", "generate", {"ok.grm", "--primitives", "p", "-o", "p/"}, kUsage,
   "p/variant_000.obj: error: ", "this output is a file the run has read", kValidGrammar,
   [](const fs::path& d) { primitives_folder(d, "variant_000.obj"); }},

  {"infer_unknown_option", "infer", {"two_parts.obj", "-o", "style.grm", "--tolerence", "1"}, kUsage,
   "infer: error: ", "unknown option '--tolerence'\n  hint: did you mean '--tolerance'?", kValidObj},
  {"infer_missing_value", "infer", {"two_parts.obj", "-o"}, kUsage,
   "infer: error: ", "--output needs 1 value (STYLE.grm)", kValidObj},
  {"infer_value_not_a_number", "infer", {"two_parts.obj", "-o", "style.grm", "--tolerance", "fine"}, kUsage,
   "infer: error: ", "--tolerance expects a number, got 'fine'", kValidObj},
  {"infer_tolerance_not_positive", "infer", {"two_parts.obj", "-o", "style.grm", "--tolerance", "-1"}, kUsage,
   "infer: error: ", "--tolerance must be > 0", kValidObj},
  {"infer_up_unknown", "infer", {"two_parts.obj", "-o", "style.grm", "--up", "x"}, kUsage,
   "infer: error: ", "unknown --up 'x'\n  hint: give y or z", kValidObj},
  {"infer_max_parts_zero", "infer", {"two_parts.obj", "-o", "style.grm", "--max-parts", "0"}, kUsage,
   "infer: error: ", "--max-parts must be between 1 and", kValidObj},
  {"infer_no_output", "infer", {"two_parts.obj"}, kUsage, "infer: error: ", "no output grammar given", kValidObj},
  {"infer_output_empty", "infer", {"two_parts.obj", "-o", ""}, kUsage,
   "infer: error: ", "--output is given an empty value", kValidObj},
  {"infer_primitives_out_empty", "infer", {"two_parts.obj", "-o", "style.grm", "--primitives-out=", }, kUsage,
   "infer: error: ", "--primitives-out is given an empty value", kValidObj},
  {"infer_example_empty", "infer", {"two_parts.obj", "", "-o", "style.grm"}, kUsage,
   "infer: error: ", "an empty argument names no file", kValidObj},
  {"infer_no_examples", "infer", {"-o", "style.grm"}, kUsage, "infer: error: ", "no examples given"},
  {"infer_start_not_a_label", "infer", {"two_parts.obj", "-o", "style.grm", "--start", "1st"}, kUsage,
   "infer: error: ", "--start '1st' cannot be a rule label", kValidObj},
  {"infer_output_is_an_example", "infer", {"two_parts.obj", "-o", "two_parts.obj"}, kUsage,
   "infer: error: ", "the output two_parts.obj is an example itself", kValidObj},
  {"infer_primitives_out_is_an_example", "infer", {"two_parts.obj", "-o", "style.grm", "--primitives-out", "./two_parts.obj"},
   kUsage, "infer: error: ", "the output ./two_parts.obj is an example itself", kValidObj},
  {"infer_two_outputs_one_file", "infer", {"two_parts.obj", "-o", "style.obj", "--primitives-out", "style.obj"}, kUsage,
   "infer: error: ", "two outputs of this run are the same file: style.obj and style.obj", kValidObj},
  {"infer_grammar_is_the_primitives_materials", "infer", {"two_parts.obj", "-o", "style.mtl", "--primitives-out", "style.obj"},
   kUsage, "infer: error: ", "two outputs of this run are the same file: style.mtl and style.mtl", kValidObj},
  // The meshes are 1620 bytes, the grammar 4267.
  {"infer_grammar_fails_after_the_meshes", "infer", {"examples", "-o", "style.grm"}, kIo,
   "style.grm: error: ", "cannot write", {},
   [](const fs::path& d) {
     fs::create_directory(d / "examples");
     for (const auto& e : fs::directory_iterator(VERN_SOURCE_DIR "/data/examples/better_roofs"))
       if (e.path().extension() == ".obj") fs::copy_file(e.path(), d / "examples" / e.path().filename());
     earlier_outputs(d, {"style.grm", "style.prims.obj", "style.prims.mtl"}); },
   nullptr, 0, {}, {}, 0, 3000},
  {"infer_gltf_buffer_is_the_meshes_materials", "infer", {"model.gltf", "-o", "style.grm"}, kUsage,
   "style.prims.mtl: error: ", "this output is a file the run has read (as ./style.prims.mtl)", {},
   [](const fs::path& d) { buffer_named(d, "style.prims.mtl"); }},
  {"infer_gltf_buffer_is_the_grammar", "infer", {"model.gltf", "-o", "style.grm"}, kUsage,
   "style.grm: error: ", "this output is a file the run has read (as ./style.grm)", {},
   [](const fs::path& d) { buffer_named(d, "style.grm"); }},
  {"infer_primitives_folder_holds_the_meshes", "infer", {"two_parts.obj", "--primitives", "p", "-o", "p/s.grm"}, kUsage,
   "p/s.prims.obj: error: ", "this output is a file the run has read", kValidObj,
   [](const fs::path& d) { primitives_folder(d, "s.prims.obj"); }},
  {"infer_primitives_out_not_obj", "infer", {"two_parts.obj", "-o", "style.grm", "--primitives-out", "style.glb"}, kUsage,
   "infer: error: ", "--primitives-out must name an .obj file", kValidObj},
  {"infer_output_is_a_folder", "infer", {"two_parts.obj", "-o", "style.grm"}, kIo,
   "style.grm: error: ", "it is an existing folder", kValidObj, [](const fs::path& d) { fs::create_directory(d / "style.grm"); }},
  {"infer_unwritable_output", "infer", {"two_parts.obj", "-o", "file/style.grm"}, kIo,
   "file/style.grm: error: ", "cannot write here: file is not an existing folder", kValidObj,
   [](const fs::path& d) { write_text(d / "file", "a file, not a folder\n"); }},
  {"infer_unwritable_primitives_out", "infer", {"two_parts.obj", "-o", "style.grm", "--primitives-out", "meshes/style.obj"},
   kIo, "meshes/style.obj: error: ", "cannot write here: meshes is not an existing folder", kValidObj, nullptr, "style.grm"},

  // evaluate's --keep writes a grammar per grammar evaluated, and
  // --random-styles-write the styles: none may be a grammar evaluated, and
  // no two may be one file.
  {"evaluate_keep_is_the_grammars_folder", "evaluate", {"ok.grm", "-k", "2", "-n", "2", "--keep", "."}, kUsage,
   "evaluate: error: ", "the output ./ok.grm is the grammar file itself", kValidGrammar},
  {"evaluate_two_grammars_kept_in_one_file", "evaluate",
   {"a/ok.grm", "b/ok.grm", "-k", "2", "-n", "2", "--keep", "kept"}, kUsage, "evaluate: error: ",
   "the grammar inferred from a/ok.grm and the grammar inferred from b/ok.grm would both be written to kept/ok.grm", {},
   [](const fs::path& d) {
     for (const char* folder : {"a", "b", "kept"}) fs::create_directory(d / folder);
     fs::copy_file(kCorpus / "grammar/ok.grm", d / "a/ok.grm");
     fs::copy_file(kCorpus / "grammar/ok.grm", d / "b/ok.grm"); }},
  {"evaluate_kept_over_another_grammar", "evaluate",
   {"ok.grm", "ok.3.grm", "--precision-recall", "--counts", "3", "--samples", "2", "--keep", "."}, kUsage,
   "evaluate: error: ", "the output ./ok.3.grm is the grammar file itself (ok.3.grm)", kValidGrammar,
   [](const fs::path& d) { fs::copy_file(kCorpus / "grammar/ok.grm", d / "ok.3.grm"); }},
  {"evaluate_random_style_written_over_a_grammar", "evaluate",
   {"random_style_0.grm", "-k", "2", "-n", "2", "--random-styles", "1", "--seed", "3", "--random-styles-write", "."},
   kUsage, "evaluate: error: ", "the output ./random_style_0.grm is the grammar file itself (random_style_0.grm)", {},
   [](const fs::path& d) { fs::copy_file(kCorpus / "grammar/ok.grm", d / "random_style_0.grm"); }},

  {"check_unknown_option", "check", {"ok.grm", "two_parts.obj", "--breif"}, kUsage,
   "check: error: ", "unknown option '--breif'\n  hint: did you mean '--brief'?", kGrammarAndObj},
  {"check_missing_value", "check", {"ok.grm", "two_parts.obj", "--scope", "1", "2"}, kUsage,
   "check: error: ", "--scope needs 3 values (X Y Z)", kGrammarAndObj},
  {"check_value_out_of_range", "check", {"ok.grm", "two_parts.obj", "--max-steps", "0"}, kUsage,
   "check: error: ", "--max-steps must be between 1 and", kGrammarAndObj},
  {"check_tolerance_not_positive", "check", {"ok.grm", "two_parts.obj", "--tolerance", "0"}, kUsage,
   "check: error: ", "--tolerance must be > 0, got 0", kGrammarAndObj},
  {"check_negative_scope", "check", {"ok.grm", "two_parts.obj", "--scope", "1", "-2", "3"}, kUsage,
   "check: error: ", "--scope sizes must be >= 0, got -2", kGrammarAndObj},
  {"generate_scope_too_large", "generate", {"ok.grm", "--scope", "1e300", "1", "1", "-o", "out.glb"}, kUsage,
   "generate: error: ", "--scope sizes must be at most 1e+38, got 1e300", kValidGrammar},
  {"generate_spacing_too_large", "generate", {"ok.grm", "-n", "3", "--spacing", "1e308", "-o", "out.glb"}, kUsage,
   "generate: error: ", "--spacing must be between -1e+38 and 1e+38, got 1e308", kValidGrammar},
  {"generate_negative_scope", "generate", {"ok.grm", "--scope", "1", "-2", "3"}, kUsage,
   "generate: error: ", "--scope sizes must be >= 0, got -2", kValidGrammar},
  {"check_too_many_steps", "check", {"ok.grm", "two_parts.obj", "--max-steps", "1"}, kLimit,
   "two_parts.obj: error: ", "more than 1 matching steps", kGrammarAndObj},
  {"check_grammar_empty", "check", {"", "two_parts.obj"}, kUsage,
   "check: error: ", "an empty argument names no file", kValidObj},
  {"check_grammar_only", "check", {"ok.grm"}, kUsage, "check: error: ", "give a grammar and at least one example",
   kValidGrammar},
  {"check_missing_grammar", "check", {"missing.grm", "two_parts.obj"}, kIo,
   "missing.grm: error: ", "cannot open the grammar file", kValidObj},
  {"check_missing_example", "check", {"ok.grm", "missing.obj"}, kIo,
   "missing.obj: error: ", "no such file or folder", kValidGrammar},
  {"check_empty_example_folder", "check", {"ok.grm", "examples"}, kIo,
   "examples: error: ", "the folder holds no example files", kValidGrammar,
   [](const fs::path& d) { fs::create_directory(d / "examples"); }},
  {"check_bad_grammar", "check", {"unknown_rule.grm", "two_parts.obj"}, kInput,
   "unknown_rule.grm:1:40: error: ", "unknown rule 'hose'", {"grammar/unknown_rule.grm", "obj/two_parts.obj"}},
};
// clang-format on

class BadInputCorpus : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputCorpus, Runs) {
  const BadInput& c = GetParam();
  TempFolder dir;
  for (const std::string& input : c.inputs) fs::copy_file(kCorpus / input, dir / fs::path(input).filename());
  if (c.setup) c.setup(dir.path());
  if (c.precious) write_text(dir / c.precious, "precious: must survive a failed run\n");
  const FolderSnapshot before = test::snapshot(dir.path());

  if (c.address_space_mib != 0 && kAddressSanitizer) GTEST_SKIP() << "a capped address space and ASan do not mix";
  test::CommandResult r;
  if (c.max_memory_mib != 0 || c.address_space_mib != 0 || c.max_file_bytes != 0) {
    const test::MeasuredResult m =
        test::run_program_measured(c.tool, c.args, dir.path(), {c.address_space_mib, c.max_file_bytes});
    r = m.result;
    RecordProperty("peak_kib", std::to_string(m.peak_kib));
    // Far below what holding the input (or its geometry) whole would take.
    // Under AddressSanitizer a program holds some 75 MiB before it reads
    // anything (shadow memory, the sanitizer's own allocator): there the
    // bound is on what the run takes beyond the same program doing nothing.
    if (c.max_memory_mib != 0) {
      const long idle = kAddressSanitizer ? test::run_program_measured(c.tool, {"--help"}, dir.path()).peak_kib : 0;
      EXPECT_LT(m.peak_kib - idle, static_cast<long>(c.max_memory_mib) * 1024)
          << "peak memory in KiB" << (kAddressSanitizer ? ", beyond the program's own " + std::to_string(idle) : "");
    }
  } else {
    r = run_program(c.tool, c.args, dir.path());
  }

  EXPECT_EQ(r.exit_code, c.exit_code) << r.err;
  if (c.exit_code == kOk) {
    for (const std::string& file : c.creates) EXPECT_TRUE(fs::is_regular_file(dir / file)) << file << "\n" << r.err;
    // A valid input may still deserve a warning, which names where and what.
    EXPECT_NE(r.err.find(c.where), std::string::npos) << "where: " << c.where << "\n" << r.err;
    EXPECT_NE(r.err.find(c.what), std::string::npos) << "what: " << c.what << "\n" << r.err;
    return;
  }
  EXPECT_NE(r.err.find(c.where), std::string::npos) << "where: " << c.where << "\n" << r.err;
  EXPECT_NE(r.err.find(c.what), std::string::npos) << "what: " << c.what << "\n" << r.err;
  if (!c.unsaid.empty()) {
    EXPECT_EQ(r.err.find(c.unsaid), std::string::npos) << "says " << c.unsaid << ":\n" << r.err;
  }
  EXPECT_NE(r.err.find("\n  hint: "), std::string::npos) << "no hint:\n" << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  // Nothing created, changed or removed: not the output, not a temporary.
  EXPECT_TRUE(test::snapshot(dir.path()) == before) << "the run folder changed";
}

INSTANTIATE_TEST_SUITE_P(BadInput, BadInputCorpus, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<BadInput>& p) { return std::string(p.param.name); });

// The corpus's README lists every case the table runs, and the other way
// round, so the two cannot drift apart.
TEST(BadInputCorpusReadme, ListsEveryCase) {
  const std::string readme = test::read_file(kCorpus / "README.md");
  for (const BadInput& c : kCases)
    EXPECT_NE(readme.find("| `" + std::string(c.name) + "` |"), std::string::npos) << c.name << " is not in the README";
  EXPECT_GE(kCases.size(), 70u);
}

}  // namespace
}  // namespace vern
