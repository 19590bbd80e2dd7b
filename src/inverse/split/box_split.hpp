// The box-splitting problem (thesis chapter 9.1): cut the box around all
// parts of an example, recursively and with straight cuts that cut no part,
// until every piece ("container") holds exactly one part or empty space.
// The pieces become split, primitive and nil operations (split_graph.hpp).
//
// Contract:
//   - Coordinates within `tolerance` of each other count as equal (a run of
//     coordinates each within tolerance of the next is one), so parts that
//     touch with exporter float noise split cleanly. The tree's extents are
//     the parts' own coordinates; where parts meet within the tolerance, the
//     cut between them lies at the smallest of their coordinates there.
//     So a leaf matches its part within the tolerance (more only where a
//     run of coordinates, each within tolerance of the next, is longer),
//     and exactly where no other part's coordinate comes that close.
//   - Parts must not overlap: two parts whose insides intersect on all three
//     axes (by more than the tolerance; a flat part counts as inside a solid
//     one when it lies strictly within it, and two flat parts when they lie
//     in one plane) can never be cut apart. split_boxes throws vern::Error
//     (Input) naming both objects and how much they overlap. Identical
//     duplicates are overlaps too. (Overlapping parts always end up in one
//     container no cut divides; only those are searched, so a valid
//     example pays nothing for the check.)
//   - A flat part (no thickness on an axis) can only be cut out of a
//     container that is itself flat on that axis: a cut never makes a part
//     of zero length, because derivation skips such parts. So 2-D facades
//     (every part flat at one y) work; a panel lying on a wall's face is
//     unsplittable.
//   - Containers that no straight cut divides (five boxes in a pinwheel)
//     come back as Kind::Unsplittable holding their boxes as leaves.
//   - Deterministic, and independent of the parts' order apart from box
//     indices (an Unsplittable's leaves come in index order).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "graph/node.hpp"
#include "inverse/load/example.hpp"

namespace vern {

struct BoxSplitOptions {
  // Absolute, in the example's units (metres). default_tolerance(example)
  // suits files from modelling tools; 0 compares coordinates exactly.
  double tolerance = 0.0;
};

// A container and how it is divided. Value semantic: children are held by
// value, in order.
struct SplitTree {
  enum class Kind {
    Leaf,          // exactly one box, filling the container
    Empty,         // empty space (a gap between boxes): nil
    Split,         // cut along `axis` into `children`, in order, gaps included
    Unsplittable,  // no straight cut divides it: its boxes as Leaf children
    Comp,          // flat parts round an open box: one child per face, in the face's frame (comp_faces.hpp)
  };
  Kind kind = Kind::Empty;
  int axis = -1;  // Split: 0, 1, 2 for x, y, z; otherwise -1
  glm::dvec3 min{0.0}, max{0.0};  // this container's extent
  std::uint32_t box = 0;          // Leaf: index into the boxes given to split_boxes
  std::vector<SplitTree> children;
  std::vector<Face> faces;        // Comp: each child's face

  glm::dvec3 size() const { return max - min; }
  friend bool operator==(const SplitTree&, const SplitTree&) = default;
};

// Splits the bounding box of `boxes` by the ordered-box algorithm (thesis
// 9.1.3): O(n log n + n m) for n boxes and a tree m levels deep. `source`
// names the example file in messages. No boxes give an Empty tree of zero
// extent; one box, a Leaf.
// Throws vern::Error (Input) for overlapping boxes (see above), unless
// `overlaps` is given: then every overlapping pair (i < j, box indices) is
// listed there, sorted, and the tree holds them in Unsplittable
// containers (layered_parts.hpp resolves them into visible pieces).
SplitTree split_boxes(const std::vector<LabelledBox>& boxes, const BoxSplitOptions& options,
                      const std::string& source = {},
                      std::vector<std::pair<std::uint32_t, std::uint32_t>>* overlaps = nullptr);

// "objects 'a' (line 4) and 'b' (line 9) overlap by 1 x 0.2 x 0.5 (along
// x, y, z)": how messages name an overlap.
std::string describe_overlap(const LabelledBox& a, const LabelledBox& b);

// Where a or b is an object of loose pieces whose boxes meet (one part,
// loose_parts.hpp), which may well be what overlaps: how to separate them.
std::optional<std::string> loose_pieces_hint(const LabelledBox& a, const LabelledBox& b);

// Counts of the tree's nodes by kind (Unsplittable leaves are counted as
// leaves too): for tests and for the caller's warnings.
struct SplitTreeStats {
  std::size_t leaves = 0, empties = 0, splits = 0, unsplittable = 0, depth = 0;
};
SplitTreeStats split_tree_stats(const SplitTree& tree);

}  // namespace vern
