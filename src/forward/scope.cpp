#include "forward/scope.hpp"

#include <cmath>
#include <numbers>

namespace vern {

bool within_reach(const Scope& s) {
  // A corner's coordinate k is origin[k] + sum of frame[i][k] * u_i * size[i]
  // with u_i in [0, 1]: at most this far from 0.
  for (int k = 0; k < 3; ++k) {
    double reach = std::abs(s.origin[k]);
    for (int i = 0; i < 3; ++i) reach += std::abs(s.frame[i][k]) * s.size[i];
    if (!(reach <= kMaxDerivedCoordinate)) return false;
  }
  return true;
}

Bounds world_bounds(const Scope& s) {
  Bounds b{s.origin, s.origin};
  for (int corner = 1; corner < 8; ++corner) {
    const glm::dvec3 u{double(corner & 1), double((corner >> 1) & 1), double((corner >> 2) & 1)};
    const glm::dvec3 p = s.to_world(u);
    b.min = glm::min(b.min, p);
    b.max = glm::max(b.max, p);
  }
  return b;
}

Scope rotated(const Scope& s, Axis axis, double angle) {
  const int a = static_cast<int>(axis);
  const int u = (a + 1) % 3;  // the two axes the turn moves: u -> v
  const int v = (a + 2) % 3;
  // Quarter turns are exact so axis-aligned buildings stay exactly aligned
  // (cos(pi/2) is 6e-17 in floating point, which would tilt every part).
  const double quarters = angle / (std::numbers::pi / 2);
  const double nearest = std::round(quarters);
  double c, sn;
  bool odd_quarter = false;
  if (std::abs(quarters - nearest) * (std::numbers::pi / 2) < 1e-9) {
    const int q = static_cast<int>(std::fmod(std::fmod(nearest, 4.0) + 4.0, 4.0));
    constexpr double kCos[4] = {1, 0, -1, 0};
    constexpr double kSin[4] = {0, 1, 0, -1};
    c = kCos[q];
    sn = kSin[q];
    odd_quarter = q % 2 == 1;
  } else {
    c = std::cos(angle);
    sn = std::sin(angle);
  }
  // Turn the frame about its own axis a (right-handed, counter-clockwise
  // seen from the positive end of the axis).
  Scope r = s;
  r.frame[u] = c * s.frame[u] + sn * s.frame[v];
  r.frame[v] = -sn * s.frame[u] + c * s.frame[v];
  if (odd_quarter) std::swap(r.size[u], r.size[v]);
  const glm::dvec3 centre = s.to_world(glm::dvec3(0.5));
  r.origin = centre - r.frame * (r.size * 0.5);
  return r;
}

Scope face_scope(const Scope& s, Face face) {
  const glm::dvec3 X = s.frame[0], Y = s.frame[1], Z = s.frame[2];
  const glm::dvec3 L = s.size;
  switch (face) {
    case Face::Front: return {s.origin, glm::dmat3(X, Z, -Y), {L.x, L.z, 0}};
    case Face::Back: return {s.origin + X * L.x + Y * L.y, glm::dmat3(-X, Z, Y), {L.x, L.z, 0}};
    case Face::Right: return {s.origin + X * L.x, glm::dmat3(Y, Z, X), {L.y, L.z, 0}};
    case Face::Left: return {s.origin + Y * L.y, glm::dmat3(-Y, Z, -X), {L.y, L.z, 0}};
    case Face::Top: return {s.origin + Z * L.z, glm::dmat3(X, Y, Z), {L.x, L.y, 0}};
    case Face::Bottom: return {s.origin + Y * L.y, glm::dmat3(X, -Y, -Z), {L.x, L.y, 0}};
  }
  return s;
}

}  // namespace vern
