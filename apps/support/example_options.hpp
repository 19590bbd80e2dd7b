// The options of the commands that read examples (infer, check): how many
// parts an example may have, and which files a glTF may have read.
#pragma once

#include <string>
#include <vector>

#include "inverse/example.hpp"
#include "support/command_line.hpp"

namespace vern {

// --max-parts, --max-faces, --max-gltf-mib, --allow-outside-files, --up,
// --stack.
void add_example_options(CommandLine& cl);

// The limits those options give (Usage errors for values out of range).
ExampleLimits example_limits(const ParsedCommandLine& args);

// --stack's labels, bottom to top (none when not given); Usage errors for
// an empty label or one listed twice.
std::vector<std::string> stack_order(const ParsedCommandLine& args);

}  // namespace vern
