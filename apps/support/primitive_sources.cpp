#include "support/primitive_sources.hpp"

namespace vern {

PrimitiveLibrary primitives_for(const Grammar& grammar, const std::filesystem::path& grammar_file,
                                const std::optional<std::filesystem::path>& command_line) {
  PrimitiveLibrary library = PrimitiveLibrary::builtin();
  if (!grammar.primitives.empty()) library.load(grammar_file.parent_path() / grammar.primitives);
  if (command_line) library.load(*command_line);
  return library;
}

}  // namespace vern
