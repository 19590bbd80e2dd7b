// Every part's vertex positions, kept compactly for matching turns
// (orientation.hpp), which compares each part's vertices with its label's
// canonical mesh.
//
// Exported boxes and most primitives have all their vertices on corners of
// their own bounding box: such a vertex is kept as one byte, a bit per axis
// saying whether it sits at the box's min or max. A part with any other
// vertex keeps its positions as they are. Either way the positions come
// back as the very same doubles, in the same order.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace vern {

class PartPositions {
 public:
  // Appends the next part's positions; `min` and `max` are their bounds.
  void add(std::span<const glm::dvec3> positions, const glm::dvec3& min, const glm::dvec3& max);

  std::size_t size() const { return parts_.size(); }

  // Part `part`'s positions into `out` (replacing what it held), given the
  // bounds it was added with.
  void get(std::size_t part, const glm::dvec3& min, const glm::dvec3& max, std::vector<glm::dvec3>& out) const;

 private:
  struct Part {
    std::uint32_t first = 0;  // in corners_, or in exact_ when `exact`
    std::uint32_t count : 31 = 0;
    std::uint32_t exact : 1 = 0;
  };
  std::vector<Part> parts_;
  std::vector<std::uint8_t> corners_;  // bit k: at max (1) or min (0) on axis k
  std::vector<glm::dvec3> exact_;
};

}  // namespace vern
