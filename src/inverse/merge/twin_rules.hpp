// Subgraphs that differ only in an axis or a value become one rule with
// parameters (issue 4, "compactness"; the thesis's "great extension",
// section 12.3).
//
// Merging unifies parts that are identical and turns similar ones into
// ranges, but two parts of one building that are built the same way with
// other numbers (a wing 6 m high and one 4 m high, a facade split along x
// and the same facade along y) stay two copies of one structure:
//
//   split(x){ ~1 : split(z){ 6 : split(y){ 0.5 : I(wall) | ~1 : I(window) | 0.5 : I(wall) } | ~1 : I(roof) }
//           | ~1 : split(z){ 4 : split(y){ 0.5 : I(wall) | ~1 : I(window) | 0.5 : I(wall) } | ~1 : I(roof) } }
//
// Here such copies (twins: equal once every number and axis is blanked
// out) become one rule taking the values they differ in, called with each
// copy's values:
//
//   building --> split(x){ ~1 : wallWindowRoofZ(6) | ~1 : wallWindowRoofZ(4) }
//   wallWindowRoofZ(v1) --> split(z){ v1 : split(y){ ... } | ~1 : I(roof) }
//
// Values the twins share stay written in the rule; slots that vary alike
// (a wall thickness written on both sides) share one parameter. A group of
// twins is joined only where that writes less: the copies' operations and
// numbers (as description_length counts them) against the rule's, plus
// one for the rule, one per parameter and one per argument written; at
// most max_params parameters (a call with more values than that reads worse
// than the copies). Groups are joined largest saving first, in one rewrite
// all those whose twins neither hold nor lie inside another's; rounds
// repeat until none is left, so twins inside twins are joined too. A rule whose body was a
// twin takes the parameters (its callers pass its own values), the first
// such rule in grammar order; the others' callers call it instead.
//
// The grammar derives exactly what it did: the arguments are literals and
// a call draws with its caller's random key (random_stream.hpp), so every
// seed gives the same building, byte for byte. Subgraphs that read a
// parameter of their rule are left alone, but for whole rule bodies: rules
// with parameters whose bodies are twins reading them alike become the
// first of them, taking the values they differ in after its own
// parameters, and every call of any of them passes its own values after
// its arguments (rules that call one of their twins, recursion, stay
// apart).
#pragma once

#include <cstddef>

#include "graph/grammar.hpp"

namespace vern {

struct TwinOptions {
  std::size_t max_params = 4;  // a group differing in more values stays apart
};

struct TwinRules {
  std::size_t rules = 0;   // parameterised rules made (or given parameters)
  std::size_t copies = 0;  // subgraphs they stand in for
};

// Rewrites g in place; rules left uncalled are dropped (unused_rules.hpp).
TwinRules parameterise_twins(Grammar& g, const TwinOptions& options = {});

}  // namespace vern
