// Small helpers for tests that derive grammars given as text.
#pragma once

#include <string>
#include <vector>

#include "forward/derive.hpp"
#include "graph/parser.hpp"

namespace vern::test {

// Parses text and derives it on an axis-aligned scope of the given size.
Derivation derive_text(const std::string& text, glm::dvec3 size, std::uint64_t seed = 1);

// The world bounds of every terminal, as {min, max} pairs, with labels.
struct LabelledBox {
  std::string label;
  glm::dvec3 min, max;
};
std::vector<LabelledBox> boxes(const Derivation& d);

// Every data/grammars/*.grm file, sorted.
std::vector<std::string> bundled_grammars();

}  // namespace vern::test
