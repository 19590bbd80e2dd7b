#include "io/gltf_files.hpp"

#include "base/folder_confinement.hpp"

namespace vern {

namespace fs = std::filesystem;

std::string gltf_size_hint(const GltfFileRules& rules) {
  return "glTF files and the files they name are read whole: raise the limit with --max-gltf-mib (now " +
         std::to_string(rules.max_bytes >> 20) + ")";
}

GltfFiles::GltfFiles(const fs::path& gltf, GltfFileRules rules)
    : folder_(gltf.has_parent_path() ? gltf.parent_path().string() : std::string(".")), rules_(rules) {}

std::optional<std::string> GltfFiles::uri_of(const std::string& joined) const {
  if (!joined.starts_with(folder_)) return std::nullopt;
  std::string uri = joined.substr(folder_.size());
  if (folder_.back() != '/') {
    if (!uri.starts_with('/')) return std::nullopt;  // "folder2/..." is not below "folder"
    uri.erase(0, 1);
  }
  return uri;
}

void GltfFiles::refuse(ErrorKind kind, std::string message, std::string hint) {
  if (!refusal_) refusal_ = Refusal{kind, std::move(message), std::move(hint)};
}

std::optional<fs::path> GltfFiles::resolve(const std::string& uri) {
  // A NUL would cut the path short where the system reads it.
  if (uri.empty() || uri.find('\0') != std::string::npos) return std::nullopt;
  const fs::path path(uri);
  if (rules_.outside_folder) return path.is_absolute() ? path : fs::path(folder_) / path;
  std::optional<fs::path> inside = path_in_folder(folder_, uri);
  if (!inside) {
    refuse(ErrorKind::Input, "the URI '" + uri + "' names a file outside the glTF's folder",
           "a glTF may name files in its own folder only: copy the file there and name it so, or pass "
           "--allow-outside-files if you trust this glTF");
  }
  return inside;
}

bool GltfFiles::may_read(const std::string& joined) {
  const std::optional<std::string> uri = uri_of(joined);
  if (!uri) return false;
  const std::optional<fs::path> path = resolve(*uri);
  std::error_code ec;
  return path && fs::exists(*path, ec);
}

bool GltfFiles::read(const std::string& joined, std::vector<unsigned char>& out) {
  const std::optional<std::string> uri = uri_of(joined);
  const std::optional<fs::path> path = uri ? resolve(*uri) : std::nullopt;
  if (!path) return false;
  last_read_ = *uri;
  const std::optional<ReadRefusal> refused = read_regular_file(*path, rules_.max_bytes, out);
  if (!refused) return true;
  refuse(refused->kind, "the URI '" + *uri + "' names a file that " + refused->problem,
         refused->kind == ErrorKind::Limit ? gltf_size_hint(rules_) : "name a regular file beside the glTF");
  return false;
}

}  // namespace vern
