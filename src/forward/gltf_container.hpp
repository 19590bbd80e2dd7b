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

// A GLB file is 12-byte header, the JSON chunk padded with spaces to 4
// bytes, then (when bin is not empty) the BIN chunk. glb_head completes, in
// place, `file` (kGlbJsonOffset bytes of room, then the JSON text, whose
// buffer 0 describes bin) up to the BIN chunk's header; `bin`, already
// padded to 4 bytes with zeros, follows it. Two pieces, so a large scene is
// written without joining them in memory. Throws vern::Error (Limit) past
// GLB's 4 GiB.
std::string glb_head(std::string file, std::string_view bin);

// RFC 4648 base64 with padding, as data URIs want it.
std::string base64(std::string_view bytes);

}  // namespace vern
