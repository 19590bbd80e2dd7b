// The options of the commands that read examples (infer, check): how many
// parts an example may have, and which files a glTF may have read.
#pragma once

#include <string>
#include <vector>

#include "inverse/building_angle.hpp"
#include "inverse/example.hpp"
#include "inverse/scene_buildings.hpp"
#include "support/command_line.hpp"

namespace vern {

// --max-parts, --max-faces, --max-gltf-mib, --allow-outside-files, --up,
// --stack, --buildings.
void add_example_options(CommandLine& cl);

// The limits those options give (Usage errors for values out of range).
ExampleLimits example_limits(const ParsedCommandLine& args);

// --stack's labels, bottom to top (none when not given); Usage errors for
// an empty label or one listed twice.
std::vector<std::string> stack_order(const ParsedCommandLine& args);

// --buildings: how a file of several buildings is divided (apart when not
// given).
BuildingsMode buildings_mode(const ParsedCommandLine& args);

// The examples of the loaded `files` once each is divided as `mode` says
// (scene_buildings.hpp), in order, each building standing at an angle
// turned back (building_angle.hpp); each file's tolerance as
// example_tolerance(file, tolerance) gives it. A note for each file
// divided and each building turned back goes to `notes`.
std::vector<Example> examples_of_files(std::vector<Example> files, BuildingsMode mode, double tolerance,
                                       std::vector<std::string>& notes);

// The notes on stderr, each "PROGRAM: note...": the first three, then how
// many more (ten files of one city say the same thing).
void print_notes(const std::string& program, const std::vector<std::string>& notes);

}  // namespace vern
