// Alternatives built alike but at one place are one alternative with a
// choice there (issue 4, compactness).
//
// Inference keeps each example's building as an alternative until merging
// finds them the same. Houses whose slab, ground-floor height and storeys
// agree but whose ground floors are built in twenty ways stay twenty
// alternatives, each writing the whole frame again:
//
//   building --> split(z){ 0.49 : I(rect) | 4.9 : groundA | ~1 : storeys } : 2
//   building --> split(z){ 0.49 : I(rect) | 4.9 : groundB | ~1 : storeys } : 1
//
// They are one frame with a choice at the place where they differ:
//
//   building --> split(z){ 0.49 : I(rect) | 4.9 : groundChoice | ~1 : storeys }
//   groundChoice --> groundA : 2
//   groundChoice --> groundB : 1
//
// This generalises nothing: the buildings and their probabilities are the
// same (the frame is drawn with the sum of the priorities, then the place
// with each alternative's share), so it is done wherever it applies, unlike
// generalise.hpp, which lets places that vary combine freely. Alternatives
// differing at two places stay apart: making both choices would pair every
// ground floor with every storey kind.
//
// Considered: options without a condition and with a literal priority whose
// child is a split; they join when axis, sizes and every child but one are
// the same nodes (so after tidy_numbers, which writes sizes alike). Groups
// are formed largest first, each option in one group at most.
#pragma once

#include "graph/grammar.hpp"

namespace vern {

// The graph below root with every choice so factored.
NodeId share_frames(Grammar& g, NodeId root);

}  // namespace vern
