// The two ways a glTF document carries its binary buffer: a GLB file (JSON
// chunk + BIN chunk) or, in a .gltf text file, a base64 data URI.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace vern {

// Bytes a GLB file has before its JSON text: the file header (12) and the
// JSON chunk's header (8).
inline constexpr std::size_t kGlbJsonOffset = 20;

// A GLB file is a 12-byte header, the JSON chunk (its 8-byte header, the
// text padded with spaces to 4 bytes), then, when the binary buffer is not
// empty, the BIN chunk (8-byte header, the bytes padded with zeros to 4).
// The pieces are given apart so that a large scene is written as it is
// read back from where it waited, never joined in memory.

// The kGlbJsonOffset bytes before a JSON text of json_length bytes, in a
// file whose BIN chunk holds bin_length bytes (a multiple of 4; 0: none).
// Throws vern::Error (Limit) past GLB's 4 GiB.
std::string glb_header(std::uint64_t json_length, std::uint64_t bin_length);

// The spaces after a JSON text of json_length bytes, then the BIN chunk's
// header when bin_length is not 0.
std::string glb_between(std::uint64_t json_length, std::uint64_t bin_length);

// RFC 4648 base64 with padding, as data URIs want it.
std::string base64(std::string_view bytes);

}  // namespace vern
