// Plain `v` and `f` lines: what nearly every line of a large OBJ is.
//
// `v x y z` of three plain decimals (plain_number.hpp) and `f i j k ...` of
// plain vertex indices, blanks between them and nothing else. Reading these
// needs no tokens, and none of them is an error; anything else (a comment,
// a slash, an exponent, a fourth coordinate) is left to the reader's
// general path, which also words every error.
#pragma once

#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "io/obj_reader.hpp"
#include "io/plain_number.hpp"

namespace vern {

namespace plain_line_detail {

inline const char* skip_blanks(const char* p, const char* end) {
  while (p != end && (*p == ' ' || *p == '\t')) ++p;
  return p;
}

inline bool at_blank_or_end(const char* p, const char* end) { return p == end || *p == ' ' || *p == '\t'; }

}  // namespace plain_line_detail

// A plain vertex within kMaxObjCoordinate: true and v set.
inline bool parse_plain_vertex(std::string_view line, glm::dvec3& v) {
  using namespace plain_line_detail;
  if (line.size() <= 2 || line[0] != 'v' || line[1] != ' ') return false;
  const char* p = line.data() + 2;
  const char* const end = line.data() + line.size();
  for (int i = 0; i < 3; ++i) {
    p = scan_plain_decimal(skip_blanks(p, end), end, v[i]);
    if (p == nullptr || !at_blank_or_end(p, end) || std::abs(v[i]) > kMaxObjCoordinate) return false;
  }
  return skip_blanks(p, end) == end;
}

// A plain face of at least three indices, none 0 (whether each names a
// vertex above it is the reader's to check): true and the indices, as
// written (from 1), appended to out; false and out as it was.
inline bool parse_plain_face(std::string_view line, std::vector<std::uint32_t>& out) {
  using namespace plain_line_detail;
  if (line.size() <= 2 || line[0] != 'f' || line[1] != ' ') return false;
  const char* p = skip_blanks(line.data() + 2, line.data() + line.size());
  const char* const end = line.data() + line.size();
  const std::size_t first = out.size();
  while (p != end) {
    std::uint32_t index = 0;
    p = scan_plain_index(p, end, index);
    if (p == nullptr || !at_blank_or_end(p, end) || index == 0) {
      out.resize(first);
      return false;
    }
    out.push_back(index);
    p = skip_blanks(p, end);
  }
  if (out.size() - first < 3) {
    out.resize(first);
    return false;
  }
  return true;
}

}  // namespace vern
