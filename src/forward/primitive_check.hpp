// Which primitives a grammar inserts that the library does not have.
//
// docs/grammar.md, I(name): an unknown primitive inserts a box labelled with its name and
// warns once, naming the known primitives. The check runs before deriving,
// from the graph, so the warning points at the first I(name) in the file.
#pragma once

#include <string>
#include <vector>

#include "forward/primitive_library.hpp"
#include "graph/grammar.hpp"

namespace vern {

// One warning per unknown primitive name ("file:line:col: warning: ...").
std::vector<std::string> unknown_primitive_warnings(const Grammar& grammar, const PrimitiveLibrary& library);

}  // namespace vern
