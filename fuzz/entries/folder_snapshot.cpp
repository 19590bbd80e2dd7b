#include "folder_snapshot.hpp"

#include <fstream>
#include <iterator>

namespace vern::fuzz {

namespace fs = std::filesystem;

FolderSnapshot snapshot_folder(const fs::path& folder) {
  FolderSnapshot snapshot;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(folder)) {
    const std::string rel = e.path().lexically_relative(folder).string();
    switch (e.symlink_status().type()) {
      case fs::file_type::regular: {
        std::ifstream in(e.path(), std::ios::binary);
        snapshot[rel] = "file:" + std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        break;
      }
      case fs::file_type::symlink: snapshot[rel] = "link:" + fs::read_symlink(e.path()).string(); break;
      case fs::file_type::directory: snapshot[rel] = "folder"; break;
      default: snapshot[rel] = "other"; break;
    }
  }
  return snapshot;
}

std::string snapshot_difference(const FolderSnapshot& before, const FolderSnapshot& after) {
  for (const auto& [path, held] : after) {
    const auto it = before.find(path);
    if (it == before.end()) return "'" + path + "' was made";
    if (it->second != held) return "'" + path + "' was changed";
  }
  for (const auto& [path, held] : before)
    if (!after.contains(path)) return "'" + path + "' was removed";
  return "";
}

}  // namespace vern::fuzz
