// Example graphs written as grammar text, for the merging tests: each text
// is one example's graph as inference builds it (splits with relative
// sizes in metres), all imported into one interned grammar.
#pragma once

#include <string>
#include <vector>

#include "graph/import.hpp"
#include "graph/parser.hpp"

namespace vern::test {

inline std::vector<NodeId> example_graphs(Grammar& g, const std::vector<std::string>& texts) {
  std::vector<NodeId> roots;
  for (const auto& t : texts) {
    const Grammar parsed = parse_grammar("e --> " + t);
    roots.push_back(import_subgraph(g, parsed, parsed.rules[0].body));
  }
  return roots;
}

}  // namespace vern::test
