#include "io/gltf_container.hpp"

#include <cstdint>
#include <cstring>

#include "base/error.hpp"

namespace vern {

namespace {

void put_u32(std::string& out, std::uint32_t v) {
  // GLB is little-endian, whatever the host.
  const char bytes[4] = {static_cast<char>(v & 0xff), static_cast<char>((v >> 8) & 0xff),
                         static_cast<char>((v >> 16) & 0xff), static_cast<char>((v >> 24) & 0xff)};
  out.append(bytes, 4);
}

std::uint64_t padded(std::uint64_t n) { return (n + 3) & ~std::uint64_t{3}; }

}  // namespace

std::string glb_header(std::uint64_t json_length, std::uint64_t bin_length) {
  if (bin_length % 4 != 0) throw Error(ErrorKind::Internal, "error: a GLB binary chunk not padded to 4 bytes");
  const std::uint64_t json_padded = padded(json_length);
  const std::uint64_t total = kGlbJsonOffset + json_padded + (bin_length == 0 ? 0 : 8 + bin_length);
  if (total > 0xffffffffu) {
    fail(ErrorKind::Limit, "glTF output", {}, "the scene needs " + std::to_string(total >> 20) +
                                                  " MiB, more than a GLB file can hold (4 GiB)",
         "write fewer variants per file (-o a folder), or use --instancing to store terminals compactly");
  }
  std::string header;
  header.append("glTF", 4);
  put_u32(header, 2);
  put_u32(header, static_cast<std::uint32_t>(total));
  put_u32(header, static_cast<std::uint32_t>(json_padded));
  header.append("JSON", 4);
  return header;
}

std::string glb_between(std::uint64_t json_length, std::uint64_t bin_length) {
  std::string out(padded(json_length) - json_length, ' ');
  if (bin_length != 0) {
    put_u32(out, static_cast<std::uint32_t>(bin_length));
    out.append("BIN\0", 4);
  }
  return out;
}

std::string base64(std::string_view bytes) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 3 <= bytes.size(); i += 3) {
    const std::uint32_t v = static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i])) << 16 |
                            static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i + 1])) << 8 |
                            static_cast<unsigned char>(bytes[i + 2]);
    out += kDigits[v >> 18];
    out += kDigits[(v >> 12) & 63];
    out += kDigits[(v >> 6) & 63];
    out += kDigits[v & 63];
  }
  const std::size_t rest = bytes.size() - i;
  if (rest > 0) {
    std::uint32_t v = static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i])) << 16;
    if (rest == 2) v |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i + 1])) << 8;
    out += kDigits[v >> 18];
    out += kDigits[(v >> 12) & 63];
    out += rest == 2 ? kDigits[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

}  // namespace vern
