// What reading a JSON text costs in memory, told by one quick pass over it.
//
// tinygltf reads a .gltf's JSON (and a GLB's that plain_glb.hpp declines)
// into an nlohmann::json document, then into its model: each value takes
// far more memory than its text. A number in an array, 2 bytes written
// ("1,"), takes some 200 bytes read; an empty material ("{},", 3 bytes)
// some 3.5 KB; an 18 MB file of them takes 2 to 4 GB and minutes. The
// glTF loader weighs the text here before any reader sees it and refuses
// a file whose reading would cost more than its limit: memory then follows
// the limit, not the file's shape.
//
// The pass also finds nesting deeper than a bound: tinygltf reads `extras`
// and `extensions` recursively, and 200,000 '[' overflow its stack.
//
// The pass only counts: it does not check the text is JSON (the reader
// after it does), and reads any text to its end in linear time.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "base/error.hpp"

namespace vern {

struct JsonCost {
  // Upper bounds of what reading takes beyond the text itself: memory
  // per value, as measured on tinygltf 2.7 (json_cost.cpp).
  std::uint64_t values = 0;  // members of objects and elements of arrays
  std::uint64_t bytes = 0;   // memory, in bytes
  // Where nesting first goes deeper than max_depth (an offset into the
  // text), or npos when it never does.
  std::size_t too_deep_at = npos;

  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
};

// The cost of reading `text`; counting stops where it nests deeper than
// max_depth (the top value is depth 1).
JsonCost json_cost(std::string_view text, std::size_t max_depth);

// Line and column (from 1, in bytes) of an offset into a text.
SourceLoc text_location(std::string_view text, std::size_t offset);

}  // namespace vern
