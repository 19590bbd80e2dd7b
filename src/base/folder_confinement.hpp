// Files that a file names: only in its own folder, unless the user allows more.
//
// A glTF's URIs and a grammar's @primitives are chosen by whoever wrote the
// file, not by the user who runs the command on it: `../../.ssh/id_rsa`,
// `/etc/passwd` or a link to either would be read, and what they hold could
// reach a message or an output. So a path a file names is followed only when
// it stays in that file's folder or below it: no absolute path, no `..`, and
// no link on the way that leads out. `--allow-outside-files` lifts this
// (io/gltf_files.hpp, forward/primitive_sources.hpp).
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

namespace vern {

// folder / named, when `named` (a relative path as the file wrote it) stays
// in `folder` (empty: the current folder) or below it: it is not absolute,
// has no `..` step, and leads, links followed, into the folder. Nothing
// otherwise, and for an empty name or one holding a NUL. Paths written
// outside are refused as written, without looking at what they name.
std::optional<std::filesystem::path> path_in_folder(const std::filesystem::path& folder, std::string_view named);

// Whether `path`, its links followed, lies in `folder` or below it (false
// when either cannot be resolved: a link that leads to itself).
bool leads_into_folder(const std::filesystem::path& path, const std::filesystem::path& folder);

}  // namespace vern
