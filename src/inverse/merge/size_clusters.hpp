// Parts alike in structure but not in size are different parts (issue 4,
// "merging that keeps parts apart"): the thesis merges every split of one
// structure into one, so a balcony's 0.2 m railing and a 10 m floor slab
// become one part ranging from 0.2 to 10 (its figure 12.6's elongated
// balcony bars). Merging asks this file which members of a structural
// group are one kind.
//
// The rule, per sized part: the members' lengths in order; a new kind
// starts where the next length lies more than a gap beyond the longest so
// far. The gap is the larger of a quarter and the gap that lengths of one
// kind, spread evenly over the range seen (on a log scale, each length
// counted once per example that shows it), would leave with a chance of
// less than one in ten: about half the range for ten lengths, a quarter
// for twenty. Ten plots 8 to 20 m wide stay one kind however unevenly
// they fall; railings, walls and slabs of 0.2, 0.6 and 10 m seen again and
// again do not. Two lengths alone are one kind: they are their range's
// ends. A split's part is also read as its share of the split, parted
// into kinds the same way: where saying the shares costs less than saying
// the metres (each kind's range, which kind each member is, and each size
// within its kind's range, to a thousandth), the shares decide (a U
// plan's wings, a fifth of plots 16 to 30 m wide, are one kind of wing
// however their metres clump; a shop window always 2.8 m and an upper
// window always 1.4 m stay two kinds however their shares overlap). Members are one kind where every part
// agrees; parts holding empty space have no say (merge.cpp): air is what
// the other parts leave; nor have runs of tiles (a part that is a
// repeat): bays before a door bay are as long as their count makes them.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "inverse/merge/merge.hpp"

namespace vern {

struct SizedMember {
  std::vector<std::optional<Range>> sizes;  // per sized part; nullopt: not a literal (no say)
  double weight = 1;                        // in how many examples it occurs
  double total = 0;                         // a split's length (its sizes' sum); 0: no shares
};

// Each member's kind: 0, 1, ... in order of each kind's first member.
std::vector<std::size_t> size_clusters(const std::vector<SizedMember>& members);

}  // namespace vern
