// Parts that combine freely: from "these combinations were seen" to "any
// combination of what was seen at each place".
//
// Splits with the same axis, part count, relative flags and proportions
// form a frame (a row of four equal cells, a storey of ground-floor parts).
// When the examples show many distinct fillings of a frame, more than
// twice the number of alternatives seen at its busiest position, its
// positions are taken to vary independently: each position that varies
// becomes a choice among what was seen there (weighted by how often), and
// the frame's members become one split. A frame with few fillings keeps
// them coupled: a roof end that is either two gable halves or two hip
// corners (two fillings of two positions with two alternatives each) never
// gets a half gable beside a corner.
//
// The alternatives of one choice that are splits along one axis into as
// many parts are a frame too, whatever their proportions: they stand for
// one place. Examples that differ only deep down (a roof label, a special
// tile, a kept option) make every example's top split unique, so without
// this a style comes back as one alternative per example. Such a frame is
// joined when saying its varying places independently costs no more bits
// than listing the combinations seen (choice_costs.hpp), or in part: where
// some places said on their own beside the combinations of the others cost
// fewer bits than either (a roof of any kind on houses whose ground floor
// and storeys keep one door bay's place together), the members holding the
// same children at the others become one split each, with a choice at the
// free places; its members' flags
// are those of members built from examples unified, an example's own split
// taking them (its flags say nothing yet). Its weights are the choice's.
//
// Every example stays derivable: its child at each position is one of that
// position's alternatives, and each size lies in its position's range.
#pragma once

#include <utility>
#include <vector>

#include "graph/grammar.hpp"
#include "inverse/merge/merge.hpp"
#include "inverse/merge/sample_book.hpp"

namespace vern {

// Which splits form frames: alike ones (same axis, part count, relative
// flags and proportions) anywhere, and, when asked, also the alternatives
// of one choice that share axis, part count and relative flags whatever
// their proportions. Those are joined once recursion is folded, so that
// a tower's tiers are found nested before their levels are joined.
enum class FrameKinds { Alike, AlikeAndAlternatives };

// Returns the new root, and whether anything was generalised; rebuilt
// gets the nodes above a generalised frame that were rebuilt (substitute),
// joined each frame member with the split that replaced it. The joined
// split's relative sizes range over its members' scaled to one relative
// total: members share their proportions, not their lengths.
NodeId generalise_free_parts(Grammar& g, NodeId root, const MergeOptions& options, FrameKinds kinds,
                             const RowBook& rows, bool& changed,
                             std::vector<std::pair<NodeId, NodeId>>* rebuilt = nullptr,
                             std::vector<std::pair<NodeId, NodeId>>* joined = nullptr);

}  // namespace vern
