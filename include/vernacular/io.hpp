// Reading example buildings, writing derived ones.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "vernacular/derive.hpp"
#include "vernacular/grammar.hpp"

namespace vernacular {

namespace detail {
struct ExampleData;
}

// How a file of several buildings becomes examples.
enum class Buildings {
  Apart,   // each building standing apart from the others, never dividing a top-level glTF node or OBJ `g` group
  Parts,   // the same, dividing groups too
  Groups,  // each top-level glTF node or OBJ group
  File,    // the whole file one example
};

enum class UpAxis { Y, Z };

struct ReadOptions {
  // The examples' noise level in metres: coordinates closer than this are
  // one (0: each file's own float precision).
  double tolerance = 0;
  Buildings buildings = Buildings::Apart;
  // The up axis of an OBJ that does not declare one with a `# up` line
  // (Blender exports OBJ y-up; glTF is always y-up).
  UpAxis obj_up = UpAxis::Y;
  // A glTF's URIs may name files outside its own folder.
  bool outside_files = false;
  std::size_t max_parts = 10000;              // labelled parts per example
  std::size_t max_faces = 1'000'000;          // faces per labelled part
  // Faces (and vertices) a glTF example's parts place in all, a mesh
  // counting once for each node that places it.
  std::size_t max_total_faces = 10'000'000;
  // A glTF or GLB file and each file it names are read whole, up to this
  // size; and their JSON may take no more memory than this once read.
  std::uint64_t max_file_bytes = 256ull << 20;
};

// One labelled part of an example, as read: its world-space box (z up).
struct ExamplePart {
  std::string label;   // the object's or node's name without a numeric suffix ("window.001": "window")
  std::string object;  // the name as the file writes it
  Vec3 min{}, max{};
  friend bool operator==(const ExamplePart&, const ExamplePart&) = default;
};

// An example building read from a file: its labelled parts, and what
// inference needs of their meshes. A value; copies share what they read.
class Example {
 public:
  // "house.obj", or "street.glb (building 2 of 3)" for one of a file's buildings.
  const std::string& source() const;
  const std::vector<ExamplePart>& parts() const;
  // Notes on how it was read: that its file held several buildings, that
  // it stands turned and was read turned back.
  const std::vector<std::string>& notes() const;

  // An example made in memory, without a file: labelled boxes (world
  // space, z up; min <= max on every axis) as a program has them
  // (annotations, another tool's scene). Each part is its box (no mesh).
  // `source` names it in messages. Throws Failure (Input) for no parts, an
  // empty or unusable label, a box whose min exceeds its max or that is a
  // point, a coordinate that is not finite.
  static Example from_parts(std::vector<ExamplePart> parts, std::string source = "<memory>");

  explicit Example(std::shared_ptr<const detail::ExampleData> data);
  const detail::ExampleData& data() const { return *data_; }

 private:
  std::shared_ptr<const detail::ExampleData> data_;
};

// Reads example files (.obj, .gltf, .glb) and folders of them (their
// files in name order), each file one example or, holding several
// buildings, one per building (options.buildings). Throws Failure: Io
// for a file that cannot be read, Input for one that is no example (its
// location names the file and, where known, the line or object), Usage
// for a file of another type, Limit past options.max_parts.
std::vector<Example> read_examples(const std::vector<std::filesystem::path>& paths, const ReadOptions& options = {});

// The example files `paths` stand for, in order: a file itself, a folder
// every .obj, .glb and .gltf file directly in it, by name. Throws Failure:
// Io for a path that does not exist or a folder without example files,
// Usage for a file of another kind.
std::vector<std::filesystem::path> example_files(const std::vector<std::filesystem::path>& paths);

// Writes buildings to one file, laid out side by side on a grid `spacing`
// metres apart: .obj (with its .mtl beside it), .glb or .gltf, chosen by
// the extension. Each part is its label's mesh from the grammar's
// @primitives, else the built-in one, else a box. Written to a temporary
// file, synced and renamed. Throws Failure: Usage for another extension,
// Io when a file cannot be written.
void write_buildings(const std::vector<Building>& buildings, const Grammar& grammar,
                     const std::filesystem::path& file, double spacing = 5.0);

}  // namespace vernacular
