#include "inverse/nested_split.hpp"

#include <algorithm>


namespace vern {

namespace {

// Three rows at least: two rows put almost any run in a fixed ratio to
// the rest by chance of rounding. Past 32 parts (rows of windows) the
// search, cubic in the parts, is not tried.
constexpr std::size_t kFewestRows = 3, kMostParts = 32;

// One split's plan for the rows, if it fixes every size. plan_sizes has
// none when the rows' totals agree: such a run keeps its parts' lengths
// and is no nesting.
std::optional<std::vector<PartPlan>> fixed_plan(const std::vector<std::vector<double>>& lengths, double tolerance) {
  auto plan = plan_sizes(lengths, tolerance);
  if (!plan || !std::all_of(plan->begin(), plan->end(), [](const PartPlan& p) { return p.fixed; })) return std::nullopt;
  return plan;
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
  if (lengths.size() < kFewestRows) return std::nullopt;
  const std::size_t parts = lengths[0].size();
  if (parts < 3 || parts > kMostParts) return std::nullopt;
  for (const auto& row : lengths)
    if (row.size() != parts) return std::nullopt;
  // Only a row that one split cannot give with fixed sizes: a row that
  // varies in its totals (plan_sizes has a plan) and keeps a part unfixed.
  if (!whole || std::all_of(whole->begin(), whole->end(), [](const PartPlan& p) { return p.fixed; }))
    return std::nullopt;
  for (std::size_t length = 2; length < parts; ++length) {
    for (std::size_t first = 0; first + length <= parts; ++first) {
      NestedRun run{first, first + length - 1, {}, {}};
      auto outer = fixed_plan(outer_lengths(lengths, run), tolerance);
      if (!outer) continue;
      auto inner = fixed_plan(inner_lengths(lengths, run), tolerance);
      if (!inner) continue;
      run.outer = std::move(*outer);
      run.inner = std::move(*inner);
      return run;
    }
  }
  return std::nullopt;
}

}  // namespace vern
