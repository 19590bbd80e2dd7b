// From an operation graph to rules a person would write (thesis chapter 11,
// and better): a rule only where a subgraph is shared or is a choice,
// nested operations everywhere else, and names that say what a rule makes.
#pragma once

#include <string>

#include "graph/grammar.hpp"

namespace vern {

struct NamingOptions {
  std::string start = "building";  // the start rule's label
};

// A new grammar whose rules cover the graph below root: the start rule
// (root), one rule per choose and per subgraph used more than once (leaves
// stay inline: I(rect) is clearer than a rule). A rule is named from the
// primitives beneath it, in order of first appearance (at most three), and
// its operation: split(z) over rect and roof is rectRoofZ, a repeat of
// windows windowRowX, a choice between them rectRoofChoice; clashes get 2,
// 3, ... Deriving the result gives the same buildings as deriving root.
Grammar rules_for(const Grammar& graph, NodeId root, const NamingOptions& options = {});

// The name rules_for gives a rule whose body is this node, before it is
// made unique: its first three primitives' labels and what it does
// (rectRoofZ), looking through the rules it calls.
std::string node_name(const Grammar& g, NodeId id);

// base, else base2, base3, ...: the first label no rule of g has and no
// operation is spelled as (for rules added to a named grammar).
std::string free_label(const Grammar& g, const std::string& base);

}  // namespace vern
