// How much a grammar says: the size measure inference tries to keep small
// (issue 4, "compactness"; the thesis's city came back as hundreds of rules).
//
// A written grammar is rules, operations and the numbers in them, counted
// as a reader reads them: every operation written in every rule body (a
// rule call is one operation; the rule's body counts once, in its rule).
// Numbers are the free parameters: each literal is a value someone had to
// choose (axes, faces and rule names are not counted).
#pragma once

#include <cstddef>

#include "graph/grammar.hpp"

namespace vern {

struct DescriptionLength {
  std::size_t rules = 0;
  std::size_t operations = 0;  // operations written in the rule bodies
  std::size_t numbers = 0;     // number literals in them, the constants and @scope
  // The one figure tables report: operations + numbers.
  std::size_t total() const { return operations + numbers; }
};

DescriptionLength description_length(const Grammar& grammar);

// The number literals of one expression: what it adds to `numbers`.
std::size_t number_literals(const Expr& e);

}  // namespace vern
