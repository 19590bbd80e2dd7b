// Recognising turned primitives (issue 4, "Rotations"): a part whose mesh
// is its label's canonical mesh turned by quarter turns is written as
// R(axis, angle){ I(label) }, so generated buildings show it turned as the
// example did (the thesis had to label such parts by hand).
//
// A turn is tested the way the forward engine applies it: the part's box is
// the scope, the R operations turn it (scope.hpp, rotated), and the
// canonical unit mesh placed in the turned scope must land on the part's
// own vertices. The 24 turns of a box are all reached by at most two
// quarter turns; the fewest that match win, so a symmetric mesh (a box)
// is never turned.
#pragma once

#include <optional>
#include <vector>

#include "forward/mesh.hpp"
#include "forward/primitive_library.hpp"
#include "graph/grammar.hpp"
#include "graph/value.hpp"
#include "inverse/load/example.hpp"

namespace vern {

struct QuarterTurn {
  Axis axis = Axis::Z;
  int quarters = 1;  // 1, 2 or 3: R(axis, quarters * pi / 2)
  friend bool operator==(const QuarterTurn&, const QuarterTurn&) = default;
};

// Outermost turn first; empty: the mesh as it is.
using Orientation = std::vector<QuarterTurn>;

// The turns under which `canonical` (a mesh in the unit box) placed in the
// box [box_min, box_max] has the same vertex positions as `placed` (a
// part's, world space), each within `tolerance`; nullopt when no turn fits
// (another shape under the same label).
std::optional<Orientation> find_orientation(const Mesh& canonical, const std::vector<glm::dvec3>& placed,
                                            glm::dvec3 box_min, glm::dvec3 box_max, double tolerance);

// I(label) inside R nodes for `turns`, interned in g; angles written as
// multiples of pi ("pi / 2", "pi", "3 * pi / 2").
NodeId turned_primitive(Grammar& g, LabelId label, const Orientation& turns);

// Any node inside R nodes for `turns`, written the same way.
NodeId turned_node(Grammar& g, NodeId node, const Orientation& turns);

// Each label's canonical mesh and each part's turns relative to it.
struct PartOrientations {
  // A label's mesh from `library` (the user's --primitives, else the
  // built-in ones) when the first part's mesh is one of its turns; else
  // that first mesh, normalised to the unit box. Labels whose parts have
  // no mesh (examples built in memory) are absent.
  PrimitiveLibrary canonical;
  std::vector<std::vector<Orientation>> turns;  // per example, per box; empty: as it is
  std::size_t unmatched = 0;  // parts whose mesh is no turn of their label's (kept unturned)
};

// Vertices match within max(tolerance, 1e-4 of the part's largest size):
// exporters round coordinates, and a wrong turn misses by the part's size.
double vertex_tolerance(const LabelledBox& box, double tolerance);

PartOrientations orient_parts(const std::vector<Example>& examples, const PrimitiveLibrary& library,
                              double tolerance);

}  // namespace vern
