// The two ways a glTF document carries its binary buffer: a GLB file (JSON
// chunk + BIN chunk) or, in a .gltf text file, a base64 data URI.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace vern {

// Bytes a GLB file has before its JSON text: the file header (12) and the
// JSON chunk's header (8).
inline constexpr std::size_t kGlbJsonOffset = 20;

// A GLB file: 12-byte header, the JSON chunk padded with spaces to 4 bytes,
// then (when bin is not empty) the BIN chunk padded with zeros. The JSON's
// buffer 0 must describe bin (its byteLength at most bin's size).
// `file` holds kGlbJsonOffset bytes of room, then the JSON text; the file
// is completed in place, so a large document is not copied.
std::string glb_file(std::string file, std::string_view bin);

// RFC 4648 base64 with padding, as data URIs want it.
std::string base64(std::string_view bytes);

}  // namespace vern
