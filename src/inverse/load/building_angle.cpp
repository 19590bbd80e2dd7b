// CGAL is used here alone: the outlines' hulls and smallest rectangles.
#include "inverse/load/building_angle.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/min_quadrilateral_2.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numbers>
#include <vector>

namespace vern {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;

constexpr double kQuarter = std::numbers::pi / 2;

// An angle taken modulo a quarter turn, in [0, pi/2).
double modulo_quarter(double a) {
  a = std::fmod(a, kQuarter);
  return a < 0 ? a + kQuarter : a;
}

// How far apart two angles are, modulo a quarter turn.
double apart(double a, double b) {
  const double d = std::abs(modulo_quarter(a) - modulo_quarter(b));
  return std::min(d, kQuarter - d);
}

// Whether every position lies on a corner of the box in x and y: a part
// along the axes (the common case, settled without a hull).
bool along_axes(const std::vector<glm::dvec3>& at, const LabelledBox& box) {
  return std::all_of(at.begin(), at.end(), [&](const glm::dvec3& p) {
    return (p.x == box.min.x || p.x == box.max.x) && (p.y == box.min.y || p.y == box.max.y);
  });
}

// The angle of a part's outline from above when it is square (its hull
// is its smallest enclosing rectangle, or a segment: a flat panel), with
// how long it is (the longer, the more precise its angle).
struct Outline {
  double angle = 0, extent = 0;
};
std::optional<Outline> square_outline(const std::vector<glm::dvec3>& at, double tolerance) {
  std::vector<Point> points, hull;
  points.reserve(at.size());
  for (const glm::dvec3& p : at) points.emplace_back(p.x, p.y);
  CGAL::convex_hull_2(points.begin(), points.end(), std::back_inserter(hull));
  if (hull.size() < 2) return std::nullopt;
  if (hull.size() == 2) {
    const double dx = hull[1].x() - hull[0].x(), dy = hull[1].y() - hull[0].y();
    const double length = std::hypot(dx, dy);
    if (length <= tolerance) return std::nullopt;
    return Outline{modulo_quarter(std::atan2(dy, dx)), length};
  }
  std::vector<Point> rectangle;
  CGAL::min_rectangle_2(hull.begin(), hull.end(), std::back_inserter(rectangle));
  if (rectangle.size() != 4) return std::nullopt;
  const double dx = rectangle[1].x() - rectangle[0].x(), dy = rectangle[1].y() - rectangle[0].y();
  const double side = std::hypot(dx, dy);
  const double other = std::hypot(rectangle[2].x() - rectangle[1].x(), rectangle[2].y() - rectangle[1].y());
  const double hull_area = std::abs(CGAL::polygon_area_2(hull.begin(), hull.end(), Kernel()));
  // Square: the rectangle adds no more than a tolerance-wide band to it.
  if (side * other - hull_area > tolerance * (side + other) * 2) return std::nullopt;
  return Outline{modulo_quarter(std::atan2(dy, dx)), std::max(side, other)};
}

glm::dvec3 turned(const glm::dvec3& p, const glm::dvec3& centre, double c, double s) {
  const double x = p.x - centre.x, y = p.y - centre.y;
  return {centre.x + c * x - s * y, centre.y + s * x + c * y, p.z};
}

}  // namespace

std::optional<double> building_angle(const Example& example, double tolerance) {
  if (example.positions.size() != example.boxes.size()) return std::nullopt;
  std::vector<glm::dvec3> at;
  std::optional<Outline> first;
  double longest = 0;
  std::vector<Outline> square;
  for (std::size_t b = 0; b < example.boxes.size(); ++b) {
    const LabelledBox& box = example.boxes[b];
    example.positions.get(b, box.min, box.max, at);
    if (along_axes(at, box)) return std::nullopt;
    const std::optional<Outline> o = square_outline(at, tolerance);
    if (!o) continue;
    square.push_back(*o);
    if (o->extent > longest) {
      longest = o->extent;
      first = o;
    }
  }
  if (!first) return std::nullopt;
  // One angle: each part's within the tolerance at its extent.
  for (const Outline& o : square)
    if (apart(o.angle, first->angle) * o.extent > tolerance) return std::nullopt;
  if (std::min(first->angle, kQuarter - first->angle) * first->extent <= tolerance) return std::nullopt;
  return first->angle;
}

Example turned_back(const Example& example, double angle) {
  Example out;
  out.source = example.source;
  out.snapped = example.snapped;
  out.file_tolerance = example.file_tolerance;
  const glm::dvec3 centre = (example.min + example.max) / 2.0;
  const double c = std::cos(-angle), s = std::sin(-angle);
  const bool positions = example.positions.size() == example.boxes.size();
  std::vector<glm::dvec3> at;
  for (std::size_t b = 0; b < example.boxes.size(); ++b) {
    LabelledBox box = example.boxes[b];
    if (positions) {
      example.positions.get(b, box.min, box.max, at);
    } else {
      at.clear();
      for (int k = 0; k < 8; ++k)
        at.push_back({k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z});
    }
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    for (glm::dvec3& p : at) {
      p = turned(p, centre, c, s);
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    box.min = lo;
    box.max = hi;
    if (positions) out.positions.add(at, lo, hi);
    out.boxes.push_back(std::move(box));
  }
  out.meshes = example.meshes;
  for (Mesh& m : out.meshes) {
    for (glm::dvec3& p : m.positions) p = turned(p, centre, c, s);
    for (glm::dvec3& n : m.normals) n = turned(n, glm::dvec3(0.0), c, s);
  }
  update_bounds(out);
  return out;
}

}  // namespace vern
