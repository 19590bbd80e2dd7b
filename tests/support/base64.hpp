// Bytes as base64 text, for glTF data URIs written by tests.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace vern::test {

inline std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t got = bytes.size() - i < 3 ? bytes.size() - i : 3;
    std::uint32_t chunk = 0;
    for (std::size_t k = 0; k < 3; ++k) chunk = (chunk << 8) | (k < got ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k) out += k <= got ? digits[(chunk >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

}  // namespace vern::test
