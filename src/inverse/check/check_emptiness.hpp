// Where a node of a grammar may leave empty space, whatever its scope and
// draws (for check.hpp), found from the grammar alone.
//
// A split's search asks this before it lets a part end inside the empty
// space after its last box, or lets a part hold no box: trying such
// placements costs far more than the answer, and only nodes that can
// derive nothing, or stop short of their scope's end, may need them. The
// answers over-approximate (a size that uses a parameter may be 0, an axis
// given by a parameter may be any), so the search never misses a placement
// derive() could make; each is memoised per node.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "graph/grammar.hpp"
#include "inverse/sizes/support.hpp"

namespace vern::check_detail {

class Emptiness {
 public:
  // lookup: the names' values while checking, for sizes that use constants.
  Emptiness(const Grammar& g, const BindingLookup& lookup);

  // Derives nothing whatever the scope and the draws (nil, or only nils).
  bool vanishes(NodeId id);
  // Can what node `id` derives stop short of its scope's end along its own
  // axis a, leaving empty space there? Only then may a part holding it end
  // in empty space. Axes given by parameters, sizes that use parameters and
  // transforms all count as "may".
  bool may_trail(NodeId id, int a);
  // Can node `id` derive nothing at all in some case (a nil alternative,
  // a zero share, a condition that fails)? Over-approximated like may_trail.
  bool may_derive_nothing(NodeId id);

 private:
  // May a size be 0? Sizes that use parameters may; others are evaluated
  // (constants are known, or unknowns with a support).
  bool share_may_be_zero(const Expr& e);

  const Grammar& g_;
  const BindingLookup& lookup_;
  std::vector<std::int8_t> vanishes_;  // per node: -1 not yet known, 0 no, 1 yes
  std::vector<std::int8_t> trails_;    // per node and axis
  std::vector<std::int8_t> nothing_;   // per node
};

}  // namespace vern::check_detail
