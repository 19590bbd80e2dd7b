#pragma once

#include "graph/grammar.hpp"
#include "inverse/repeat_folding.hpp"
#include "inverse/sample_book.hpp"

namespace vern {

// Repeats whose tile sizes vary, once merging has settled (rows that
// differ in their counts have been united first):
//   - one that made the same number of tiles wherever the examples show
//     it is that many tiles whatever the length: repeatN. A cluster of
//     three by three towers stays three by three on a wider plot instead
//     of growing to seven by seven;
//   - one whose counts vary takes its tile sizes from the middle of each
//     count's range: n tiles on L come from any size in [L/n, L/(n-1)),
//     and the sizes seen, L/n, are that range's lower end, so sizes drawn
//     between them would make more tiles, on average, than the examples
//     had. L/(n - 1/2) makes the same n tiles on L, and so does the
//     shortest decimal near it.
// Returns the new root; the centred tile sizes' values go into book, for
// fitting.
NodeId settle_repeats(Grammar& g, NodeId root, const TileCounts& tile_counts, SampleBook& book, double tolerance);

}  // namespace vern
