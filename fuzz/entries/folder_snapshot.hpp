// What a folder holds, to tell whether a run wrote anything in it: every
// file's bytes, every link's target, every folder, links not followed.
#pragma once

#include <filesystem>
#include <map>
#include <string>

namespace vern::fuzz {

// Path relative to the folder -> "file:" and its bytes, "link:" and its
// target, "folder", or "other".
using FolderSnapshot = std::map<std::string, std::string>;

FolderSnapshot snapshot_folder(const std::filesystem::path& folder);

// "" when equal, else the first path made, removed or changed.
std::string snapshot_difference(const FolderSnapshot& before, const FolderSnapshot& after);

}  // namespace vern::fuzz
