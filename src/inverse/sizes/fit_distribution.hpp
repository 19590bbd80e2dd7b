// Which distribution did the examples' values come from? (issue 4,
// "Fitted distributions"). The thesis wrote every varying size as a
// uniform range between the smallest and largest value seen; a person
// would write a constant, a choice among the few values used, a uniform
// range, or a bell curve, whichever the data supports.
//
// Candidates, compared by BIC (k ln n - 2 ln L, n the number of
// observations), each a model whose support holds every value seen, so
// every example stays derivable:
//   - constant: all values within the resolution (no fitting needed);
//   - choice(v1, ..., vm) of the distinct values, when values repeat
//     (m <= n / 2, and at most a quarter of the m, or one, seen once: one
//     value seen again and again beside a spread of values seen once
//     each is no list to choose from): a discrete style, m parameters;
// Observations of one value from one example (Observation::example) count
// once, for every model: a value repeats only across examples.
//   - rand(lo, hi), 2 parameters;
//   - tnormal(mu, sigma, lo, hi), 4 parameters, mu and sigma fitted by
//     maximum likelihood (Ceres' gradient solver);
// Continuous densities are turned into probabilities over the resolution
// (the examples' tolerance), so discrete and continuous models compare on
// one footing. The continuous supports widen the range seen by the
// unbiased estimate for a uniform sample ((max - min) / (n - 1) each side;
// never below `floor`): ten examples say the style reaches a little
// beyond their own extremes. Being estimates, the widened bounds are the
// shortest decimals within a tenth of the widening.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "graph/expr.hpp"

namespace vern {

struct Observation {
  double value = 0;
  double count = 1;  // how many examples show it
  // The one example that shows it, when it is one and known (-1: any).
  // One example's value seen at two places (two wings of one depth, in
  // pieces merged from both) is one observation of the style, not two:
  // counted twice, thirty such depths looked like a choice of thirty values
  // seen twice each.
  std::int64_t example = -1;
};

enum class DistributionKind { Constant, Choice, Uniform, TruncatedNormal };

struct Distribution {
  DistributionKind kind = DistributionKind::Constant;
  std::vector<double> values;  // Constant: one; Choice: the distinct values, ascending
  double lo = 0, hi = 0;       // Uniform, TruncatedNormal: the support
  double mu = 0, sigma = 0;    // TruncatedNormal
  double bic = 0;              // of the chosen model (0 for a constant)
};

struct FitOptions {
  double resolution = 1e-9;  // values this close are one value (the examples' tolerance)
  double floor = -std::numeric_limits<double>::infinity();  // sizes: 0
  bool uniform_only = false;  // `--distributions uniform`: min-max ranges, as the thesis
};

// observations must not be empty.
Distribution fit_distribution(const std::vector<Observation>& observations, const FitOptions& options);

// Values on an evenly spaced row (a door bay after one, two or four bays
// of 4.3 m: 4.3, 8.6, 17.2): every point of the row from the smallest
// value seen to the largest, the step the largest that spaces them all
// (a whole share of the smallest gap), as long as the distinct values
// seen, three or more, fill half the row's points or more, and the
// values, counted with their repeats, are two more than the points. None
// otherwise: values drawn from a range lie on no such row, and values
// each seen once, evenly spread or not, are a range.
std::optional<std::vector<double>> even_row(const std::vector<double>& values, double resolution);

// A size's distribution (a part's length, a plot's): sizes stay positive,
// and one seen in every example never vanishes (a zero length would drop
// the part from the structure), so the support stops at half the smallest
// size seen. observations must not be empty.
Distribution fit_size(const std::vector<Observation>& sizes, double resolution, bool uniform_only);

// A count drawn as the counts seen say (tiers of a recursion, tiles of a
// row whose count does not follow its length): randint(lo, hi) where they
// run without a gap (the counts between are as likely as those seen),
// else choice(...) of them, or the one count. counts must not be empty.
Expr count_expr(std::vector<double> counts);

// The distribution as the grammar writes it: a literal, choice(...),
// rand(lo, hi) or tnormal(mu, sigma, lo, hi).
Expr distribution_expr(const Distribution& d);

// The distribution a size expression writes, where it is one that
// distribution_expr writes, of literal numbers (choice's values sorted);
// none for anything else (rand(0, s1), 2 * rand(1, 2)).
std::optional<Distribution> written_distribution(const Expr& e);

// The distribution's numbers as short decimals: values and support bounds
// the shortest within `tolerance` either way (tidy_numbers.hpp says why),
// mu and sigma to about a hundredth of sigma.
Distribution short_decimals(Distribution d, double tolerance);

}  // namespace vern
