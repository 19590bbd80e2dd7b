#include "io/glb_chunks.hpp"

#include <cstdint>
#include <cstring>

namespace vern {

namespace {

constexpr std::uint32_t kJson = 0x4E4F534A, kBin = 0x004E4942;
constexpr std::size_t kHeader = 12, kChunkHeader = 8;

std::uint32_t word(std::span<const unsigned char> bytes, std::size_t at) {
  std::uint32_t v = 0;
  std::memcpy(&v, bytes.data() + at, 4);  // GLB is little-endian, as every target of ours
  return v;
}

GlbChunks refused(std::string problem) {
  GlbChunks out;
  out.problem = std::move(problem);
  return out;
}

}  // namespace

GlbChunks glb_chunks(std::span<const unsigned char> bytes) {
  if (bytes.size() < kHeader) return refused("it ends inside the 12-byte GLB header");
  if (std::memcmp(bytes.data(), "glTF", 4) != 0) return refused("it does not start with the magic 'glTF'");
  if (const std::uint32_t version = word(bytes, 4); version != 2) {
    return refused("its header says container version " + std::to_string(version) +
                   "; only version 2 (glTF 2.0) is read");
  }
  if (word(bytes, 8) != bytes.size()) return refused("the length its header gives is not the file's length");
  GlbChunks out;
  std::size_t at = kHeader;
  for (std::size_t chunk = 0; at < bytes.size(); ++chunk) {
    const std::string which = "chunk " + std::to_string(chunk);
    if (bytes.size() - at < kChunkHeader) return refused(which + " ends inside its 8-byte header");
    const std::uint64_t length = word(bytes, at);
    const std::uint32_t type = word(bytes, at + 4);
    at += kChunkHeader;
    if (length > bytes.size() - at) return refused(which + " runs past the end of the file");
    if (length % 4 != 0) return refused(which + "'s length is not a multiple of 4: chunks are 4-byte aligned");
    const std::span<const unsigned char> data = bytes.subspan(at, length);
    at += length;
    if (chunk == 0) {
      if (type != kJson) return refused("its first chunk is not the JSON chunk");
      if (length == 0) return refused("its JSON chunk is empty");
      out.json = data;
    } else if (type == kJson) {
      return refused("it has a second JSON chunk (" + which + ")");
    } else if (type == kBin) {
      if (chunk != 1) return refused("its BIN chunk is " + which + ", not chunk 1 right after the JSON chunk");
      out.bin = data;
      out.has_bin = true;
    }
    // Chunks of other types are for extensions: skipped, as glTF asks.
  }
  if (out.json.empty()) return refused("it has no JSON chunk");
  return out;
}

}  // namespace vern
