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

}  // namespace vern
