#include "inverse/load/part_positions.hpp"

#include <cstring>

namespace vern {

namespace {

// Bit for bit, so that -0.0 stays -0.0 when read back.
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

void PartPositions::add(std::span<const glm::dvec3> positions, const glm::dvec3& min, const glm::dvec3& max) {
  Part part;
  part.count = static_cast<std::uint32_t>(positions.size()) & 0x7FFFFFFFu;
  part.first = static_cast<std::uint32_t>(corners_.size());
  for (const glm::dvec3& p : positions) {
    std::uint8_t code = 0;
    for (int axis = 0; axis < 3; ++axis) {
      if (same_bits(p[axis], max[axis])) code |= static_cast<std::uint8_t>(1u << axis);
      else if (!same_bits(p[axis], min[axis])) part.exact = 1;
    }
    if (part.exact) break;
    corners_.push_back(code);
  }
  if (part.exact) {
    corners_.resize(part.first);
    part.first = static_cast<std::uint32_t>(exact_.size());
    exact_.insert(exact_.end(), positions.begin(), positions.end());
  }
  parts_.push_back(part);
}

void PartPositions::get(std::size_t part, const glm::dvec3& min, const glm::dvec3& max,
                        std::vector<glm::dvec3>& out) const {
  const Part& p = parts_[part];
  out.clear();
  if (p.exact) {
    out.assign(exact_.begin() + p.first, exact_.begin() + p.first + p.count);
    return;
  }
  for (std::uint32_t i = 0; i < p.count; ++i) {
    const std::uint8_t code = corners_[p.first + i];
    out.emplace_back(code & 1 ? max.x : min.x, code & 2 ? max.y : min.y, code & 4 ? max.z : min.z);
  }
}

}  // namespace vern
