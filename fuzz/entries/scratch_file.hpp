// A file for loaders that only read from paths (load_example): the input is
// written to a private folder that lives as long as the process.
#pragma once

#include <filesystem>
#include <string>

#include "entries.hpp"

namespace vern::fuzz {

// Writes `input` to <private folder>/<name> (replacing the last input of
// that name) and returns the path. The folder is created under the system's
// temporary folder on first use, holds nothing else (so relative URIs in a
// fuzzed glTF find no files), and is removed when the process ends.
std::filesystem::path scratch_file(const std::string& name, Bytes input);

}  // namespace vern::fuzz
