// Is a derived building physically sensible? Parts that share volume, and
// parts outside the plot, are what a person would call broken output
// (the thesis's floating tiers and elongated balcony bars show as both).
//
// Parts are compared by their world-space bounding boxes, which are exact
// for axis-aligned scopes and quarter turns; a part turned by another angle
// counts by its bounding box, so it may be reported where its true shape
// would not overlap. Parts thinner than the tolerance on some axis (comp()
// faces, flat panels) have no volume and never overlap.
#pragma once

#include <cstddef>
#include <string>

#include "forward/derive.hpp"

namespace vern {

struct LayoutFaults {
  std::size_t overlaps = 0;  // pairs of parts sharing volume deeper than the tolerance
  std::size_t outside = 0;   // parts reaching further than the tolerance outside the start scope
  // The first fault found, for messages: "'window' #12 overlaps 'wall' #3 by 0.2 x 0.1 x 1".
  std::string first;
  bool valid() const { return overlaps == 0 && outside == 0; }
};

// tolerance <= 0: 1e-6 of the start scope's largest size.
LayoutFaults find_faults(const Derivation& d, double tolerance = 0);

}  // namespace vern
