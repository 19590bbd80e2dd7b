// A derived building as an inference example, without a file in between:
// what `generate -o x.obj` then `load_example(x.obj)` gives, in memory.
// Used where grammars are judged by round trips (evaluate, tests).
#pragma once

#include <string>

#include "forward/derive.hpp"
#include "inverse/load/example.hpp"

namespace vern {

// One labelled box per terminal (its world bounds), objects named
// "label.<index>" as an exporter would, no meshes. Bounds are computed.
Example example_from_derivation(const Derivation& d, std::string source);

// The example moved so its bounds start at the origin, as check and infer
// place every example ("each example at its own origin").
Example at_origin(Example example);
// The same for checking, which reads the boxes alone: the meshes and the
// parts' vertex positions (12 MB for the city's ten) are not copied.
Example boxes_at_origin(const Example& example);

}  // namespace vern
