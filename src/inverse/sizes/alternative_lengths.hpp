// Sizes that scale, read across alternatives (issue 4). size_plan.hpp
// tells an absolute part from a relative one within pieces of one
// structure that span different lengths. Alternatives of one choice are
// often built differently (houses whose ground floors have a door or not,
// and two to five storeys), so each was seen at one length only and says
// nothing by itself: all its sizes would stay shares, and a variant that
// draws a two-storey alternative on a five-storey plot would stretch its
// 4.9 m ground floor to 12 m.
//
// The choice as a whole does say something. Its options all fill the same
// scope; when they were seen at different lengths, a leading (or
// trailing) part whose length is the same in every one of them, however
// it is built (the 0.5 m base slab, the 4.9 m ground floor), is absolute:
// it kept its length while the whole changed. The parts after it stay
// shares of what is left, each option as it was seen, so every example
// still derives exactly.
//
// What lies between the absolute parts stretches with the scope. A run of
// one or two storeys is too short to be a repeat on its own evidence
// (repeat_folding.hpp folds three or more), so on a taller plot it would
// stretch into storeys of 10 m. When a sibling option holds a stretching
// repeat along the same axis that may make each of the run's parts (its
// tile, or one of the tile's choices), whose tile is within a quarter of
// the parts' length and which makes exactly as many tiles on the run's
// length, the run becomes that repeat: each example still gets its own
// storeys, and a variant as many as its height holds. (Options that differ
// then only in their lone share's weight become one when tidy_numbers
// writes every lone share as ~1.)
//
// Options already settled (split along the same axis, with literal
// metres at their ends: seen at several lengths, merged) say it too: an
// option seen at one length whose leading or trailing parts are as long
// as theirs (a 4.4 m ground floor, a 2.8 m roof, where all settled
// options agree) has those parts in metres as well, not shares of the
// one height it was seen at.
//
// Considered: options that split along one literal axis with every size a
// relative literal (an option seen at one length); they must number two
// or more, along one axis, and their lengths must differ, or have settled
// siblings whose ends they share. Each keeps one
// relative part at least, so it fills any scope. Options that are not so
// are left as they are. Only the choice is rebuilt: an option's node,
// which may also stand elsewhere, is not changed in place.
#pragma once

#include "graph/grammar.hpp"

namespace vern {

// The graph below root with such choices rebuilt. tolerance: lengths that
// agree within it are one length, and no part of any option may move by
// more than it.
NodeId absolute_across_alternatives(Grammar& g, NodeId root, double tolerance);

}  // namespace vern
