// The primitive meshes that I(name) inserts, by name.
//
// The built-ins (data/primitives/*.obj, compiled in) are always there; a
// grammar or the command line may load more from OBJ files, replacing
// built-ins of the same name. Every mesh the library holds
//   - fills the unit box: its bounds are mapped onto [0,1]^3 (an axis along
//     which it is flat stays at 0), so a scope of any size fits it exactly;
//   - has a normal on every corner: files without normals get flat
//     per-face normals.
// Copies are cheap: meshes are shared, immutable.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "forward/mesh.hpp"

namespace vern {

class PrimitiveLibrary {
 public:
  // The built-in primitives (parsed once per process, then copied).
  static PrimitiveLibrary builtin();

  // Adds the meshes of an OBJ file or a folder of them:
  //   folder: each *.obj in it is one primitive named by the file's stem,
  //           all its objects together;
  //   file:   each object is one primitive named by the label its name
  //           carries (graph/label.hpp; objects sharing a name are merged;
  //           faces before any `o` are named by the file's stem).
  // within: the folder every file read must lie in, links followed (a
  // grammar's @primitives: the caller checks `path`, this the files a
  // folder holds).
  // Throws vern::Error: Io when the path is missing or unreadable, Input for
  // a malformed OBJ, a name that is not a label, a folder without .obj files
  // or a file outside `within`.
  void load(const std::filesystem::path& path, const std::optional<std::filesystem::path>& within = std::nullopt);

  // Adds (or replaces) one primitive; normalises it as described above.
  // Throws vern::Error (Input) when the mesh has no faces.
  void add(const std::string& name, Mesh mesh);

  // The mesh called name, or null.
  const Mesh* find(std::string_view name) const;

  // All names, sorted.
  std::vector<std::string> names() const;

  // The unit box ("rect"): what an unknown primitive name inserts.
  const Mesh& box() const;

 private:
  std::map<std::string, std::shared_ptr<const Mesh>, std::less<>> meshes_;
};

// The mesh fitted to the unit box and given normals, as the library stores
// it (exposed for tests and for tools that check primitive files).
Mesh normalised_primitive(Mesh mesh);

}  // namespace vern
