// Parts set into parts, and layered annotations: overlapping parts
// resolved into what is visible of each (issue 24, item 1).
//
// Models as people make them set windows into walls, and annotations paint
// a sill over a window's lower edge and every rectangle on the facade's
// own. Inference needs parts that do not overlap, so each part keeps what
// is visible of it: the box minus the parts painted over it, tiled by
// boxes with its label, object name and line. Which of two overlapping
// parts is painted over the other:
//   1. the later of their labels in the stack order (`--stack`, bottom to
//      top), when both are listed and differ;
//   2. otherwise the part that lies inside the other (within the
//      tolerance): a window set into its wall, the wall its container;
//   3. otherwise, for two parts of one listed label, the later in the
//      file: annotation tools paint in the order they write (two blinds of
//      the CMP set overlapping by a few millimetres);
//   4. otherwise no one can say, and the pair is an error that names both
//      parts and how to give the order.
// A part wholly covered is gone. The visible region is tiled by straight
// cuts where they cut nothing painted over it, on z first, then along the
// horizontal axis with more such cuts, then the other (storeys, then bays,
// whichever way the wall faces), at every such cut at once; where none cuts
// cleanly (a pinwheel of parts painted over it), by the grid of their
// bounds. So a wall holding a row of windows becomes bands below and
// above the row and piers between the windows, the pieces a split grammar
// writes.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "inverse/load/example.hpp"

namespace vern {

using OverlapPair = std::pair<std::uint32_t, std::uint32_t>;

struct Layering {
  // Labels from bottom to top (--stack): of two overlapping parts whose
  // labels are listed and differ, the later label is painted over.
  std::vector<std::string> stack;
  // Coordinates closer than this are equal (the example's own tolerance).
  double tolerance = 0;
};

// The example with every part that `overlaps` (pairs of box indices, as
// split_boxes lists them) names replaced by the boxes of what is visible of
// it, in file order; other parts, meshes and positions as they were (a
// piece's positions are its box's corners). Throws vern::Error (Input),
// naming the example and both parts, for overlapping parts that neither
// the stack order nor containment orders (the count of all such pairs in
// the message), and for parts painted over one another in a circle.
Example visible_parts(const Example& example, const std::vector<OverlapPair>& overlaps, const Layering& layering);

// The same, finding the overlaps itself (one split_boxes of the example):
// what check runs on each example, as infer does.
Example visible_parts(const Example& example, const Layering& layering);

}  // namespace vern
