// Numbers a person would write (graph/writer.hpp), without
// losing exactness: every example must still derive within tolerance.
//
//   - A split whose relative parts are all literals writes them as small
//     whole ratios when the lengths allow it: ~6.666666666666667 :
//     ~3.3333333333333335 is ~2 : ~1, and ~0.40383 : 1.2 : ~0.80767 is
//     ~1 : 1.2 : ~2 (the weights are metres, as inference writes them: no
//     cut between the relative parts may move by more than the tolerance;
//     the absolute parts are rounded as below).
//   - Any other literal becomes the shortest decimal within the tolerance:
//     0.30000000000000004 is 0.3.
//   - A range rand(lo, hi) rounds each bound to the shortest decimal within
//     the tolerance, either way: a Blender scene's 15.800001 (a float's
//     noise) is 15.8. An example at a bound then lies outside the range by
//     less than the tolerance, and check takes it, as it takes any size
//     within the tolerance; rounding outward kept the noise in the text,
//     and an OBJ and a GLB of one scene gave different grammars.
#pragma once

#include "graph/grammar.hpp"

namespace vern {

// The shortest decimal within tolerance of v (direction < 0: not above v;
// > 0: not below v; 0: either side).
double shortest_decimal(double v, double tolerance, int direction = 0);

// Small whole ratios for a split's relative sizes, if they exist: whole
// n_i <= max_whole with r_i = k * n_i to 1e-9 relative, or, given a
// tolerance (in the sizes' unit, metres for inference's weights), with
// every cut between them, at the n_i's shares of the sizes' total, within
// it: a modelling tool's 6.666667 : 3.333333 is 2 : 1. The fewest units
// that fit win.
std::optional<std::vector<double>> whole_ratios(const std::vector<double>& sizes, double tolerance = 0,
                                                int max_whole = 60);

// Rewrites the sizes below root; returns the new root (nodes interned in g).
NodeId tidy_numbers(Grammar& g, NodeId root, double tolerance);

}  // namespace vern
