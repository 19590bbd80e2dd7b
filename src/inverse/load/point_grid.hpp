// Whether points lie within a tolerance of one of a set of points.
//
// Matching a part's vertices against its label's mesh (orientation.cpp)
// asks this for every vertex. Points sorted by x alone made each question
// read every point of about the same x: all of them for a flat panel, so a
// million-face part took minutes. Here the points are binned into cells
// twice the tolerance wide, and a question reads the at most 8 cells that
// can hold an answer: linear in the points, whatever their shape. A few
// points (a box's 8 to 24 corners, most parts) are simply read in turn:
// cheaper than binning and sorting them.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace vern {

class PointGrid {
 public:
  PointGrid(const std::vector<glm::dvec3>& points, double tolerance);

  // Whether some point lies within the tolerance of p on every axis.
  bool near(const glm::dvec3& p) const;

  // Whether every one of `points` is near().
  bool covers(const std::vector<glm::dvec3>& points) const;

 private:
  // A coordinate's cell along an axis, counted from the points' lowest
  // corner and clamped to 21 bits (a key holds three).
  std::uint64_t cell(double v, int axis) const;
  static std::uint64_t key(std::uint64_t x, std::uint64_t y, std::uint64_t z) { return (x << 42) | (y << 21) | z; }

  struct Binned {
    std::uint64_t key;
    glm::dvec3 point;
  };
  double tolerance_ = 0.0;
  double cell_ = 1.0;
  glm::dvec3 origin_{0.0};
  std::vector<Binned> binned_;  // sorted by key; in their order, unbinned, when few
  bool small_ = false;
};

}  // namespace vern
