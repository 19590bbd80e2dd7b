// Terminals: what a derivation produces, and what the writers consume.
#pragma once

#include <string>
#include <vector>

#include "forward/scope.hpp"
#include "graph/node.hpp"

namespace vern {

struct Rgb {
  float red = 0, green = 0, blue = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

// One inserted primitive: its label (an index into the grammar's label
// table), the scope its unit mesh fills, and a colour if colour() set one.
struct Terminal {
  LabelId label = 0;
  bool coloured = false;
  Rgb colour;
  Scope scope;
};

// A set of derived buildings laid out for writing: each variant is moved by
// its offset and becomes one named group (glTF node, OBJ comment).
struct Variant {
  std::string name;
  glm::dvec3 offset{0.0};
  std::vector<Terminal> terminals;
};

struct Scene {
  std::vector<std::string> labels;  // LabelId -> primitive name
  std::vector<Variant> variants;
};

}  // namespace vern
