#include "forward/layout_faults.hpp"

#include <algorithm>
#include <numeric>
#include <vector>

#include "base/number_format.hpp"

namespace vern {

namespace {

std::string describe(const Derivation& d, std::size_t i) {
  return "'" + d.labels[d.terminals[i].label] + "' #" + std::to_string(i);
}

}  // namespace

LayoutFaults find_faults(const Derivation& d, double tolerance) {
  const glm::dvec3& size = d.start.size;
  if (tolerance <= 0) tolerance = std::max(1e-9, 1e-6 * std::max({size.x, size.y, size.z}));
  LayoutFaults faults;
  const Bounds plot = world_bounds(d.start);

  std::vector<Bounds> bounds(d.terminals.size());
  std::vector<std::size_t> solid;  // parts with volume, by index
  for (std::size_t i = 0; i < d.terminals.size(); ++i) {
    const Bounds b = world_bounds(d.terminals[i].scope);
    bounds[i] = b;
    bool inside = true;
    for (int a = 0; a < 3; ++a) inside = inside && b.min[a] >= plot.min[a] - tolerance && b.max[a] <= plot.max[a] + tolerance;
    if (!inside) {
      if (faults.first.empty()) faults.first = describe(d, i) + " reaches outside the start scope";
      ++faults.outside;
    }
    const glm::dvec3 extent = b.max - b.min;
    if (extent.x > tolerance && extent.y > tolerance && extent.z > tolerance) solid.push_back(i);
  }

  // Sweep along x: parts sorted by their low x; a part is compared with the
  // earlier ones whose x range it still reaches into.
  std::sort(solid.begin(), solid.end(), [&](std::size_t a, std::size_t b) {
    return bounds[a].min.x < bounds[b].min.x || (bounds[a].min.x == bounds[b].min.x && a < b);
  });
  std::vector<std::size_t> active;
  for (const std::size_t i : solid) {
    const Bounds& b = bounds[i];
    std::erase_if(active, [&](std::size_t j) { return bounds[j].max.x <= b.min.x + tolerance; });
    for (const std::size_t j : active) {
      glm::dvec3 depth;
      for (int a = 0; a < 3; ++a) depth[a] = std::min(b.max[a], bounds[j].max[a]) - std::max(b.min[a], bounds[j].min[a]);
      if (depth.x > tolerance && depth.y > tolerance && depth.z > tolerance) {
        if (faults.first.empty()) {
          faults.first = describe(d, i) + " overlaps " + describe(d, j) + " by " + format_number(depth.x) + " x " +
                         format_number(depth.y) + " x " + format_number(depth.z);
        }
        ++faults.overlaps;
      }
    }
    active.push_back(i);
  }
  return faults;
}

}  // namespace vern
