// Buildings that stand at an angle about z: a house modelled, or placed in
// a scene, turned 30 degrees. Inference works on each part's box along x,
// y and z; the boxes of a turned house's walls and roof reach past their
// parts and overlap one another, and it was refused as overlapping parts.
//
// A building's angle is read from its square parts: each part's outline
// seen from above (the convex hull of its vertices in x and y) whose
// smallest enclosing rectangle (CGAL's min_rectangle_2) is the outline
// itself, a box's or a gable roof's, turned by that rectangle's angle
// modulo a quarter turn. When every square part stands at one angle, not
// 0 (a quarter turn is another matter: turned_examples.hpp), the building
// stands at it; parts of other outlines (a round tower) follow the
// others. A building with any square part along x and y is not turned,
// and is known to be at its first such part: nearly every file is read in
// no time.
//
// Turned back about the centre of its bounds, the building is read as
// it stands in its own frame: the grammar describes the building, and
// where a scene placed it, at what angle, is the scene's (generate lays
// its buildings out along x and y).
#pragma once

#include <optional>

#include "inverse/load/example.hpp"

namespace vern {

// The angle in radians, in (0, pi/2), that the example's square parts all
// stand at about z modulo a quarter turn, when they do (within
// `tolerance` metres at their extent). Turned back by it, a house turned
// by 0 to 90 degrees is in the frame it was modelled in; one turned by
// 120 is a quarter turn from it, which inference takes as it takes
// houses turned a quarter (turned_examples.hpp). Nothing for a building
// along x and y, or without vertex positions, or whose square parts stand
// at different angles.
std::optional<double> building_angle(const Example& example, double tolerance);

// The example turned by -angle about z through the centre of its bounds:
// its parts' positions and its labels' meshes turned, each part's box
// that of its turned positions (parts without positions keep their box
// turned, as a box: only buildings with positions have an angle).
Example turned_back(const Example& example, double angle);

}  // namespace vern
