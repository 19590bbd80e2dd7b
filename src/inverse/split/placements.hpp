// Placements: parts that no straight cut separates, represented exactly.
//
// Ordered-box splitting (box_split.hpp) leaves some containers whole: five
// boxes in a pinwheel, each pushing the next, or a flat panel inside a
// thicker empty space (a cut never makes a part of zero length). Their
// boxes cannot be separated by planes, but their min corners, being points,
// always can. So such a container is cut along x at its parts' min x
// coordinates, each part going to the piece its min corner lies in, and each
// piece the same way along y, then z. A piece holding one part whose min
// corner is the piece's origin is that part: I(label) where the part fills
// the piece; where it falls short on an axis, a split of the piece into
// the part and nil; where it reaches beyond the piece, S(~r, ...){ I(label) }
// with r the part's length over the piece's (a flat part: ~0); pieces
// without parts are nil. Every size is a share, so the group scales with
// its container as one and its parts never overlap on a plot of another
// size. Only split, S, I (and R for turned parts) are used, so deriving
// the result gives every part's box, within the tolerance.
//
// The construction needs distinct min corners, and no part whose min corner
// lies on the container's far face where a piece from there would have no
// length (derivation skips such parts). Two panels meeting at a corner
// share their min corner: place_group gives up on such a group.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>

#include "graph/grammar.hpp"
#include "inverse/split/box_split.hpp"

namespace vern {

// The placement of an Unsplittable container's parts (its Leaf children).
// part(box) is the node of the part with that box index (I(label), or
// turned); nil the nil node. Nodes are interned in g. nullopt when the
// construction above cannot separate the parts.
std::optional<NodeId> place_group(Grammar& g, const SplitTree& group, double tolerance,
                                  const std::function<NodeId(std::uint32_t box)>& part, NodeId nil);

}  // namespace vern
