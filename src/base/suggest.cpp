#include "base/suggest.hpp"

#include <algorithm>

namespace vern {

std::optional<std::size_t> edit_distance_within(std::string_view a, std::string_view b, std::size_t limit) {
  if (a.size() > b.size()) std::swap(a, b);
  if (b.size() - a.size() > limit) return std::nullopt;  // that many insertions at least
  // row[j] is the distance from a's first i characters to b's first j,
  // for the j within `limit` of i; `over` stands for every larger value.
  const std::size_t over = limit + 1;
  std::vector<std::size_t> row(b.size() + 1, over);
  for (std::size_t j = 0; j <= std::min(b.size(), limit); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    const std::size_t first = i > limit ? i - limit : 1;
    const std::size_t last = std::min(b.size(), i + limit);
    std::size_t diagonal = row[first - 1];
    std::size_t left = first == 1 ? std::min(i, over) : over;
    if (first == 1) row[0] = left;
    std::size_t smallest = left;
    for (std::size_t j = first; j <= last; ++j) {
      const std::size_t up = row[j];
      const std::size_t substitute = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      const std::size_t d = std::min({up + 1, left + 1, substitute, over});
      diagonal = up;
      row[j] = left = d;
      smallest = std::min(smallest, d);
    }
    if (smallest > limit) return std::nullopt;  // every path goes through this row
  }
  if (row[b.size()] > limit) return std::nullopt;
  return row[b.size()];
}

std::string closest_name(std::string_view name, const std::vector<std::string>& candidates) {
  // A third of the name's length (at least 2) counts as a typo, not a new
  // word; and no more than 8 edits, which a name of up to 26 characters
  // never reaches: more is a different name, and it would only make each
  // comparison cost more.
  std::size_t limit = std::min<std::size_t>(std::max<std::size_t>(2, name.size() / 3), 8);
  std::string best;
  for (const auto& c : candidates) {
    const auto d = edit_distance_within(name, c, limit);
    if (!d) continue;
    best = c;
    if (*d == 0) break;
    limit = *d - 1;  // the first of the closest wins: only a closer one replaces it
  }
  return best;
}

std::string suggest(std::string_view name, const std::vector<std::string>& candidates, const std::string& what) {
  if (auto best = closest_name(name, candidates); !best.empty()) return "did you mean '" + shown_name(best) + "'?";
  return listed(candidates, what);
}

std::string listed(const std::vector<std::string>& candidates, const std::string& what) {
  if (candidates.empty()) return "there are no " + what;
  std::string list;
  for (std::size_t i = 0; i < candidates.size() && i < 12; ++i) list += (i ? ", " : "") + shown_name(candidates[i]);
  if (candidates.size() > 12) list += ", ...";
  return what + " are: " + list;
}

}  // namespace vern
