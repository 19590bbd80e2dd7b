// Structural hashing and equality of operation graphs.
//
// Two graphs are equal when they would derive the same buildings by the
// same steps: same operations, same expressions, same primitive names, same
// rules called, whatever the node ids, the order nodes were added in, or
// the source locations. The inverse pipeline hash-conses with these, and
// the writer is tested with them (parse(write(g)) == g).
#pragma once

#include <cstddef>
#include <vector>

#include "graph/grammar.hpp"

namespace vern {

// Hash of one operation with its children taken by id: what Grammar::intern
// needs, since interned children already stand for their whole subgraphs.
std::size_t shallow_hash(const Operation& op);

// Hash of the whole subgraph below a node; primitives by name, calls by the
// called rule's label. Equal subgraphs hash equally across grammars.
std::size_t structural_hash(const Grammar& g, NodeId node);

// structural_hash of every node of g, by id, each subgraph hashed once:
// for passes that compare many nodes with many (a single structural_hash
// hashes its whole subgraph again every call).
std::vector<std::size_t> structural_hashes(const Grammar& g);

// Are the subgraphs below a (in ga) and b (in gb) structurally equal?
bool structurally_equal(const Grammar& ga, NodeId a, const Grammar& gb, NodeId b);

// Whole grammars: start rule, @scope, @primitives, constants (names and
// values, in order), rules (labels, parameter counts, bodies, in order).
// Parameter names and source text do not count.
bool equal_grammars(const Grammar& a, const Grammar& b);

}  // namespace vern
