// Where a command may write, checked before any work is done.
//
// A run that could only fail when it writes, or would write over one of its
// own inputs, fails at once: nothing is derived or inferred in vain and no
// file is created or changed (README, "Errors and exit codes").
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace vern {

// Whether two paths name the same file: the same inode when both exist,
// otherwise the same absolute path once "." and ".." are resolved.
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b);

// Checks that `output` can be written as one file and is none of `inputs`.
// Throws vern::Error: Usage, naming `program`, when it is the same file as
// an input (input_kind says what the inputs are: "the grammar file"); Io
// when it is an existing folder or its folder does not exist.
void check_output_file(const std::string& program, const std::filesystem::path& output,
                       const std::vector<std::filesystem::path>& inputs, const std::string& input_kind);

// Throws vern::Error (Usage) when two outputs of one run are the same file:
// the second would overwrite the first.
void check_distinct_outputs(const std::string& program, const std::vector<std::filesystem::path>& outputs);

}  // namespace vern
