#pragma once

#include <optional>
#include <vector>

#include "graph/grammar.hpp"
#include "inverse/merge/repeat_folding.hpp"
#include "inverse/merge/sample_book.hpp"

namespace vern {

// The shortest decimal tile size that makes, on every length seen, the
// count seen there (n tiles on L: any size in [L/n, L/(n-1))), nearest the
// middle of what they allow among those as short: the lengths as they are
// first (4 m tiles on 4 and 8 m are 4), else each known only to the
// tolerance (noisy files); either way the size must still give each count
// on a length a tolerance longer, unless it divides the length exactly.
// None when no one size does.
std::optional<double> common_tile(const std::vector<TileSeen>& seen, double tolerance);

// Repeats whose tile sizes vary, once merging has settled (rows that
// differ in their counts have been united first):
//   - one whose counts, on every length seen, one tile size explains is
//     that size (common_tile): the same counts on the examples, and on
//     other lengths the counts the source's own tile gives, as near as
//     the examples tell;
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
// Repeats of one axis and length kind whose tiles are of one shape (rows
// cut along one axis: storeys, whatever bays they hold) share one size
// where one gives every count they made; else those made of the same
// parts do.
// A repeat of one tile size already keeps it where it gives every count
// seen, and still on a length a tolerance longer (or one it divides
// exactly); else it takes common_tile's: merging may have made one size
// of tiles that agree within the tolerance, and on a row of thirty a
// centimetre is one tile more.
// Returns the new root; the centred tile sizes' values go into book, for
// fitting.
NodeId settle_repeats(Grammar& g, NodeId root, const TileCounts& tile_counts, SampleBook& book, double tolerance);

}  // namespace vern
