// How check spells what it reports (check.hpp): numbers, source positions,
// boxes, and the grammar's expressions and operations.
//
// Mismatches and witness lines name a node the same way ("split(x) at
// 24:10", "choice at 12:3"), with the parameter names of the rule it runs
// in, so a user can find it in the grammar file whichever message they read.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <string>

#include "graph/grammar.hpp"
#include "inverse/load/example.hpp"

namespace vern::check_detail {

// No rule: an expression outside every rule (a constant), or no call.
inline constexpr std::uint32_t kNone = ~std::uint32_t{0};

// "6.5", "0.333333", "inf": coordinates and values.
std::string num(double v);
// "24:10", or "?" for a node built by code.
std::string loc_text(SourceLoc l);
// "x 0..6.5, y 0..10, z 0..3"
std::string bounds_text(const glm::dvec3& lo, const glm::dvec3& hi);
// "'window' (x 0..1, y 0..0.2, z 1..2)", with the object's name when it is not the label.
std::string box_text(const LabelledBox& b);

// An expression as written, with the parameter names of `rule` (kNone: none).
std::string expr_text(const Grammar& g, const Expr& e, RuleId rule);
// "split(x)", "repeatN(y)", "I(window)", a called rule's label.
std::string op_text(const Grammar& g, NodeId id, RuleId rule);
// "split(x) at 24:10"
std::string node_ref(const Grammar& g, NodeId id, RuleId rule);
// A choose: the rule's label when it is the rule's body, else "choice at 12:3".
std::string choose_name(const Grammar& g, NodeId id, RuleId rule);

}  // namespace vern::check_detail
