// Writing derived buildings as labelled OBJ (+ MTL).
//
// One `o <label>` object per terminal, so the file is exactly the labelled
// input that inference reads back. Each terminal's primitive mesh is placed
// by its scope (to_world) and moved by its variant's offset; indices are
// absolute and 1-based. A `# <variant name>` comment starts each variant.
// Materials: one per distinct colour for coloured terminals, one per label
// otherwise (see palette.hpp). Same scene, same bytes.
#pragma once

#include <filesystem>
#include <string>

#include "forward/primitive_library.hpp"
#include "forward/terminal.hpp"

namespace vern {

// The OBJ text; it names mtl_file_name in its `mtllib` line (omitted when
// empty). Labels the library does not know are written as its box().
std::string obj_text(const Scene& scene, const PrimitiveLibrary& library, const std::string& mtl_file_name);

// The MTL text defining the materials obj_text uses.
std::string mtl_text(const Scene& scene);

// Writes obj_path and, beside it, the MTL file of the same stem, each
// atomically (the MTL first, so the OBJ never names a missing file).
// Throws vern::Error (Io) when a file cannot be written.
void write_obj(const Scene& scene, const PrimitiveLibrary& library, const std::filesystem::path& obj_path);

}  // namespace vern
