// Writing derived buildings as glTF 2.0 (binary .glb or text .gltf).
//
// Each (primitive, material) pair in use is one glTF mesh whose triangles
// (polygons fanned from their first corner; primitive faces are convex) are
// stored once. Materials match the OBJ writer's (palette.hpp). The node tree
// has one root per variant, named after it, whose matrix moves it by its
// offset and turns the grammar's z-up frame to glTF's y-up (up_axis.hpp).
// Beneath it, one of two layouts:
//   - plain (default): one child per terminal, named by its label (as
//     graph/label.hpp writes a label into a name), whose matrix maps the
//     unit box onto the terminal's scope (columns frame[i] * size[i], then
//     the origin). Every viewer reads it, and `infer` reads it back as
//     labelled examples.
//   - instancing: one child per mesh the variant uses, named as the mesh
//     ("label", or "label colour_ff0000": the label one word, its spaces
//     written %20), carrying all its terminals as EXT_mesh_gpu_instancing
//     translations, rotations and scales (floats). Files are several times
//     smaller and faster to write and to draw; the extension is marked
//     required, so viewers without it refuse the file rather than show one
//     stray part per mesh. It cannot be optional: a fallback of plain
//     nodes would be drawn twice by the viewers that read the extension,
//     and would cost the plain layout's size on top (city, 10 buildings:
//     0.88 MB instanced, 3.04 MB plain).
// Same scene, same bytes, whether given whole or variant by variant
// (GltfStream: what `generate` does, so that its memory does not grow with
// the number of buildings).
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "base/atomic_file.hpp"
#include "forward/primitive_library.hpp"
#include "forward/terminal.hpp"

namespace vern {

struct GltfOptions {
  bool instancing = false;  // EXT_mesh_gpu_instancing layout (see above)
};

// A glTF document given its variants one at a time, to be written once
// (glb or gltf, then write_gltf). What it holds does not grow with the
// number of variants but for a few bytes each: the plain nodes and the
// instances' transforms wait in temporary files in spill_folder (in
// memory when none is given); `owner` names the output in errors.
// The library is kept by reference: it must outlive the stream.
class GltfStream {
 public:
  GltfStream(std::vector<std::string> labels, const PrimitiveLibrary& library, GltfOptions options,
             std::optional<std::filesystem::path> spill_folder, std::string owner);
  GltfStream(GltfStream&&) noexcept;
  ~GltfStream();

  // Throws vern::Error (Internal) for a terminal's label outside `labels`.
  void add(const Variant& variant);

  // The file in pieces, once: a GLB (throws vern::Error Limit past 4 GiB),
  // or glTF text with the buffer as a base64 data URI (held whole).
  void glb(const std::function<void(std::string_view)>& write);
  void gltf(const std::function<void(std::string_view)>& write);

  // Bytes held in memory for the variants (a test's measure of flatness).
  std::size_t held_bytes() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Throws vern::Error (Usage) unless the path ends in .glb or .gltf.
void check_gltf_path(const std::filesystem::path& path);

// Stages the stream's file, .glb or .gltf by the extension, among a run's
// outputs. Throws as write_gltf below.
void write_gltf(GltfStream& stream, const std::filesystem::path& path, OutputFiles& outputs);

// The scene as a GLB file's bytes.
std::string glb_bytes(const Scene& scene, const PrimitiveLibrary& library, GltfOptions options = {});

// The scene as glTF JSON text with the buffer embedded as a base64 data URI.
std::string gltf_text(const Scene& scene, const PrimitiveLibrary& library, GltfOptions options = {});

// Stages a .glb (binary) or .gltf (text) file, chosen by the extension,
// among a run's outputs (base/atomic_file.hpp). Throws vern::Error: Usage
// for another extension, Io when the file cannot be written, Limit when a
// GLB would pass 4 GiB.
void write_gltf(const Scene& scene, const PrimitiveLibrary& library, const std::filesystem::path& path,
                GltfOptions options, OutputFiles& outputs);

// The same as a run of its own: written, then replaced.
void write_gltf(const Scene& scene, const PrimitiveLibrary& library, const std::filesystem::path& path,
                GltfOptions options = {});

}  // namespace vern
