// "Did you mean ...?" for unknown names: rules, options, functions, colours.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace vern {

// Levenshtein distance between two names.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate closest to name when it is close enough to be a likely typo.
std::string closest_name(std::string_view name, const std::vector<std::string>& candidates);

// A hint for an unknown name: "did you mean 'garage'?" when one candidate is
// close, otherwise "<what> are: a, b, c" (at most 12 listed).
std::string suggest(std::string_view name, const std::vector<std::string>& candidates, const std::string& what);

}  // namespace vern
