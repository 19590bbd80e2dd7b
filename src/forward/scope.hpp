// Scopes: the oriented boxes that operations cut, move and fill.
//
// A scope is an origin corner, an orthonormal right-handed frame (its
// columns are the scope's x, y and z axes in world space) and a size along
// each of those axes. The box it stands for is
//   { origin + frame * (u * size) : u in [0,1]^3 }.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "graph/node.hpp"
#include "graph/value.hpp"

namespace vern {

struct Scope {
  glm::dvec3 origin{0.0};
  glm::dmat3 frame{1.0};
  glm::dvec3 size{1.0};

  // A point given in unit-box coordinates, in world space.
  glm::dvec3 to_world(const glm::dvec3& unit) const { return origin + frame * (unit * size); }

  // The size along an axis. (glm's operator[] on a vector is a switch over
  // the index; the derivation's hot path asks for sizes by runtime axis.)
  double extent(Axis axis) const { return glm::value_ptr(size)[static_cast<int>(axis)]; }

  // The part [from, from + length) along an axis.
  Scope slice(Axis axis, double from, double length) const {
    Scope s = *this;
    s.slice_in_place(axis, from, length);
    return s;
  }

  // The same, on this scope when it is a copy already.
  void slice_in_place(Axis axis, double from, double length) {
    const auto a = static_cast<int>(axis);
    origin += frame[a] * from;
    glm::value_ptr(size)[a] = length;
  }

  friend bool operator==(const Scope&, const Scope&) = default;
};

// How far from the origin a derived scope may reach on any axis, in
// metres. Outputs hold coordinates as finite numbers, some as 32-bit floats
// (glTF instancing), which end at 3.4e38; a box within +-1e38 has sizes up
// to 2e38. A grammar that moves, scales or turns a scope past it fails
// there (derive.cpp) rather than writing inf.
inline constexpr double kMaxDerivedCoordinate = 1e38;

// Whether every corner of s lies within +-kMaxDerivedCoordinate (a NaN
// does not). Splits, repeats and comp cut a scope into parts inside it, so
// only the operations that move or grow one need to ask.
bool within_reach(const Scope& s);

// The world-space axis-aligned bounds of a scope (min and max corners).
struct Bounds {
  glm::dvec3 min{0.0};
  glm::dvec3 max{0.0};
};
Bounds world_bounds(const Scope& s);

// R(axis, angle) applied to a scope: the same centre, the frame turned by
// angle about the scope's own axis. Multiples of pi/2 (within 1e-9 rad) are
// snapped to exact quarter turns and swap the two other sizes on odd
// multiples, so the child occupies exactly the parent's box.
Scope rotated(const Scope& s, Axis axis, double angle);

// The face scopes of comp(f): x along the face, y up the face, z the
// outward normal, zero thickness, each frame right-handed (docs/grammar.md).
// Front is the face at y = 0, back at y = max, left x = 0, right x = max,
// bottom z = 0, top z = max.
Scope face_scope(const Scope& s, Face face);

}  // namespace vern
