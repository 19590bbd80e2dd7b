// A run's examples from the files it read: each file divided into its
// buildings, each building standing at an angle read turned back.
#pragma once

#include <string>
#include <vector>

#include "inverse/load/example.hpp"
#include "inverse/load/scene_buildings.hpp"

namespace vern {

// The examples of the loaded `files` once each is divided as `mode` says
// (scene_buildings.hpp), in order, each building standing at an angle
// turned back (building_angle.hpp); each file's tolerance as
// example_tolerance(file, tolerance) gives it. A note for each file
// divided and each building turned back goes to `notes`.
std::vector<Example> examples_of_files(std::vector<Example> files, BuildingsMode mode, double tolerance,
                                       std::vector<std::string>& notes);

}  // namespace vern
