// Writing derived buildings as labelled OBJ (+ MTL).
//
// One `o <label>` object per terminal, so the file is exactly the labelled
// input that inference reads back (a label OBJ cannot hold as it is, such
// as "#x", is written as graph/label.hpp says, and reads back the same).
// Each terminal's primitive mesh is placed
// by its scope (to_world) and moved by its variant's offset; indices are
// absolute and 1-based. A `g <variant name>` group holds each variant's
// objects, so that a file of several buildings reads back as its buildings.
// Materials: one per distinct colour for coloured terminals, one per label
// otherwise (see palette.hpp). Coordinates are turned to the up axis asked
// for (up_axis.hpp; y by default, as Blender imports OBJ), which a `# up y`
// or `# up z` line at the top declares, so that the reader turns them back
// whatever it would assume. Same scene, same bytes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "base/atomic_file.hpp"
#include "forward/primitive_library.hpp"
#include "forward/terminal.hpp"
#include "io/palette.hpp"
#include "io/up_axis.hpp"

namespace vern {

// The OBJ text written variant by variant into `write` (in pieces of
// about a megabyte), so that `generate` holds one building at a time
// however many it writes; the MTL text, which names the materials used,
// comes once all variants are in.
// The library is kept by reference: it must outlive the stream.
class ObjStream {
 public:
  ObjStream(std::vector<std::string> labels, const PrimitiveLibrary& library, const std::string& mtl_file_name,
            std::function<void(std::string_view)> write, UpAxis up = UpAxis::Y);
  // Throws vern::Error (Internal) for a terminal's label outside `labels`.
  void add(const Variant& variant);
  // Writes what is still held; call after the last add().
  void flush();
  std::string mtl_text() const;
  // Bytes of text held (a test's measure of flatness).
  std::size_t held_bytes() const { return out_.capacity(); }

 private:
  std::vector<std::string> labels_;
  std::vector<const Mesh*> meshes_;  // by label
  std::vector<std::string> names_;   // by label: its `o` name (graph/label.hpp)
  MaterialTable materials_;
  std::function<void(std::string_view)> write_;
  std::string out_;
  std::uint64_t positions_ = 0, uvs_ = 0, normals_ = 0;  // written so far
  UpAxis up_;
};

// Throws vern::Error (Usage) when the path does not end in .obj (its MTL
// file would be itself).
void check_obj_path(const std::filesystem::path& obj_path);

// The OBJ text; it names mtl_file_name in its `mtllib` line (omitted when
// empty). Labels the library does not know are written as its box().
std::string obj_text(const Scene& scene, const PrimitiveLibrary& library, const std::string& mtl_file_name,
                     UpAxis up = UpAxis::Y);

// The MTL text defining the materials obj_text uses.
std::string mtl_text(const Scene& scene);

// The path of the MTL file write_obj writes beside obj_path: the same stem.
std::filesystem::path mtl_path_for(const std::filesystem::path& obj_path);

// Stages obj_path and, beside it, mtl_path_for(obj_path) among a run's
// outputs (base/atomic_file.hpp): both are replaced together or neither.
// Throws vern::Error: Io when a file cannot be written, Usage when the
// path does not end in .obj (its MTL file would be itself).
void write_obj(const Scene& scene, const PrimitiveLibrary& library, const std::filesystem::path& obj_path,
               OutputFiles& outputs, UpAxis up = UpAxis::Y);

// The same as a run of its own: both files written, then both replaced.
void write_obj(const Scene& scene, const PrimitiveLibrary& library, const std::filesystem::path& obj_path,
               UpAxis up = UpAxis::Y);

}  // namespace vern
