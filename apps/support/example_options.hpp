// The options of the commands that read examples (infer, check): how many
// parts an example may have, and which files a glTF may have read.
#pragma once

#include <string>
#include <vector>

#include <vernacular/io.hpp>

#include "inverse/load/example.hpp"
#include "inverse/load/examples_of_files.hpp"
#include "support/command_line.hpp"

namespace vern {

// --max-parts, --max-faces, --max-gltf-mib, --allow-outside-files, --up,
// --stack, --buildings.
void add_example_options(CommandLine& cl);

// The limits those options give (Usage errors for values out of range).
ExampleLimits example_limits(const ParsedCommandLine& args);

// The same limits, --up, --allow-outside-files and --buildings as the
// public API's reading options (its tolerance left at 0).
vernacular::ReadOptions read_options(const ParsedCommandLine& args);

// --stack's labels, bottom to top (none when not given); Usage errors for
// an empty label or one listed twice.
std::vector<std::string> stack_order(const ParsedCommandLine& args);

// --buildings: how a file of several buildings is divided (apart when not
// given).
BuildingsMode buildings_mode(const ParsedCommandLine& args);

// The notes on stderr, each "PROGRAM: note...": the first three, then how
// many more (ten files of one city say the same thing).
void print_notes(const std::string& program, const std::vector<std::string>& notes);

}  // namespace vern
