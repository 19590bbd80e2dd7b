// Files for loaders that only read from paths (load_example): inputs are
// written to private folders that live as long as the process.
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

// A private folder of its own for `purpose` (a word: "indirect"), created
// under the system's temporary folder on first use, apart from the one
// scratch_file writes to, and removed when the process ends. What it holds
// is the caller's business.
std::filesystem::path scratch_folder(const std::string& purpose);

}  // namespace vern::fuzz
