// Which rules can reach a call of themselves, directly or through the
// rules they call: a recursion's body runs at several depths, each a
// different place (joint_sizes never enters one), and its count is what
// it runs down (scope_by_count reads only such counts).
#pragma once

#include <vector>

#include "graph/grammar.hpp"

namespace vern {

// By rule id: true where the rule recurses.
std::vector<bool> recursive_rules(const Grammar& g);

}  // namespace vern
