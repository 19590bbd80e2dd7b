// The one criterion inference chooses between generalisations with
// (issue 15): a description length, the grammar's plus the examples' given
// the grammar (minimum description length; Bayesian model merging,
// Stolcke and Omohundro 1994). A grammar that writes more numbers must
// say the examples in fewer: a range of one length where the examples
// spread in shares costs each example the log of the range's width.
//
// Costs are in nats. The grammar's own length is counted by
// graph/description_length.hpp (operations + numbers); here are the
// pieces the decisions inside inference weigh against each other:
//   - writing a number: number_cost (two for a range);
//   - saying a value drawn from a range, to a precision: drawn_value_cost;
//   - saying which of several kinds a value is: kind_cost.
// Where a decision uses them: size_clusters.cpp (kinds of sizes read as
// metres or as shares), size_plan.cpp (a part drawn in metres or as a
// share), settle_repeats.cpp (one tile size, one number, where a range
// would write two and say a count no example had).
#pragma once

#include <algorithm>
#include <cmath>

namespace vern {

// One number in a grammar, written to a share `precision` of itself.
inline double number_cost(double precision) { return std::log(1 / precision); }

// One value drawn from a range `width` wide, said to `precision` (both in
// one unit). A width below the precision costs nothing: the value is the
// range.
inline double drawn_value_cost(double width, double precision) {
  return std::log(std::max(width, precision) / precision);
}

// Which kind a value is, of kinds seen with shares summing to 1.
inline double kind_cost(double share) { return -std::log(share); }

}  // namespace vern
