// What a repeat's drawn tile size and a repeat's count that follows a size
// are, once joint_sizes has read them (issue 23, item 1).
//
// A size s gives ceil(L / s) tiles of L / n: a building whose n tiles are
// t long drew s somewhere in [t, t n / (n - 1)), and t itself is no draw.
// Fitted to the tiles' lengths (the lowest ends of those intervals), the
// draw gave variants storeys lower than any the style makes.
#pragma once

#include <vector>

#include "graph/expr.hpp"
#include "inverse/sizes/fit_distribution.hpp"
#include "inverse/sizes/linear_size.hpp"

namespace vern {

// One run of a repeat in one building: its tiles' length and their count.
struct TileRun {
  double length = 0;
  double count = 0;
};

// The draw of a tile size that gave these runs: the uniform range most
// likely to have given every run's interval of sizes (each run's chance
// the share of the range its interval covers), its ends among the
// intervals' ends (at most 48 candidates each), then in short decimals
// moved inwards by at most a hundredth of the range and still meeting
// every interval by the tolerance. Where a run has one tile (any size
// above L gives it), or no range meets every interval, the tiles'
// lengths are fitted as other sizes are (fit_distribution).
Distribution tile_size_distribution(const std::vector<TileRun>& runs, const std::vector<Observation>& lengths,
                                    const FitOptions& fit, double tolerance);

// A count that is a line of sizes, as a person writes it: `s1 / 4.4`,
// `5 - s1 / 4.4`, where a coefficient is one over a short decimal (to a
// hundred-thousandth: counts are rounded); else linear_expr's form.
Expr count_line_expr(const Linear& f);

}  // namespace vern
