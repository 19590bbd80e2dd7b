// Rows of the same kind share what their tiles may hold (issue 4,
// "merging"). Folding (repeat_folding.hpp) turns each example's row of
// unlike buildings into repeat(x, tile){ choose{ what this row held } }; a
// city has hundreds of such rows, each holding its own few of the same
// building kinds. Two tile choices are the same slot when their repeats run
// along the same axis, the choice sits at the same place in the tile, and
// they share an alternative; slots linked so, directly or through others,
// become one choice over everything any of them held, weighted by how
// often (by tiles: a city's blocks of small buildings at its edges weigh
// every building they hold against the mixed blocks at its centre). A tile that always holds one thing counts as a choice of one.
// Merging then unifies the rows, whose tiles now agree, and the blocks
// above them in turn.
//
// Every example stays derivable: each tile's choice only gains
// alternatives. Slots that share nothing stay apart (a row of windows and
// a row of balconies; a row of buildings and the column of blocks above
// it, which run along another axis or hold other things).
#pragma once

#include <utility>
#include <vector>

#include "graph/grammar.hpp"
#include "inverse/merge/repeat_folding.hpp"

namespace vern {

struct TileChoiceUnion {
  NodeId root = 0;
  // Each repeat rebuilt with united choices, and each node above one
  // rebuilt in turn, with what replaced it: merging's notes on their sizes
  // carry over to their replacements.
  std::vector<std::pair<NodeId, NodeId>> replaced;
};

// Weights: where folding counted every repeat's tiles (tile_counts), each
// alternative weighs the tiles it stands for, a repeat's tiles shared out
// by its choice's weights; otherwise the choices' own weights add up.
TileChoiceUnion unite_tile_choices(Grammar& g, NodeId root, const TileCounts* tile_counts = nullptr);

}  // namespace vern
