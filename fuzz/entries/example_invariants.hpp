// What every loaded mesh, example and primitive library must satisfy,
// whatever file it came from: the promises inference and derivation build on.
#pragma once

#include <string>

#include "forward/mesh.hpp"
#include "forward/primitive_library.hpp"
#include "inverse/load/example.hpp"

namespace vern::fuzz {

// "" or what is broken: every face has >= 3 corners and the corners add
// up; every index is in range (or kNone for normals and uvs); every number
// is finite.
std::string mesh_invariants(const Mesh& mesh);

// "" or what is broken: at least one box; each box has a label and an
// object name, finite bounds with min <= max, not a single point, and a
// mesh whose bounds are the box's; the example's bounds enclose the boxes.
std::string example_invariants(const Example& example);

// "" or what is broken: every primitive's name is a label, and its mesh
// has faces, keeps the mesh invariants and fills the unit box (bounds from
// 0 to 1 on each axis, or 0 to 0 on an axis along which it is flat).
std::string library_invariants(const PrimitiveLibrary& library);

}  // namespace vern::fuzz
