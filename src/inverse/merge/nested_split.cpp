#include "inverse/merge/nested_split.hpp"

#include <algorithm>


namespace vern {

namespace {

// Three rows at least: two rows put almost any run in a fixed ratio to
// the rest by chance of rounding. Past 32 parts (rows of windows) the
// search, cubic in the parts, is not tried.
constexpr std::size_t kFewestRows = 3, kMostParts = 32;
// Runs nested in pairs are searched over rows of at most this many parts
// (the search is of the fourth power in the parts).
constexpr std::size_t kMostPairedParts = 12;

// What the row as one split draws: its drawn plan's draws, else every
// part plan_sizes leaves unfixed (the split keeps their ranges).
std::size_t draws_of_whole(const std::vector<std::vector<double>>& lengths, const std::vector<PartPlan>& whole,
                           double tolerance) {
  if (const auto drawn = plan_drawn_sizes(lengths, whole, tolerance)) return draws_of(*drawn);
  return static_cast<std::size_t>(std::count_if(whole.begin(), whole.end(), [](const PartPlan& p) { return !p.fixed; }));
}

// Rows worth searching: enough of them, of one part count in [fewest,
// most], and only a row that one split cannot give with fixed sizes: a
// row that varies in its totals (plan_sizes has a plan) and keeps a part
// unfixed.
bool worth_nesting(const std::vector<std::vector<double>>& lengths, const std::optional<std::vector<PartPlan>>& whole,
                   std::size_t fewest, std::size_t most) {
  if (lengths.size() < kFewestRows) return false;
  const std::size_t parts = lengths[0].size();
  if (parts < fewest || parts > most) return false;
  for (const auto& row : lengths)
    if (row.size() != parts) return false;
  return whole && !std::all_of(whole->begin(), whole->end(), [](const PartPlan& p) { return p.fixed; });
}

}  // namespace

std::vector<std::vector<double>> outer_lengths(const std::vector<std::vector<double>>& lengths, NestedRun run) {
  std::vector<std::vector<double>> out;
  out.reserve(lengths.size());
  for (const auto& row : lengths) {
    std::vector<double> r(row.begin(), row.begin() + static_cast<std::ptrdiff_t>(run.first));
    double sum = 0;
    for (std::size_t i = run.first; i <= run.last; ++i) sum += row[i];
    r.push_back(sum);
    r.insert(r.end(), row.begin() + static_cast<std::ptrdiff_t>(run.last + 1), row.end());
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<std::vector<double>> inner_lengths(const std::vector<std::vector<double>>& lengths, NestedRun run) {
  std::vector<std::vector<double>> out;
  out.reserve(lengths.size());
  for (const auto& row : lengths)
    out.emplace_back(row.begin() + static_cast<std::ptrdiff_t>(run.first),
                     row.begin() + static_cast<std::ptrdiff_t>(run.last + 1));
  return out;
}

std::optional<NestedRun> find_nested_run(const std::vector<std::vector<double>>& lengths,
                                         const std::optional<std::vector<PartPlan>>& whole, double tolerance) {
  if (!worth_nesting(lengths, whole, 3, kMostParts)) return std::nullopt;
  const std::size_t parts = lengths[0].size();
  std::size_t fewest = draws_of_whole(lengths, *whole, tolerance);
  std::optional<NestedRun> best;
  for (std::size_t length = 2; length < parts && fewest > 0; ++length) {
    for (std::size_t first = 0; first + length <= parts && fewest > 0; ++first) {
      NestedRun run{first, first + length - 1, {}, {}};
      auto inner = planned_sizes(inner_lengths(lengths, run), tolerance);
      if (!inner || draws_of(*inner) >= fewest) continue;
      auto outer = planned_sizes(outer_lengths(lengths, run), tolerance);
      if (!outer || draws_of(*inner) + draws_of(*outer) >= fewest) continue;
      fewest = draws_of(*inner) + draws_of(*outer);
      run.outer = std::move(*outer);
      run.inner = std::move(*inner);
      best = std::move(run);
    }
  }
  return best;
}

std::optional<NestedRun> find_fixed_run_leading_on(const std::vector<std::vector<double>>& lengths,
                                                   const std::optional<std::vector<PartPlan>>& whole,
                                                   double tolerance) {
  if (!worth_nesting(lengths, whole, 4, kMostPairedParts)) return std::nullopt;
  const std::size_t parts = lengths[0].size();
  std::size_t fewest = draws_of_whole(lengths, *whole, tolerance);
  std::optional<NestedRun> best;
  for (std::size_t length = 2; length + 1 < parts && fewest > 0; ++length) {
    for (std::size_t first = 0; first + length <= parts && fewest > 0; ++first) {
      NestedRun run{first, first + length - 1, {}, {}};
      auto inner = planned_sizes(inner_lengths(lengths, run), tolerance);
      if (!inner || draws_of(*inner) > 0) continue;
      const std::vector<std::vector<double>> outer_rows = outer_lengths(lengths, run);
      auto outer = planned_sizes(outer_rows, tolerance);
      if (!outer) continue;
      const auto second = find_nested_run(outer_rows, plan_sizes(outer_rows, tolerance), tolerance);
      if (!second || draws_of(second->inner) + draws_of(second->outer) >= fewest) continue;
      fewest = draws_of(second->inner) + draws_of(second->outer);
      run.outer = std::move(*outer);
      run.inner = std::move(*inner);
      best = std::move(run);
    }
  }
  return best;
}

}  // namespace vern
