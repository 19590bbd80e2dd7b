// The triangles of a building, to draw it (report/raster.hpp): a derived
// one from its terminals, an example from its parts as read.
//
// Each part is coloured as the written files colour it (io/palette.hpp),
// so a picture in a report and the same building in a viewer agree.
#pragma once

#include <vector>

#include "forward/derive.hpp"
#include "forward/primitive_library.hpp"
#include "inverse/load/example.hpp"
#include "report/raster.hpp"

namespace vern {

// Each terminal's primitive (from `library`; the unit box for a name it does
// not hold, as derive's writers do) placed in its scope.
std::vector<RasterTriangle> derived_triangles(const Derivation& building, const PrimitiveLibrary& library);

// Each part with its own mesh as the file gave it, where the reader kept it
// (a label's first part; later parts whose vertices are the first's moved,
// scaled or turned by quarter turns about z, as copies are), else its box
// (a piece of a part painted over, layered_parts.hpp).
std::vector<RasterTriangle> example_triangles(const Example& example);

}  // namespace vern
