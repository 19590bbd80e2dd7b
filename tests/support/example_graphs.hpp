// Example graphs written as grammar text, for the merging tests: each text
// is one example's graph as inference builds it (splits with relative
// sizes in metres), all imported into one interned grammar.
#pragma once

#include <string>
#include <vector>

#include "graph/import.hpp"
#include "graph/parser.hpp"
#include "inverse/merge/merge.hpp"

namespace vern::test {

inline std::vector<NodeId> example_graphs(Grammar& g, const std::vector<std::string>& texts) {
  std::vector<NodeId> roots;
  for (const auto& t : texts) {
    const Grammar parsed = parse_grammar("e --> " + t);
    roots.push_back(import_subgraph(g, parsed, parsed.rules[0].body));
  }
  return roots;
}

// Merging exactly (1e-9), varying sizes as rand(min, max): what the
// merging tests compare written grammars with.
inline MergeOptions uniform_merge() {
  MergeOptions o;
  o.tolerance = 1e-9;
  o.uniform_distributions = true;
  return o;
}

}  // namespace vern::test
