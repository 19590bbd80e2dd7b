// The chain of rules a derivation is inside, as errors name it:
// "plot > house(3) > floors(2)".
//
// derive() and check stop a runaway grammar with the same kind of message
// (docs/grammar.md, "Errors and warnings": errors name file:line:column and the chain of rules), so the
// chain is spelled here for both. Past twelve rules the middle is left out
// ("plot > a > b > c > ... (990 more) ... > x > y"): a recursion a thousand
// calls deep still gives a message a person can read.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

#include "graph/grammar.hpp"

namespace vern {

// `depth` running rules, outermost first: rule(i) is the i-th, and arg(i, k)
// the text of its k-th argument. "(none)" when no rule runs.
std::string rule_chain_text(const Grammar& g, std::size_t depth, const std::function<RuleId(std::size_t)>& rule,
                            const std::function<std::string(std::size_t, std::size_t)>& arg);

}  // namespace vern
