// Helpers for the bad-input corpus (tests/bad_inputs/, bad_input_test.cpp):
// a folder's exact contents, a command's peak memory, and the inputs that
// are made at test time because they are binary or large.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "support/child_process.hpp"
#include "support/run_command.hpp"

namespace vern::test {

// Every file under a folder (relative path -> its size and a hash of its
// bytes) and every folder (relative path -> "/"): equal snapshots mean
// nothing was created, changed or removed.
using FolderSnapshot = std::map<std::string, std::string>;
FolderSnapshot snapshot(const std::filesystem::path& folder);

// run_program, without a shell, reporting the peak resident memory of the
// program (getrusage of the waited child, in KiB), under `limits`.
struct MeasuredResult {
  CommandResult result;
  long peak_kib = 0;
};
MeasuredResult run_program_measured(const std::string& program, const std::vector<std::string>& args,
                                    const std::filesystem::path& folder, ChildLimits limits = {});

// Two labelled boxes (a wall with a roof on it), then comment lines up to
// `bytes`: a valid example that must be read to its end.
void write_commented_obj(const std::filesystem::path& path, std::size_t bytes);

// `parts` unit boxes in a row, alternately labelled wall and window.
void write_many_parts_obj(const std::filesystem::path& path, std::size_t parts);

// `bytes` of 'v 1 ' repeated without a line break.
void write_endless_line(const std::filesystem::path& path, std::size_t bytes);

// A valid GLB of two parts, written by `generate` into folder/name.
void write_generated_glb(const std::filesystem::path& folder, const std::string& name);

}  // namespace vern::test
