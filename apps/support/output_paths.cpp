#include "support/output_paths.hpp"

#include "base/error.hpp"

namespace vern {

namespace fs = std::filesystem;

bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec);
  // An output that does not exist yet can still be an input's path spelled
  // differently ("./x.obj", "dir/../x.obj").
  const fs::path ca = fs::weakly_canonical(fs::absolute(a, ec), ec);
  if (ec) return false;
  const fs::path cb = fs::weakly_canonical(fs::absolute(b, ec), ec);
  return !ec && ca == cb;
}

void check_output_file(const std::string& program, const fs::path& output, const std::vector<fs::path>& inputs,
                       const std::string& input_kind) {
  for (const fs::path& input : inputs) {
    if (same_file(output, input))
      throw Error(ErrorKind::Usage, program + ": error: the output " + output.string() + " is " + input_kind + " itself" +
                                        (input.string() == output.string() ? "" : " (" + input.string() + ")") +
                                        "\n  hint: choose another output path; inputs are never overwritten");
  }
  std::error_code ec;
  if (fs::is_directory(output, ec))
    fail(ErrorKind::Io, output.string(), {}, "cannot write this file: it is an existing folder",
         "name a file inside it, or another path");
  const fs::path folder = output.has_parent_path() ? output.parent_path() : fs::path(".");
  if (!fs::is_directory(folder, ec))
    fail(ErrorKind::Io, output.string(), {}, "cannot write here: " + folder.string() + " is not an existing folder",
         "create the folder first, or choose another path");
}

void check_distinct_outputs(const std::string& program, const std::vector<fs::path>& outputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i)
    for (std::size_t j = i + 1; j < outputs.size(); ++j)
      if (same_file(outputs[i], outputs[j]))
        throw Error(ErrorKind::Usage, program + ": error: two outputs of this run are the same file: " +
                                          outputs[i].string() + " and " + outputs[j].string() +
                                          "\n  hint: give them different paths");
}

}  // namespace vern
