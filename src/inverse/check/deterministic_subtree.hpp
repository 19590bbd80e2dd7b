// Subtrees with one outcome, checked by deriving them (for check.hpp).
//
// check's matcher follows a split by cutting the example's boxes where no
// box crosses, so it cannot follow parts whose contents leave their slice:
// the S placements inference writes for a pinwheel (placements.hpp) reach
// into the next piece, and no cut lies between the pieces. But where the
// grammar below a node has one outcome (no random draw, no choice between
// alternatives, no random constant, no parameter but those a call below
// passes as fixed values), the node derives one
// thing on a given scope: deriving it there with the forward engine and
// comparing its terminals with the example's boxes is exact, whatever the
// operations do.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "forward/scope.hpp"
#include "graph/grammar.hpp"
#include "inverse/load/example.hpp"

namespace vern {

class DeterministicSubtrees {
 public:
  explicit DeterministicSubtrees(const Grammar& g);

  // Has node `id` one outcome, with a T or an S below it (through calls)?
  // Only there can contents leave their part's slice; elsewhere the
  // matcher follows the grammar itself.
  bool placed(NodeId id);

  // Why node `id`, derived on scope s, does not give exactly the boxes
  // `inside` (indices into `boxes`), each coordinate within `tolerance`;
  // nullopt when it does. A derivation error counts as a difference.
  // describe names a box in the message.
  std::optional<std::string> difference(NodeId id, const Scope& s, const std::vector<LabelledBox>& boxes,
                                        const std::vector<std::uint32_t>& inside, double tolerance,
                                        const std::function<std::string(const LabelledBox&)>& describe);

 private:
  // Per node: kUnknown, kRandom, or kFixed with the bits kPlaced (a T or
  // S below) and kReadsParams (a parameter of its rule in it or below,
  // short of a call: fixed where its rule's call passes fixed values).
  static constexpr std::int8_t kUnknown = -1, kRandom = 0, kFixed = 1, kPlaced = 2, kReadsParams = 4;
  std::int8_t classify(NodeId id);
  bool fixed(const Expr& e) const;

  const Grammar& g_;
  std::vector<std::int8_t> memo_;        // per node: see classify
  std::vector<bool> fixed_constants_;    // per constant: no draw in it or the constants it uses
  std::optional<Grammar> probe_;         // g_ plus a rule deriving the node asked about (made once)
};

}  // namespace vern
