// The files an inferred grammar is saved as: the grammar (STYLE.grm) and,
// beside it, its parts' meshes (STYLE.prims.obj and .mtl), which the
// grammar names with @primitives so that it alone regenerates buildings.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "forward/primitive_library.hpp"

namespace vern {

// STYLE.prims.obj for STYLE.grm.
std::filesystem::path meshes_path_for(const std::filesystem::path& grammar);

// `file` as the grammar at `grammar` names it: relative to the grammar's
// folder where possible, so the two can move together.
std::string path_from(const std::filesystem::path& grammar, const std::filesystem::path& file);

// The comment the grammar starts with: how many examples, the tolerance,
// how to regenerate buildings.
std::string inferred_header(std::size_t examples, double tolerance, const std::filesystem::path& grammar);

// A file written with the grammar (infer --report's page).
struct AlsoWritten {
  std::filesystem::path path;
  std::string_view content;
};

// Writes the meshes (one object per label, each filling the unit box), their
// materials and the grammar's text (`header` then `text`), and `also`, all
// replaced together or, failing (a full disk), none. Throws vern::Error
// (Io; Usage unless `meshes` ends in .obj).
void write_inferred(const PrimitiveLibrary& primitives, std::string_view header, std::string_view text,
                    const std::filesystem::path& grammar, const std::filesystem::path& meshes,
                    std::span<const AlsoWritten> also = {});

}  // namespace vern
