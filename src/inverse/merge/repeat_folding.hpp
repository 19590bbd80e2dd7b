// Repeats that stretch (issue 4): a run of equal parts, or of a repeating
// pattern of parts (wall window wall window ...), becomes
//   repeat(axis, tile){ pattern }
// so that a wider scope gets more tiles, not wider ones, and examples with
// 3, 4 and 6 windows share one structure that merging can unify.
//
// Done on each example's graph before merging. A run is a maximal sequence
// of k >= 2 copies of a pattern of p <= 4 consecutive parts with the same
// children and sizes equal within the tolerance; the longest run wins,
// then the shortest pattern, then the leftmost. Only a run of three parts
// or more that leaves at most two parts of its split outside (end walls,
// margins) is folded, or a run of two or more with at most two parts on
// each side, none as long as a tile beside it (the storeys between a
// ground floor and a cornice and roof, as many as the height allows): a
// run inside a mixed row is left for merging to line up with other rows
// (merge.hpp), which finds repeats after unifying, unless it is a run of
// one part whose copies in the row are all one length, none as long
// beside them (walls either side of a door: each run a repeat). A built
// part alone in a row, of a kind some row folds as tiles along the same
// axis, is a repeat of one tile (RowsSeen). The run's part keeps its
// length (k tiles) and its relative flag; the tile is the run's length / k,
// so rounding noise spreads evenly instead of piling up at the end (the
// size written is the shortest decimal just above it, which still makes k
// tiles on that length), and
// the fold is kept only when every original cut stays within the
// tolerance. A pattern of one part is that part's child; a longer one is a
// split of the pattern with the parts' lengths as relative sizes. Runs of
// empty space are joined into one empty part instead. A split left with a
// single relative part is that part's operation.
//
// Tiles alike but for their sizes (UnlikeTiles::Fold): where no run of
// equal parts is found, a row whose pattern recurs with the same children
// and kinds of size but other sizes (bays whose windows were each drawn
// their own width) is read in the phase where most occurrences have a
// neighbour of the same length, and each run of occurrences of one length
// becomes repeat(axis, tile){ choose{ the occurrences } }, beside the
// stretches between runs as above. Merging then unites the occurrences
// into one bay whose sizes range over theirs.
//
// Rows of unlike things (UnlikeTiles::Fold): where no such run covers a
// split, equal tiles holding different buildings become
//   repeat(axis, tile){ choose{ what the tiles held, weighted by count } }
// when the split, or all but one or two parts at its ends, cuts into k >= 3
// pieces of one length at cuts it already has (a piece may be several
// parts: a plot holding three strips of towers), and the pieces are
// exchangeable: not bare primitives or empty space, and no piece the only
// one to hold some label (a ground floor with the door stays below the
// storeys, which fold); or two such tiles of one length, both built,
// between ends with no part as long beside them (two storeys above a
// ground floor, each holding its own bays). Merging then unites the
// choices of rows of one kind (tile_choices.hpp).
//
// Rows of tiles of a few kinds (UnlikeTiles::Fold): where a row is runs of
// pieces of one length whose kinds (structure, sizes aside) vary, bays
// each a balcony or a window bay with openings drawn bay by bay around an
// entrance or a bay of paired windows at some place, each run becomes a
// repeat of a choice of its pieces and the odd tile (a kind alone in the
// row, not seen trading in another) stands between them.
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <unordered_map>
#include <vector>

#include "graph/grammar.hpp"

namespace vern {

// What folding may do besides runs of equal parts.
enum class UnlikeTiles {
  Keep,  // one example alone: it must come back exactly as it is
  Fold,  // equal tiles of unlike contents become a repeat of a choice
};

// Where folding found each repeat: how many tiles it made on what length,
// per repeat node (one entry per place it was folded). Merging reads it
// (merge.cpp, settle_repeats): a repeat that made the same number of tiles
// wherever it was seen, on lengths that differ, is that many tiles
// (repeatN), not a tile length (a cluster of three by three towers on
// plots of any size); one whose counts vary gets tile sizes from the
// middle of each count's range of sizes.
struct TileSeen {
  std::uint32_t count = 0;
  double length = 0;
};
using TileCounts = std::unordered_map<NodeId, std::vector<TileSeen>>;

// Which tiles may trade places is read across rows and examples: a bay
// with a balcony alone among window bays in one storey is one of the
// tiles where another storey, or another building, shows two of them
// (a choice made tile by tile), while a door bay is alone in every row.
// Folding notes the labels it saw held by two tiles or more of a row of
// unlike tiles (seen), and the labels that kept a row from folding for
// being held by one tile only (lone); a label seen anywhere counts as
// trading places everywhere. Merging folds again when some lone label
// was seen elsewhere (merge.cpp).
// Kinds of tiles (tile shapes: structure, sizes aside) are noted alike
// by rows that segment_kinds reads.
// A built part (a storey, a bay) alone in a row is a repeat of one tile
// where some row folds runs of it along the same axis: a house of one
// storey above its ground floor is then the houses of two and three,
// not an alternative of its own. Folding notes, for each kind of such
// part (by shape, sizes aside, and axis: tiles), the longest tile size
// that makes some row's count of it, and
// the kinds it saw alone with no tile noted yet (lone_tiles); merging
// folds again when one of those turned out a tile elsewhere.
struct RowsSeen {
  std::set<LabelId> seen, lone;
  std::set<std::size_t> shapes_seen, shapes_lone;
  std::map<std::pair<std::size_t, std::uint8_t>, double> tiles;
  std::set<std::pair<std::size_t, std::uint8_t>> lone_tiles;
};

// Rewrites every split below root whose sizes are literals; returns the new
// root (nodes interned in g). Notes each repeat's tile count in counts,
// where given. Nodes `kept` marks (by id; placed groups, which merging
// copies as they are) are left as they are, and all below them.
NodeId fold_repeats(Grammar& g, NodeId root, double tolerance, UnlikeTiles unlike = UnlikeTiles::Fold,
                    TileCounts* counts = nullptr, const std::vector<bool>* kept = nullptr,
                    RowsSeen* rows_seen = nullptr);

}  // namespace vern
