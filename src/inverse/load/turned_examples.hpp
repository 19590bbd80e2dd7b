// Whole buildings turned a quarter about z (issue 16, item 5): a user who
// models some houses with their ridge along x and turns others to face
// the other way, or exports from a tool that did, gives examples whose
// cuts run along y where the others' run along x. Merged as they are,
// each orientation is a structure of its own. Recognised as turned, each
// is the same house, written `R(z, pi / 2){ ... }` where turned.
//
// How: the layout of an example, as the ordered-box splitting cuts it
// (axes, order and labels, runs of alike pieces as one, sizes left out),
// is compared with the layouts of the others, each turned by 0 to 3
// quarter turns. Of the layouts some example shows as it is, the one most
// examples can show is the common one (of those as many can show, the one
// most show as they are); an example that
// shows it only turned a quarter (either way) is turned back to it; a
// half turn is left as it is, as the mirror image a person sees in it
// (the garage on the other side of the house).
// Examples that show it as they are, or that no turn makes show it, are
// left as they are.
#pragma once

#include <vector>

#include "inverse/load/example.hpp"
#include "inverse/split/box_split.hpp"

namespace vern {

// Per example, the quarter turns about z (0, 1 or 3, counterclockwise
// seen from above) that bring it to the layout the examples share.
// trees: each example as split_boxes cut it, as it is (the layouts turned
// are cut here, on up to `threads` threads; the same answer on any number).
std::vector<int> common_orientation(const std::vector<Example>& examples, const std::vector<SplitTree>& trees,
                                    double tolerance, unsigned threads = 1);

// The example turned by `quarters` quarter turns about z (its boxes, its
// labels' meshes and its parts' positions).
Example turned_example(const Example& example, int quarters);

}  // namespace vern
