// "Did you mean ...?" for unknown names: rules, options, functions, colours.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "graph/label.hpp"  // shown_name: how the names suggested are shown

namespace vern {

// The Levenshtein distance between a and b when it is at most `limit`,
// else nullopt. Only the cells within `limit` of the diagonal can lie on
// such a path, and the work stops at the first row with none within it:
// at most (2 * limit + 1) steps per character of the shorter name, where
// the whole table took the product of both lengths (two names of 400,000
// characters: half a minute).
std::optional<std::size_t> edit_distance_within(std::string_view a, std::string_view b, std::size_t limit);

// The candidate closest to name when it is close enough to be a likely typo.
std::string closest_name(std::string_view name, const std::vector<std::string>& candidates);

// A hint for an unknown name: "did you mean 'garage'?" when one candidate is
// close, otherwise listed(candidates, what).
std::string suggest(std::string_view name, const std::vector<std::string>& candidates, const std::string& what);

// "<what> are: a, b, c" (at most 12 listed), or "there are no <what>".
std::string listed(const std::vector<std::string>& candidates, const std::string& what);


}  // namespace vern
