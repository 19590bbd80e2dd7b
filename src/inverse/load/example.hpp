// Loading labelled examples: the buildings that inference learns from.
//
// An example is a file of labelled parts (thesis chapter 9): each OBJ object
// (`o name`), or each named glTF node with a mesh, is one primitive; its
// label is the name with a Blender-style numeric suffix removed, so
// "window.001" and "window.002" are both the primitive "window". An object
// made of loose pieces whose boxes are apart (three windows joined into
// one `o window`) is one part per piece (loose_parts.hpp). Inference
// works on the axis-aligned bounding box of each part. Matching turns
// (orientation.hpp) needs every part's vertex positions, kept compactly,
// and the whole mesh of the first part of each label, its canonical mesh:
// only those meshes are kept, so that a million parts fit in little memory.
//
// Coordinates are the file's world space turned z-up (io/up_axis.hpp):
// glTF is y-up by its specification; an OBJ declares its up axis with a
// `# up` line or is read with ExampleLimits::obj_up (io/obj_reader.hpp).
// "Each example is placed at its own origin": callers translate by -min.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "forward/mesh.hpp"
#include "inverse/load/part_positions.hpp"
#include "io/gltf_files.hpp"
#include "io/up_axis.hpp"

namespace vern {

// One labelled part and its world-space bounding box.
struct LabelledBox {
  std::string label;   // the primitive: the object's name without its numeric suffix
  glm::dvec3 min{0.0}, max{0.0};
  std::string object;  // the name as written in the file, for messages
  std::uint32_t line = 0;  // OBJ: the line of its `o` statement; glTF: 0
  // Index into Example::meshes when this part is the first of its label
  // in the example, else Mesh::kNone.
  std::uint32_t mesh = Mesh::kNone;
  // Loose pieces the object is made of, kept as this one part because
  // their boxes meet (loose_parts.hpp); pieces apart are parts of their own.
  std::uint32_t loose_pieces = 1;
  // The file's own grouping of its parts: the top-level glTF node the part
  // lies under, or the OBJ `g` group its object starts in (obj_reader.hpp;
  // an object before any `g` is a group of its own). Parts of one group
  // always belong to one building of a scene (scene_buildings.hpp).
  std::uint32_t group = 0;
};

struct Example {
  std::string source;  // the file, as named to load_example
  std::vector<LabelledBox> boxes;  // in file order
  std::vector<Mesh> meshes;        // world-space mesh of each label's first box, in file order
  PartPositions positions;         // world-space vertex positions of each box, same order (empty: none known)
  glm::dvec3 min{0.0}, max{0.0};   // bounds of all boxes
  // The noise level its coordinates were snapped to (snapped_coordinates.hpp),
  // 0 as read: snapped, coordinates apart are places apart, cut within
  // float noise however close (CheckOptions::cut_tolerance).
  double snapped = 0;
  // For a building cut from a file of several (scene_buildings.hpp): the
  // file's default_tolerance. An exporter writes the whole file at one
  // precision, so a building's float noise is the file's, however near
  // the origin it stands (default_tolerance takes the larger).
  double file_tolerance = 0;
};

struct ExampleLimits {
  // Labelled parts per example (infer/check --max-parts). Inference and
  // checking grow with the parts; an OBJ stops being read at the first
  // part past the limit, so a huge file fails fast and in little memory.
  std::size_t max_parts = 10000;
  // Faces per labelled part (infer/check --max-faces): matching a part's
  // mesh is linear in its vertices, but a scanned statue need not be a
  // part of a grammar of buildings. Reading stops at the first face past it.
  std::size_t max_faces = 1'000'000;
  // Faces, and vertices, that a glTF example's parts place in all
  // (infer/check --max-total-faces): a mesh counts once for each node or
  // instance that places it, so a small file cannot make a billion faces
  // of one mesh a thousand nodes share. Reading stops before the part past
  // it is placed. An OBJ's faces are each a line of the file, read as they
  // come: its size bounds them.
  std::size_t max_total_faces = 10'000'000;
  // Which files a glTF may have read, and how large (gltf_files.hpp;
  // infer/check --allow-outside-files, --max-gltf-mib).
  GltfFileRules gltf;
  // Not a limit: the up axis of an OBJ that does not declare one
  // (infer/check --up; y, as Blender exports OBJ by default).
  UpAxis obj_up = UpAxis::Y;
  // Nor this: the tolerance the example will be matched within (infer and
  // check --tolerance; 0: its own, example_tolerance). A part no larger is
  // a point, and refused.
  double tolerance = 0;
};

// Reads a labelled example: .obj (each object one part), .glb or .gltf
// (each node with a mesh one part, its world transform applied; the name is
// required; a node with EXT_mesh_gpu_instancing, as `generate --instancing`
// writes, is one part per instance, labelled by the name's first word).
// Throws vern::Error: Io when the file is missing, unreadable or not a
// regular file (a FIFO, a device), Input when it holds no labelled parts,
// geometry without a name, a part that is a single point (no extent on any
// axis, within default_tolerance), a vertex that is not finite or beyond
// kMaxObjCoordinate (also after a glTF node's transform), a glTF node
// reached twice or naming a missing mesh, a glTF URI that limits.gltf
// refuses (gltf_files.hpp), or is not a valid OBJ or glTF file (glTF: by
// the rules gltf_rules.hpp and glb_chunks.hpp check, and JSON nested more
// than 64 deep); Limit for more parts than limits.max_parts, or a glTF file
// (or one it names) larger than limits.gltf.max_bytes, or one whose JSON
// would take more memory than that once read (json_cost.hpp), or a part of
// more than limits.max_faces faces, or glTF parts that place more than
// limits.max_total_faces faces or vertices in all; Usage for another
// extension. A part flat on one axis (a facade panel) is fine.
// threads: 1 reads on this thread alone; otherwise a second thread reads an
// OBJ's text ahead (obj_reader.hpp; the same example, and the same error).
Example load_example(const std::filesystem::path& path, const ExampleLimits& limits = {}, unsigned threads = 1);

// The files that command-line arguments name, in the order given; a folder
// stands for every .obj, .glb and .gltf file directly inside it, sorted by
// name. Throws vern::Error (Io) for a path that does not exist or a folder
// without example files, (Usage) for a file of another kind.
std::vector<std::filesystem::path> example_files(const std::vector<std::string>& args);

// The bounds of all boxes (both zero when there are none).
void update_bounds(Example& example);

// Throws vern::Error (Input) for a part no larger than the tolerance on
// every axis (a point no scope can be fitted to; a part may be flat: a
// facade panel has no thickness), or an example too small for its sizes
// to be told apart. given_tolerance: as example_tolerance takes it.
void refuse_points(const Example& example, double given_tolerance);

// The example's extent: max - min.
glm::dvec3 example_size(const Example& example);

// 1e-6 times the example's largest extent, or its largest coordinate if
// that is larger (or its file's, Example::file_tolerance): the distance
// below which two box bounds count as the same. Exporters write coordinates as 32-bit floats, about 1e-7 noise
// relative to the coordinate (a house modelled 2 km from the origin is
// noisy to 0.1 mm, however small it is); real gaps are far larger (1e-6
// keeps a 1 mm gap on a 100 m building).
double default_tolerance(const Example& example);
// The same for bounds [min, max].
double default_tolerance(glm::dvec3 min, glm::dvec3 max);

// The tolerance an example is matched within: `given` (--tolerance) when
// it is > 0, else the example's own default_tolerance, taken where the
// file put it (before it is moved to the origin). The one rule `check`
// applies to each example and `infer` holds each example to, so that a
// grammar infer writes passes check on the same examples.
double example_tolerance(const Example& example, double given);

// "'window.001' (line 12)", or "'window.001'" when the line is unknown: how
// messages name a part.
std::string describe_object(const LabelledBox& box);

}  // namespace vern
