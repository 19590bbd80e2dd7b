// The grammar writer: an operation graph back to grammar text.
//
// The contract (tests/writer_test.cpp holds it to it): for every grammar g that
// write_grammar accepts, parse_grammar(write_grammar(g)) is structurally
// equal to g (equal_grammars), and the text reads like a person wrote it:
// one rule per line, infix expressions with no more parentheses than the
// parse needs, numbers in their shortest exact form, and a split or comp
// broken over several lines, one part per line, only when its rule would
// not fit the width otherwise.
//
// What cannot be written throws vern::Error (Internal), because it is a
// graph that no parse could give: a Choose anywhere but a rule body, two
// rules with one label, a name that is not an identifier, a number that is
// not finite, a parameter slot past the rule's parameter list.
//
// Output is deterministic: the same graph always gives the same bytes.
#pragma once

#include <string>
#include <vector>

#include "graph/grammar.hpp"

namespace vern {

struct WriteOptions {
  int width = 80;  // columns a line may take before a split or comp breaks
  int indent = 4;  // spaces per nesting level of a broken split or comp
};

// The whole grammar: @start, @scope, @primitives, constants, a blank line,
// then the rules in g.rules order. Ends with exactly one newline.
std::string write_grammar(const Grammar& g, const WriteOptions& options = {});

// One expression on one line; param_names[i] names parameter slot i.
// An empty Expr gives "".
std::string write_expression(const Grammar& g, const Expr& e, const std::vector<std::string>& param_names);

// One operation as it would appear after a rule's arrow (possibly over
// several lines, without a final newline): for messages and tools.
std::string write_operation(const Grammar& g, NodeId node, const std::vector<std::string>& param_names,
                            const WriteOptions& options = {});

}  // namespace vern
