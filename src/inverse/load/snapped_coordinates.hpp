// Examples as measurements: coordinates that measure one place made one.
//
// Annotated facades and models people make carry noise: the windows of one
// row are annotated a pixel or two apart, a column's edges wander by as
// much. Cut as they are, every window stands on a level of its own, no two
// rows share their cuts and nothing repeats. Given a noise level (infer
// --tolerance), each axis's coordinates of an example are gathered into
// clusters that never span more than it (coordinate_clusters.hpp: three
// windows 0.04 m apart at a level of 0.05 m are two places, not one), and
// each coordinate becomes its cluster's median, counted over every box
// bound (a facade's edge that many parts share stays where they put it),
// moved within its cluster where it can to lie more than the level past
// the place before it (no sliver thinner than the noise between two
// places). No coordinate moves by more than the noise level, so a grammar
// of the snapped example derives the example as it is, within that level.
#pragma once

#include "inverse/load/example.hpp"

namespace vern {

// `example` with every box bound on each axis snapped to the median of its
// cluster within `tolerance`, and its parts' positions moved with their
// bounds (a position on a bound moves with it; others stay). Bounds are
// updated. Snapping can make a part flat on an axis (both faces within the
// noise level), never inside out.
Example snapped_coordinates(const Example& example, double tolerance);

// The most any box bound of `as_read` moved in `snapped`, its snapped
// copy (the same boxes in the same order).
double largest_move(const Example& as_read, const Example& snapped);

}  // namespace vern
