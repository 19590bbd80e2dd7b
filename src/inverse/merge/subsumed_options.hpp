// Alternatives that other alternatives already derive: dropped.
//
// Inference keeps an alternative for each structure the examples show.
// Where later steps generalise one of them (bays each a window or a door
// become a repeat of a bay whose opening is a choice), the examples of a
// narrower alternative beside it (the houses whose row happened to hold
// one door, which keeps its place) may now derive from the general one:
// the narrow alternative then only draws variants the examples never
// asked for (a door bay off the bays' grid). So:
//   - an alternative that examples take (by the witnesses check finds),
//     the least used of its choice first, and only one taken by at most
//     half the examples that reach the choice, is dropped where those
//     examples derive without it; its weight goes to the alternatives they
//     take then. Each is tried once, within a budget of examples checked
//     (about a quarter of a check of them all): hundreds of one-example alternatives
//     (a facade dataset) cost a bounded number of checks;
//   - then every alternative no example's witness takes is dropped (the
//     examples derive by their witnesses as before).
// A choice with conditions, or with priorities that are not numbers, is
// left as it is.
#pragma once

#include <cstddef>
#include <vector>

#include "graph/grammar.hpp"
#include "inverse/check/derives_examples.hpp"
#include "inverse/load/example.hpp"

namespace vern {

// Rewrites g in place; returns how many alternatives were dropped (0: g
// as it was, also where g does not derive every example to begin with).
// witnesses: g's, read where known, else checked; not known when it
// returns having dropped any (they would name choices since rebuilt).
std::size_t drop_subsumed_options(Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options,
                                  Witnesses& witnesses);

}  // namespace vern
