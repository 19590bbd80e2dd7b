// Sizes that scale (issue 4): when splits of one structure, unified across
// examples, span different lengths, which of their parts keep a length in
// metres (a 0.6 m end wall) and which take a share of what is left (the
// bays between the walls)?
//
// From the lengths each member gave each part (one row per member):
//   - if the members' total lengths agree (within the tolerance), nothing
//     tells absolute from relative: no plan (sizes stay relative);
//   - otherwise a part whose length is the same in every member is
//     absolute, at that length;
//   - the other parts are relative; when each one's share of what the
//     absolute parts leave is the same in every member, it is that share
//     (fixed; written as the widest member's length, a weight in metres,
//     so that rounding it moves the part by metres, not by a fraction); when not, its size ranges over its lengths (the caller
//     writes the range or fitted distribution), which still derives every
//     member exactly: weights equal to a member's lengths split what is
//     left into exactly those lengths.
// A plan is kept only if every member's parts come out within the
// tolerance; at least one part stays relative, so the split fills any
// scope.
#pragma once

#include <optional>
#include <vector>

namespace vern {

struct PartPlan {
  bool absolute = false;  // metres, not a share
  bool fixed = false;     // value holds the size; else the caller ranges over the lengths
  double value = 0;
};

std::optional<std::vector<PartPlan>> plan_sizes(const std::vector<std::vector<double>>& lengths, double tolerance);

// A part's size as the grammar writes it: fixed at value, or drawn, each
// row needing its own value (metres for an absolute part, a weight beside
// the other relative parts' for a relative one).
struct PartSizes {
  bool absolute = false;
  bool fixed = false;
  double value = 0;
  std::vector<double> values;  // per row, when not fixed
};

// Splits whose sizes vary, with as few draws as the rows need (issue 15).
// plan_sizes's absolute and fixed parts first; then, of the parts that
// vary:
//   - a part whose rows' lengths cost less to say drawn from the range of
//     lengths seen than drawn from the range of shares seen (scaled by
//     each row's split) is drawn in metres (a courtyard's range depth, 5
//     to 8 m on plots of 24 to 44 m), as long as one part stays relative
//     to fill any scope;
//   - the relative parts only share out what is left: where their
//     ratios are the same in every row they are fixed at those ratios
//     (a half's wall and roof, 1 : 0.6, above which air of any height
//     is drawn in metres); where some of three or more keep one ratio to
//     one of them and others vary, those keep it and the others are
//     drawn as weights beside it; else each row's own lengths are its
//     weights (joint_sizes draws shares that vary in one way once).
// Fixed weights are the widest member's lengths. None when nothing varies, or fewer than two rows; a plan is kept
// only if every row's cuts come out within the tolerance.
std::optional<std::vector<PartSizes>> plan_drawn_sizes(const std::vector<std::vector<double>>& lengths,
                                                       double tolerance);
// The same from plan_sizes(lengths, tolerance), where the caller has it.
std::optional<std::vector<PartSizes>> plan_drawn_sizes(const std::vector<std::vector<double>>& lengths,
                                                       const std::optional<std::vector<PartPlan>>& base,
                                                       double tolerance);

// The sizes one split of these rows writes, if it can be written: fixed
// where plan_sizes fixes every part, else as plan_drawn_sizes draws them.
// None where plan_sizes has none (the rows' totals agree: their parts keep
// their lengths) or plan_drawn_sizes finds no plan that holds.
std::optional<std::vector<PartSizes>> planned_sizes(const std::vector<std::vector<double>>& lengths, double tolerance);

// How many sizes a split of these sizes draws: each drawn part, but where
// every relative part is drawn one of them is only the scale of the
// others' weights (three shares of any proportion are two choices).
std::size_t draws_of(const std::vector<PartSizes>& sizes);

}  // namespace vern
