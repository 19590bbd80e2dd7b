#include "inverse/load/snapped_coordinates.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "inverse/load/coordinate_clusters.hpp"

namespace vern {
namespace {

// The snapped value of every bound on one axis: bound 2b is box b's min,
// 2b + 1 its max.
std::vector<double> snapped_axis(const std::vector<LabelledBox>& boxes, int axis, double tolerance) {
  const std::size_t n = boxes.size() * 2;
  std::vector<double> value(n);
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    value[2 * b] = boxes[b].min[axis];
    value[2 * b + 1] = boxes[b].max[axis];
  }
  std::vector<std::uint32_t> order(n);
  for (std::uint32_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return value[a] < value[b] || (value[a] == value[b] && a < b);
  });
  const std::vector<std::uint32_t> starts = cluster_starts(
      static_cast<std::uint32_t>(n), [&](std::uint32_t i) { return value[order[i]]; }, tolerance);
  // Each cluster's place: its median bound, one of the values the file
  // holds, where most parts put it...
  const std::size_t clusters = starts.size();
  std::vector<double> place(clusters), lo(clusters), hi(clusters);
  for (std::size_t c = 0; c < clusters; ++c) {
    const std::uint32_t first = starts[c], end = c + 1 < clusters ? starts[c + 1] : static_cast<std::uint32_t>(n);
    lo[c] = value[order[first]];
    hi[c] = value[order[end - 1]];
    place[c] = value[order[first + (end - first - 1) / 2]];
  }
  // ...moved within its cluster, where it can, to lie more than the noise
  // level past the place before it: two neighbouring clusters together
  // span more than the level (they would be one otherwise), so places a
  // level apart keep no sliver thinner than the noise between them.
  const double apart = tolerance * (1 + 1e-9);  // more than the level, not on it
  for (std::size_t c = 1; c < clusters; ++c)
    if (place[c] - place[c - 1] <= tolerance) place[c] = std::min(hi[c], std::max(place[c], place[c - 1] + apart));
  for (std::size_t c = clusters; c-- > 1;)
    if (place[c] - place[c - 1] <= tolerance) place[c - 1] = std::max(lo[c - 1], std::min(place[c - 1], place[c] - apart));
  std::vector<double> out(n);
  for (std::size_t c = 0; c < clusters; ++c) {
    const std::uint32_t first = starts[c], end = c + 1 < clusters ? starts[c + 1] : static_cast<std::uint32_t>(n);
    for (std::uint32_t i = first; i < end; ++i) out[order[i]] = place[c];
  }
  return out;
}

}  // namespace

Example snapped_coordinates(const Example& example, double tolerance) {
  Example out;
  out.source = example.source;
  out.meshes = example.meshes;
  out.boxes = example.boxes;
  out.snapped = tolerance;
  out.file_tolerance = example.file_tolerance;
  std::vector<double> bound[3];
  for (int axis = 0; axis < 3; ++axis) bound[axis] = snapped_axis(example.boxes, axis, tolerance);
  const bool positions = example.positions.size() == example.boxes.size();
  std::vector<glm::dvec3> at;
  for (std::size_t b = 0; b < out.boxes.size(); ++b) {
    LabelledBox& box = out.boxes[b];
    glm::dvec3 lo, hi;
    for (int axis = 0; axis < 3; ++axis) {
      lo[axis] = bound[axis][2 * b];
      hi[axis] = bound[axis][2 * b + 1];
    }
    if (positions) {
      example.positions.get(b, box.min, box.max, at);
      for (glm::dvec3& p : at) {
        for (int axis = 0; axis < 3; ++axis) {
          if (p[axis] == box.min[axis]) p[axis] = lo[axis];
          else if (p[axis] == box.max[axis]) p[axis] = hi[axis];
        }
      }
      out.positions.add(at, lo, hi);
    }
    box.min = lo;
    box.max = hi;
  }
  update_bounds(out);
  return out;
}

double largest_move(const Example& as_read, const Example& snapped) {
  double most = 0;
  for (std::size_t b = 0; b < as_read.boxes.size() && b < snapped.boxes.size(); ++b) {
    const glm::dvec3 lo = glm::abs(as_read.boxes[b].min - snapped.boxes[b].min);
    const glm::dvec3 hi = glm::abs(as_read.boxes[b].max - snapped.boxes[b].max);
    most = std::max({most, lo.x, lo.y, lo.z, hi.x, hi.y, hi.z});
  }
  return most;
}

}  // namespace vern
