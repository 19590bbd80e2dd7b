// Rules nothing calls any more (after joint_sizes wrote their bodies out
// inside a region's rule) are dropped; the others keep their order. The
// result is a fresh grammar of what is still used: derive() compiles every
// node a grammar holds, and the dropped rules' calls would name rules gone.
#pragma once

#include "graph/grammar.hpp"

namespace vern {

void drop_unused_rules(Grammar& g);

}  // namespace vern
