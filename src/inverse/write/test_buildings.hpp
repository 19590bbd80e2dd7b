// The buildings infer derives from its grammar before writing it.
//
// A grammar that cannot derive is a bug, better found by infer than by the
// user: an evaluation error is thrown as derive() throws it. A building
// that stops at a limit is no bug: the grammar derives every example, but
// @scope draws each axis from the examples' sizes, and an alternative seen
// only on a small example (a 0.6 m block of 0.1 m bricks beside a 40 m
// house) is derived in a scope many times its size, so its tiles run into
// millions. Such a grammar is written, with a warning that says how large
// a building got and how to keep variants near the examples.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "forward/derive.hpp"
#include "graph/grammar.hpp"

namespace vern {

struct TestBuildingsOptions {
  std::uint64_t first_seed = 1;  // building i uses first_seed + i
  std::uint32_t count = 8;
  DeriveLimits limits;           // infer runs the defaults, as generate does
  std::size_t example_parts = 0;  // the largest example's parts, for the warning
};

// Examples of more parts than this: the test buildings are counted, not
// judged (a city of a million parts).
inline constexpr std::size_t kJudgedParts = 100'000;

// Derives `count` buildings and, where the examples have no more than
// kJudgedParts parts, judges their layouts (layout_faults.hpp: parts
// sharing volume, parts outside the plot). Returns the warnings: at most
// one, for the first building that reached a limit (the others would say
// the same), or else one saying how many buildings were broken and the
// first fault. Throws vern::Error for any other failure of derive().
std::vector<std::string> derive_test_buildings(const Grammar& grammar, const TestBuildingsOptions& options);

// The test buildings for examples of `parts` parts in all, the largest of
// `largest`: eight from first_seed, or one alone past kJudgedParts in all
// (a million parts: a third of a second each). infer and the library's
// infer() both derive these.
TestBuildingsOptions test_buildings_for(std::size_t parts, std::size_t largest, std::uint64_t first_seed);

}  // namespace vern
