// A split that is two splits (issue 23): the examples' cuts along one axis
// show parts side by side, and nothing in the geometry tells which of them
// were cut first. A style that writes
//     site  --> split(x){ ~1.2 : lodge | ~1.1 : lodge | ~2.9 : front }
//     front --> split(x){ 1 : column | ~1 : mass | 1 : column }
// leaves five parts in a row whose lengths no single split gives: the
// lodges keep their ratio to the front, column and mass together, not to
// the mass. Written as one split, the mass becomes a share drawn anew in
// every building, and the buildings derived no longer keep the
// proportions the examples all keep.
//
// From the lengths each example's split gave each part (one row per
// example), find_nested_run looks for a run of neighbouring parts that,
// taken as one part, leaves an outer split and an inner one (the run's
// own parts) that together draw fewer sizes than the row as one split:
// each a length in metres, a share in a ratio every row keeps, or drawn
// (planned_sizes, draws_of). The lodges may vary themselves (a second lodge of
// any width beside the first and the front, kept in their ratio): the
// front still nests, and only that width is drawn. It is tried only where
// the row as one split draws a size.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "inverse/sizes/size_plan.hpp"

namespace vern {

// The parts [first, last] (first < last, not all parts) that become one,
// with the sizes of the split round them (the run one part) and of the
// split they make: fixed, or drawn with each row's value.
struct NestedRun {
  std::size_t first = 0, last = 0;
  std::vector<PartSizes> outer, inner;
};

// The run whose two splits draw the fewest sizes, fewer than `whole`
// (plan_sizes of the rows) does; the shortest, then the leftmost, of
// equal draws. None when `whole` fixes every part or is none, or there
// are too few rows (three) or too many parts (32) to tell.
std::optional<NestedRun> find_nested_run(const std::vector<std::vector<double>>& lengths,
                                         const std::optional<std::vector<PartPlan>>& whole, double tolerance);

// Where no run alone draws fewer sizes: a run whose own split is fixed (a
// wing, its 2.5 m porch and the rest), taken as one part, after which
// another run nests (the other wing, its porch at the far end) so that
// the two together draw fewer than the row (a villa of two wings and a
// main block, ~1 : ~1.6 : ~1); the first of those, the other being
// find_nested_run's in its outer rows. None past 12 parts.
std::optional<NestedRun> find_fixed_run_leading_on(const std::vector<std::vector<double>>& lengths,
                                                   const std::optional<std::vector<PartPlan>>& whole,
                                                   double tolerance);

// The rows with parts [run.first, run.last] summed into one.
std::vector<std::vector<double>> outer_lengths(const std::vector<std::vector<double>>& lengths, NestedRun run);

// The rows of parts [run.first, run.last] alone.
std::vector<std::vector<double>> inner_lengths(const std::vector<std::vector<double>>& lengths, NestedRun run);

}  // namespace vern
