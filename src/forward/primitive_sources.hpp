// The primitive library a command uses: built-ins, then the grammar's
// @primitives (relative to the grammar file), then --primitives.
//
// @primitives is the grammar's choice, not the user's: it may name only
// files in the grammar's folder or below it (base/folder_confinement.hpp)
// unless outside_files (--allow-outside-files). --primitives is the user's
// own path: any file.
#pragma once

#include <filesystem>
#include <optional>

#include "forward/primitive_library.hpp"
#include "graph/grammar.hpp"

namespace vern {

PrimitiveLibrary primitives_for(const Grammar& grammar, const std::filesystem::path& grammar_file,
                                const std::optional<std::filesystem::path>& command_line, bool outside_files);

}  // namespace vern
