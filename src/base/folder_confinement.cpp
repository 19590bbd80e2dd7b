#include "base/folder_confinement.hpp"

#include <algorithm>

namespace vern {

namespace fs = std::filesystem;

namespace {

bool has_parent_step(const fs::path& path) {
  return std::any_of(path.begin(), path.end(), [](const fs::path& part) { return part == ".."; });
}

}  // namespace

bool leads_into_folder(const fs::path& path, const fs::path& folder) {
  std::error_code path_error, folder_error;
  // Absolute first: the canonical form of a relative path none of whose
  // steps exists yet stays relative.
  const fs::path real = fs::weakly_canonical(fs::absolute(path, path_error), path_error);
  const fs::path real_folder = fs::canonical(folder.empty() ? fs::path(".") : folder, folder_error);
  if (path_error || folder_error) return false;
  const auto [f, p] = std::mismatch(real_folder.begin(), real_folder.end(), real.begin(), real.end());
  return f == real_folder.end();
}

std::optional<fs::path> path_in_folder(const fs::path& folder, std::string_view named) {
  // A NUL would cut the path short where the system reads it.
  if (named.empty() || named.find('\0') != std::string_view::npos) return std::nullopt;
  const fs::path path(named);
  if (path.is_absolute() || has_parent_step(path)) return std::nullopt;
  fs::path joined = folder / path;
  if (!leads_into_folder(joined, folder)) return std::nullopt;
  return joined;
}

}  // namespace vern
