// Buildings to and from the forward engine's derivations and scenes.
// Private to src/api/.
#pragma once

#include "forward/derive.hpp"
#include "forward/terminal.hpp"
#include "vernacular/derive.hpp"

namespace vernacular::detail {

Building building_of(const vern::Derivation& derivation);

// The buildings as a derivation each, all with one label table (a scene's
// buildings share theirs), to lay out and write.
std::vector<vern::Derivation> derivations_of(const std::vector<Building>& buildings);

}  // namespace vernacular::detail
