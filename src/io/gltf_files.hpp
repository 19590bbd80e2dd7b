// The files a glTF may have read: itself, and the buffers and images its
// URIs name.
//
// A glTF comes from anywhere, and its URIs are its own choice, not the
// user's: `../secret.txt` would be read into the inferred meshes, a FIFO
// would hang the run, a URI to a 1 GB file would be read whole. So a URI
// may name only a regular file in the glTF's folder or below it (no `..`,
// no absolute path, no link leading out), unless the user allows files
// outside (`--allow-outside-files`; base/folder_confinement.hpp), and no
// file larger than a cap is read.
// tinygltf opens the files through callbacks (example.cpp) that ask here.
// The first refusal is kept, to be the example's error; what a refused
// file holds and how large it is are never said.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "base/input_file.hpp"

namespace vern {

struct GltfFileRules {
  bool outside_folder = false;  // URIs may name files anywhere
  // Per file: the glTF or GLB itself, each buffer, each image; and the
  // memory the glTF's JSON may take once read (json_cost.hpp).
  std::uint64_t max_bytes = std::uint64_t{256} << 20;
};

// The hint for a file over rules.max_bytes: the flag that raises it.
std::string gltf_size_hint(const GltfFileRules& rules);

class GltfFiles {
 public:
  GltfFiles(const std::filesystem::path& gltf, GltfFileRules rules);

  // The folder URIs are relative to, as tinygltf joins them: "folder/uri".
  const std::string& folder() const { return folder_; }

  // Whether `joined` (folder() joined with a URI) names a file that may be
  // read; a refusal is kept. Paths tinygltf tries beyond folder() (the
  // current folder) are not the glTF's folder: never.
  bool may_read(const std::string& joined);

  // Reads a file may_read allowed; false (and a kept refusal) when it cannot.
  bool read(const std::string& joined, std::vector<unsigned char>& out);

  // The first refusal, phrased after the glTF's name ("the URI '../x.bin'
  // names a file outside the glTF's folder"), with its kind and hint.
  struct Refusal {
    ErrorKind kind;
    std::string message, hint;
  };
  const std::optional<Refusal>& refusal() const { return refusal_; }

  // The URI of the last file read: the buffer tinygltf stopped at when a
  // file's length is not its buffer's byteLength.
  const std::string& last_read() const { return last_read_; }

 private:
  // The URI inside `joined`, or nothing when `joined` is not below folder_.
  std::optional<std::string> uri_of(const std::string& joined) const;
  // Where the URI leads, or nothing (and a refusal) when it leads out of the folder.
  std::optional<std::filesystem::path> resolve(const std::string& uri);
  void refuse(ErrorKind kind, std::string message, std::string hint);

  std::string folder_;
  GltfFileRules rules_;
  std::optional<Refusal> refusal_;
  std::string last_read_;
};

}  // namespace vern
