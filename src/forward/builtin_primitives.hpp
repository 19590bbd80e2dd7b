// The built-in primitives' OBJ text, compiled into the library from
// data/primitives/ (see cmake/embed_primitives.cmake).
#pragma once

#include <span>
#include <string_view>

namespace vern {

struct EmbeddedPrimitive {
  std::string_view name;      // file name without .obj: the primitive's label
  std::string_view obj_text;  // the file's contents
};

std::span<const EmbeddedPrimitive> builtin_primitive_sources();

}  // namespace vern
