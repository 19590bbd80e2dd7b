#include "inverse/load/point_grid.hpp"

#include <algorithm>
#include <cmath>

namespace vern {

namespace {
constexpr std::uint64_t kCells = std::uint64_t{1} << 21;
// Up to this many points, near() reads them all.
constexpr std::size_t kReadAll = 32;
}  // namespace

PointGrid::PointGrid(const std::vector<glm::dvec3>& points, double tolerance)
    : tolerance_(tolerance), cell_(tolerance > 0.0 ? 2.0 * tolerance : 1.0) {
  if (points.empty()) return;
  if (points.size() <= kReadAll) {
    binned_.reserve(points.size());
    for (const glm::dvec3& p : points) binned_.push_back({0, p});
    small_ = true;
    return;
  }
  origin_ = points.front();
  for (const glm::dvec3& p : points) origin_ = glm::min(origin_, p);
  binned_.reserve(points.size());
  for (const glm::dvec3& p : points) binned_.push_back({key(cell(p.x, 0), cell(p.y, 1), cell(p.z, 2)), p});
  std::sort(binned_.begin(), binned_.end(), [](const Binned& a, const Binned& b) { return a.key < b.key; });
}

std::uint64_t PointGrid::cell(double v, int axis) const {
  // Clamped cells only cost time: answers compare the points themselves.
  const double c = std::floor((v - origin_[axis]) / cell_);
  if (!(c > 0.0)) return 0;
  if (!(c < double(kCells - 1))) return kCells - 1;
  return static_cast<std::uint64_t>(c);
}

bool PointGrid::near(const glm::dvec3& p) const {
  if (small_) {
    return std::any_of(binned_.begin(), binned_.end(), [&](const Binned& b) {
      const glm::dvec3 d = glm::abs(b.point - p);
      return d.x <= tolerance_ && d.y <= tolerance_ && d.z <= tolerance_;
    });
  }
  // A point within the tolerance lies in a cell between these: a cell is
  // twice the tolerance wide, so at most two along each axis.
  std::uint64_t lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    lo[a] = cell(p[a] - tolerance_, a);
    hi[a] = cell(p[a] + tolerance_, a);
  }
  for (std::uint64_t x = lo[0]; x <= hi[0]; ++x)
    for (std::uint64_t y = lo[1]; y <= hi[1]; ++y)
      for (std::uint64_t z = lo[2]; z <= hi[2]; ++z) {
        const std::uint64_t k = key(x, y, z);
        auto it = std::lower_bound(binned_.begin(), binned_.end(), k,
                                   [](const Binned& b, std::uint64_t value) { return b.key < value; });
        for (; it != binned_.end() && it->key == k; ++it) {
          const glm::dvec3 d = glm::abs(it->point - p);
          if (d.x <= tolerance_ && d.y <= tolerance_ && d.z <= tolerance_) return true;
        }
      }
  return false;
}

bool PointGrid::covers(const std::vector<glm::dvec3>& points) const {
  return std::all_of(points.begin(), points.end(), [&](const glm::dvec3& p) { return near(p); });
}

}  // namespace vern
