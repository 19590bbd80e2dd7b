#include "forward/mesh.hpp"

namespace vern {

glm::dvec3 Mesh::min_corner() const {
  if (positions.empty()) return glm::dvec3(0.0);
  glm::dvec3 lo = positions.front();
  for (const glm::dvec3& p : positions) lo = glm::min(lo, p);
  return lo;
}

glm::dvec3 Mesh::max_corner() const {
  if (positions.empty()) return glm::dvec3(0.0);
  glm::dvec3 hi = positions.front();
  for (const glm::dvec3& p : positions) hi = glm::max(hi, p);
  return hi;
}

}  // namespace vern
