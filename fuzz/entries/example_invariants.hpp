// What every loaded mesh and example must satisfy, whatever file it came
// from: the promises inference builds on.
#pragma once

#include <string>

#include "forward/mesh.hpp"
#include "inverse/example.hpp"

namespace vern::fuzz {

// "" or what is broken: every face has >= 3 corners and the corners add
// up; every index is in range (or kNone for normals and uvs); every number
// is finite.
std::string mesh_invariants(const Mesh& mesh);

// "" or what is broken: at least one box; each box has a label and an
// object name, finite bounds with min <= max, not a single point, and a
// mesh whose bounds are the box's; the example's bounds enclose the boxes.
std::string example_invariants(const Example& example);

}  // namespace vern::fuzz
