// Copying a subgraph from one grammar into another, interned.
//
// Inference builds every example's graph in one grammar so that identical
// parts are one node; tests and tools that start from grammar text use this
// to bring parsed graphs into such a grammar.
#pragma once

#include "graph/grammar.hpp"

namespace vern {

// Copies the subgraph below `node` of `from` into `to` (interned, so equal
// parts are shared with what `to` already holds) and returns its id there.
// Primitive labels are re-interned by name. Calls cannot be copied (their
// rules belong to `from`): the subgraph must be rule-free, else Internal error.
NodeId import_subgraph(Grammar& to, const Grammar& from, NodeId node);

}  // namespace vern
