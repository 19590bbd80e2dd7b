// The primitive library a command uses: built-ins, then the grammar's
// @primitives (relative to the grammar file), then --primitives.
#pragma once

#include <filesystem>
#include <optional>

#include "forward/primitive_library.hpp"
#include "graph/grammar.hpp"

namespace vern {

PrimitiveLibrary primitives_for(const Grammar& grammar, const std::filesystem::path& grammar_file,
                                const std::optional<std::filesystem::path>& command_line);

}  // namespace vern
