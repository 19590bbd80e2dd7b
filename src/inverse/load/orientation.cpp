#include "inverse/load/orientation.hpp"

#include <algorithm>
#include <numbers>

#include "forward/scope.hpp"
#include "inverse/load/point_grid.hpp"

namespace vern {

namespace {

// Every sequence of at most two quarter turns, fewest first.
const std::vector<Orientation>& candidates() {
  static const std::vector<Orientation> all = [] {
    std::vector<Orientation> out{{}};
    std::vector<QuarterTurn> single;
    for (const Axis a : {Axis::Z, Axis::X, Axis::Y}) {
      for (int q = 1; q <= 3; ++q) single.push_back({a, q});
    }
    for (const QuarterTurn& t : single) out.push_back({t});
    for (const QuarterTurn& t : single) {
      for (const QuarterTurn& u : single) {
        if (u.axis != t.axis) out.push_back({t, u});
      }
    }
    return out;
  }();
  return all;
}

Expr quarter_angle(int quarters) {
  const Expr pi = Expr::number(std::numbers::pi);
  switch (quarters) {
    case 2: return pi;
    case 3: return Expr::binary(BinaryOp::Div, Expr::binary(BinaryOp::Mul, Expr::number(3), pi), Expr::number(2));
    default: return Expr::binary(BinaryOp::Div, pi, Expr::number(2));
  }
}

}  // namespace

std::optional<Orientation> find_orientation(const Mesh& canonical, const std::vector<glm::dvec3>& placed,
                                            glm::dvec3 box_min, glm::dvec3 box_max, double tolerance) {
  const PointGrid target(placed, tolerance);
  Scope box;
  box.origin = box_min;
  box.size = box_max - box_min;
  std::vector<glm::dvec3> moved(canonical.positions.size());
  for (const Orientation& turns : candidates()) {
    Scope s = box;
    for (const QuarterTurn& t : turns) s = rotated(s, t.axis, t.quarters * (std::numbers::pi / 2));
    for (std::size_t i = 0; i < moved.size(); ++i) moved[i] = s.to_world(canonical.positions[i]);
    if (!target.covers(moved)) continue;
    if (PointGrid(moved, tolerance).covers(placed)) return turns;
  }
  return std::nullopt;
}

NodeId turned_node(Grammar& g, NodeId node, const Orientation& turns) {
  for (auto t = turns.rbegin(); t != turns.rend(); ++t) {
    node = g.intern(Node{Rotate{Expr::axis(t->axis), quarter_angle(t->quarters), node}, {}});
  }
  return node;
}

NodeId turned_primitive(Grammar& g, LabelId label, const Orientation& turns) {
  return turned_node(g, g.intern(Node{Primitive{label}, {}}), turns);
}

double vertex_tolerance(const LabelledBox& box, double tolerance) {
  const glm::dvec3 size = box.max - box.min;
  return std::max(tolerance, 1e-4 * std::max({size.x, size.y, size.z}));
}

PartOrientations orient_parts(const std::vector<Example>& examples, const PrimitiveLibrary& library,
                              double tolerance) {
  PartOrientations out;
  out.turns.resize(examples.size());
  std::vector<glm::dvec3> positions;
  for (std::size_t e = 0; e < examples.size(); ++e) {
    const Example& ex = examples[e];
    out.turns[e].resize(ex.boxes.size());
    for (std::size_t b = 0; b < ex.boxes.size() && b < ex.positions.size(); ++b) {
      const LabelledBox& box = ex.boxes[b];
      ex.positions.get(b, box.min, box.max, positions);
      const double tol = vertex_tolerance(box, tolerance);
      const Mesh* canonical = out.canonical.find(box.label);
      if (canonical == nullptr) {
        // The first part of this label decides its canonical mesh (kept
        // whole: the first of its label in its example).
        const Mesh& mesh = ex.meshes.at(box.mesh);
        const Mesh* known = library.find(box.label);
        if (known != nullptr && find_orientation(*known, positions, box.min, box.max, tol)) {
          out.canonical.add(box.label, *known);
        } else {
          out.canonical.add(box.label, normalised_primitive(mesh));
        }
        canonical = out.canonical.find(box.label);
      }
      if (auto turns = find_orientation(*canonical, positions, box.min, box.max, tol)) {
        out.turns[e][b] = std::move(*turns);
      } else {
        ++out.unmatched;
      }
    }
  }
  return out;
}

}  // namespace vern
