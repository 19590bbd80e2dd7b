// Compressed glTF read as plain glTF.
//
// Exporters shrink glTF files two ways, and files made for the web often
// come so: EXT_meshopt_compression packs buffer views (gltfpack,
// glTF-Transform's `meshopt`, three.js pipelines), KHR_draco_mesh_compression
// packs a whole primitive (Blender's export option "Compression",
// glTF-Transform's `draco`). Both are decoded here with Debian's libraries
// (meshoptimizer, Draco) into buffers of their own, so that every reader
// after this sees a plain file and checks it as one (gltf_rules.hpp,
// example.cpp's accessors).
//
// A meshopt file keeps its uncompressed size in a "fallback" buffer that
// holds no data; tinygltf reads a buffer without a URI as the GLB's binary
// chunk and refuses one longer than it, so such buffers are given one byte
// of data before tinygltf reads the file (prepared_for_tinygltf),
// and every view that reads them is decoded after (decode_compression). A
// view left reading a fallback buffer, data that does not decode, or
// indices and counts that do not fit are errors naming the view or the
// mesh. What is decoded counts against the file limit (--max-gltf-mib),
// as a plain file's buffers do.
//
// KHR_meshopt_compression (meshoptimizer's newer codecs) is not decoded
// by Debian 12's meshoptimizer 0.18; such files are refused, naming it.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "io/glb_chunks.hpp"

namespace vern {

// The file as tinygltf reads it, given its JSON text and, for a GLB, its
// chunks (glb_chunks, sound): every buffer that EXT_meshopt_compression
// marks as a fallback and that has no URI given one byte of data in a
// data URI, and every Draco primitive's indices left out (their accessor
// has no buffer view, which tinygltf refuses; decode_compression gives
// the primitive its decoded triangles). Nothing when there is no such
// buffer or primitive (the common file, found by one look for the
// extensions' common "_compression") or when the JSON does not parse
// (tinygltf then says why).
std::optional<std::vector<unsigned char>> prepared_for_tinygltf(std::span<const unsigned char> json,
                                                                const GlbChunks* glb);

// Decodes every EXT_meshopt_compression buffer view and every
// KHR_draco_mesh_compression primitive of `model` in place: each becomes
// plain views and accessors in new buffers, the extension object removed.
// Throws vern::Error (Input) naming `source` and the view or mesh when the
// data does not decode or does not fit, (Limit) when the decoded data
// would exceed max_bytes.
void decode_compression(tinygltf::Model& model, const std::string& source, std::uint64_t max_bytes);

}  // namespace vern
