// Building Scenes by hand for the writer tests.
#pragma once

#include "forward/terminal.hpp"

namespace vern::test {

// A scope's frame turned a quarter about z: its x axis points along world y.
inline const glm::dmat3 kQuarterTurnZ(glm::dvec3(0, 1, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, 1));

inline Terminal terminal(LabelId label, glm::dvec3 origin, glm::dvec3 size, glm::dmat3 frame = glm::dmat3(1.0)) {
  Terminal t;
  t.label = label;
  t.scope.origin = origin;
  t.scope.size = size;
  t.scope.frame = frame;
  return t;
}

}  // namespace vern::test
