// An example read from an OBJ file: each object `o name` one labelled
// part (example.hpp says what an example is).
#pragma once

#include <filesystem>

#include "inverse/load/example.hpp"

namespace vern {

// read_ahead: a second thread reads the file's text ahead (obj_reader.hpp).
Example load_obj_example(const std::filesystem::path& path, const ExampleLimits& limits, bool read_ahead);

}  // namespace vern
