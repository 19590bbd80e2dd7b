// An example read from a glTF or GLB file: each named node with a mesh
// one labelled part, its world transform applied (example.hpp says what
// an example is and what is refused).
#pragma once

#include <filesystem>

#include "inverse/load/example.hpp"

namespace vern {

// binary: a GLB (else glTF text).
Example load_gltf_example(const std::filesystem::path& path, bool binary, const ExampleLimits& limits);

}  // namespace vern
