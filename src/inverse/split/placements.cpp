#include "inverse/split/placements.hpp"

#include <algorithm>
#include <vector>

#include "inverse/sizes/tidy_numbers.hpp"

namespace vern {

namespace {

struct Item {
  std::uint32_t box = 0;
  glm::dvec3 min{0.0}, max{0.0};
};

class Placer {
 public:
  Placer(Grammar& g, double tolerance, const std::function<NodeId(std::uint32_t)>& part, NodeId nil)
      : g_(g), tol_(tolerance), part_(part), nil_(nil) {}

  // The node deriving `items` in the piece [lo, hi], cutting along `axis`
  // and the axes after it.
  std::optional<NodeId> place(std::vector<Item> items, glm::dvec3 lo, glm::dvec3 hi, int axis) {
    if (items.empty()) return nil_;
    if (items.size() == 1 && near(items[0].min, lo)) return alone(items[0], hi);
    if (axis == 3) return std::nullopt;  // parts sharing their min corner
    std::sort(items.begin(), items.end(), [&](const Item& a, const Item& b) { return a.min[axis] < b.min[axis]; });

    // Runs of min coordinates, each within the tolerance of the next, are
    // one cut (at the run's smallest, or the piece's start when that close),
    // as box_split snaps the coordinates it cuts at.
    std::vector<double> starts;
    std::vector<std::vector<Item>> runs;
    for (std::size_t i = 0; i < items.size(); ++i) {
      if (i == 0 || items[i].min[axis] - items[i - 1].min[axis] > tol_) {
        const double at = items[i].min[axis];
        starts.push_back(at - lo[axis] <= tol_ ? lo[axis] : at);
        runs.emplace_back();
      }
      runs.back().push_back(items[i]);
    }
    if (runs.size() == 1 && starts[0] == lo[axis]) return place(std::move(runs[0]), lo, hi, axis + 1);

    Split split;
    split.axis = Expr::axis(static_cast<Axis>(axis));
    if (starts[0] > lo[axis]) split.parts.push_back({Size{Expr::number(starts[0] - lo[axis]), true}, nil_});
    for (std::size_t k = 0; k < runs.size(); ++k) {
      glm::dvec3 piece_lo = lo, piece_hi = hi;
      piece_lo[axis] = starts[k];
      if (k + 1 < runs.size()) piece_hi[axis] = starts[k + 1];
      const double length = piece_hi[axis] - piece_lo[axis];
      if (length <= tol_) return std::nullopt;  // a part on the far face: a piece of no length is not derived
      const auto child = place(std::move(runs[k]), piece_lo, piece_hi, axis + 1);
      if (!child) return std::nullopt;
      split.parts.push_back({Size{Expr::number(length), true}, *child});
    }
    return g_.intern(Node{std::move(split), {}});
  }

 private:
  bool near(const glm::dvec3& a, const glm::dvec3& b) const {
    return std::abs(a.x - b.x) <= tol_ && std::abs(a.y - b.y) <= tol_ && std::abs(a.z - b.z) <= tol_;
  }

  // One part at the piece's origin: itself where it fills the piece. Where
  // it falls short on an axis, the rest of the piece is empty space
  // (split(axis){ ~part : ... | ~rest : nil }); where it reaches past the
  // piece, it is resized to so many times the piece's length (S(~2, ~1, ~1):
  // twice as long), and a flat part to none (S(~1, ~0, ~1)). All relative, because every cut of the group is a share
  // of the container: on a larger plot the group scales as one, each part
  // still ending on the corners its neighbours start at, so no two overlap.
  // A ratio is written to seven digits, whatever the group's size, so
  // groups of one shape in examples of other sizes are one structure.
  NodeId alone(const Item& item, glm::dvec3 hi) {
    NodeId node = part_(item.box);
    if (near(item.max, hi)) return node;
    Scale s;
    bool overruns = false;
    for (int a = 0; a < 3; ++a) {
      const double piece = hi[a] - item.min[a], length = item.max[a] - item.min[a];
      // A flat part (a panel) is resized to no thickness: a split would
      // give it a part of zero length, which is not derived.
      const bool past = length > piece + tol_, flat = length <= tol_ && piece > tol_;
      const double ratio = past ? length / piece : flat ? 0.0 : 1.0;
      s.size[static_cast<std::size_t>(a)] = Size{Expr::number(shortest_decimal(ratio, 2.5e-7 * ratio)), true};
      overruns = overruns || past || flat;
    }
    if (overruns) {
      s.child = node;
      node = g_.intern(Node{std::move(s), {}});
    }
    for (int a = 2; a >= 0; --a) {
      const double piece = hi[a] - item.min[a], length = item.max[a] - item.min[a];
      if (length >= piece - tol_ || length <= tol_) continue;
      Split short_of;
      short_of.axis = Expr::axis(static_cast<Axis>(a));
      short_of.parts = {{Size{Expr::number(length), true}, node}, {Size{Expr::number(piece - length), true}, nil_}};
      node = g_.intern(Node{std::move(short_of), {}});
    }
    return node;
  }

  Grammar& g_;
  double tol_;
  const std::function<NodeId(std::uint32_t)>& part_;
  NodeId nil_;
};

}  // namespace

std::optional<NodeId> place_group(Grammar& g, const SplitTree& group, double tolerance,
                                  const std::function<NodeId(std::uint32_t box)>& part, NodeId nil) {
  std::vector<Item> items;
  items.reserve(group.children.size());
  for (const SplitTree& c : group.children) items.push_back({c.box, c.min, c.max});
  return Placer(g, tolerance, part, nil).place(std::move(items), group.min, group.max, 0);
}

}  // namespace vern
