// Alternatives that are runs of one tile, told apart only by how many
// tiles the examples happened to show: one repeat.
//
// Storeys under a roof that takes a share of a house's height come two to
// a house on most plots and three on the tallest. Merging sees the two of
// a house alike only once examples are unified, and then writes them as
// a pair (repeatN(z, 2)), while houses of three fold into a stretching
// repeat at once: a choice of the two, each with its own tile. A variant
// that draws the pair on a tall plot gets two storeys of 3.4 m where the
// style makes three, and one that draws the repeat gets the tile that
// three storeys alone allowed.
//
// The examples say more than each alternative does: every run was seen
// with a count on a length, and where one tile size gives every count on
// its length (common_tile, settle_repeats.hpp), the runs are that repeat.
// Alternatives along one axis share one tile where one explains all of
// their runs (storeys holding one kind of row or another: a choice kept
// per building); else those that hold the same tile do.
// The runs each repeat made are read from the examples' derivations (the
// witnesses check finds), so every place a repeat stands is counted, and
// the whole change is kept only if every example still derives.
#pragma once

#include <cstddef>
#include <vector>

#include "graph/grammar.hpp"
#include "inverse/check/derives_examples.hpp"
#include "inverse/load/example.hpp"

namespace vern {

// Every choice of the written grammar g whose options hold runs at one
// place: the option itself, a call of a rule whose body is a run or a
// choice of runs (that body rewritten), or a place reached through up to
// four splits in options that hold the same parts elsewhere (their sizes
// aside: each keeps its own). Runs at one place in two or more options,
// not already one repeat, become repeats of the tile that gives every
// count seen on its length (common_tile, settle_repeats.hpp): one tile
// for every such place along an axis where one explains them all, else
// each place's runs along one axis, else those repeating one tile.
// Options so alike are joined. Returns how many choices changed (0: g as
// it was, also where a change would lose an example). witnesses: g's,
// read where known, else checked; g's again when it returns.
std::size_t join_tile_run_alternatives(Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options,
                                       Witnesses& witnesses);

}  // namespace vern
