// A run of no tiles (issue 23, item 2: a special tile at any index). A
// door bay after one, two or three bays is, in each example, a split whose
// first part is the run of bays (a repeat, one copy too); a door bay at
// the very start has no such part, so its split has one part fewer and
// merging kept it an alternative of its own, with its own sizes, beside
// the one for every other place. The ground floor's and the storeys'
// places then sat in alternatives no example showed together, and could
// not be drawn once for both.
//
// The run the other alternative starts (or ends) with is there, zero
// long: where one alternative of a choice is a split whose parts are
// another's but for a first (or last) part that is a repeat, it gains
// that part at size 0 (a part of zero length is not derived), and the
// two unify into one split whose run ranges down to 0. Every example
// still derives: the part adds nothing where it is 0.
//
// The same under a repeat whose tile is a choice (storeys whose bays were
// drawn storey by storey, so no two storeys of a house are one node),
// on either side: each row of the shorter tile (one row, or a choice of
// rows) gains the run of a row of the longer one whose parts it has but
// for that run, or the tile is left as it is.
#pragma once

#include <utility>
#include <vector>

#include "graph/grammar.hpp"
#include "inverse/merge/sample_book.hpp"

namespace vern {

struct EmptyRuns {
  NodeId root = 0;
  std::size_t padded = 0;  // splits given an empty run
  // Each split given its empty run, and each node above one rebuilt in
  // turn, with what replaced it: merging's notes carry over (the padded
  // splits' own rows and samples are written here, with the run's zeros).
  std::vector<std::pair<NodeId, NodeId>> replaced;
};

EmptyRuns pad_empty_runs(Grammar& g, NodeId root, SampleBook& book, RowBook& rows);

}  // namespace vern
