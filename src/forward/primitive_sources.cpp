#include "forward/primitive_sources.hpp"

#include <string>

#include "base/error.hpp"
#include "base/folder_confinement.hpp"
#include "graph/label.hpp"

namespace vern {

PrimitiveLibrary primitives_for(const Grammar& grammar, const std::filesystem::path& grammar_file,
                                const std::optional<std::filesystem::path>& command_line, bool outside_files) {
  PrimitiveLibrary library = PrimitiveLibrary::builtin();
  if (!grammar.primitives.empty()) {
    const std::filesystem::path folder = grammar_file.parent_path();
    // A NUL would cut the path short where the system reads it: another
    // file would be read, with --allow-outside-files too.
    if (grammar.primitives.find('\0') != std::string::npos) {
      fail(ErrorKind::Input, grammar_file.string(), grammar.primitives_loc,
           "@primitives names '" + shown_name(grammar.primitives) + "', which holds a NUL byte",
           "no file name holds one: write the path of the primitives file without it");
    }
    if (outside_files) {
      library.load(folder / grammar.primitives);
    } else {
      const std::optional<std::filesystem::path> path = path_in_folder(folder, grammar.primitives);
      if (!path) {
        fail(ErrorKind::Input, grammar_file.string(), grammar.primitives_loc,
             "@primitives names '" + shown_name(grammar.primitives) + "', which is outside the grammar's folder",
             "a grammar may name primitives files in its own folder or below it only: copy the file there and name "
             "it so, give it with --primitives, or pass --allow-outside-files if you trust this grammar");
      }
      library.load(*path, folder);
    }
  }
  if (command_line) library.load(*command_line);
  return library;
}

}  // namespace vern
