#include "inverse/check/check_text.hpp"

#include <cmath>
#include <cstdio>
#include <variant>
#include <vector>

#include "graph/writer.hpp"

namespace vern::check_detail {

std::string num(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v == 0 ? 0.0 : v);
  return text;
}

std::string loc_text(SourceLoc l) { return l.known() ? std::to_string(l.line) + ":" + std::to_string(l.column) : "?"; }

std::string bounds_text(const glm::dvec3& lo, const glm::dvec3& hi) {
  return "x " + num(lo.x) + ".." + num(hi.x) + ", y " + num(lo.y) + ".." + num(hi.y) + ", z " + num(lo.z) + ".." +
         num(hi.z);
}

std::string box_text(const LabelledBox& b) {
  std::string name = b.object.empty() || b.object == b.label ? "'" + b.label + "'" : describe_object(b);
  return name + " (" + bounds_text(b.min, b.max) + ")";
}

std::string expr_text(const Grammar& g, const Expr& e, RuleId rule) {
  static const std::vector<std::string> no_names;
  return write_expression(g, e, rule == kNone ? no_names : g.rules[rule].params);
}

std::string op_text(const Grammar& g, NodeId id, RuleId rule) {
  const Operation& op = g.op(id);
  std::string t = operation_name(op);
  if (const auto* s = std::get_if<Split>(&op)) t += "(" + expr_text(g, s->axis, rule) + ")";
  if (const auto* r = std::get_if<Repeat>(&op)) t += "(" + expr_text(g, r->axis, rule) + ")";
  if (const auto* r = std::get_if<RepeatN>(&op)) t += "(" + expr_text(g, r->axis, rule) + ")";
  if (const auto* p = std::get_if<Primitive>(&op)) t += "(" + g.label(p->label) + ")";
  if (const auto* c = std::get_if<Call>(&op)) t = g.rules[c->rule].label;
  return t;
}

std::string node_ref(const Grammar& g, NodeId id, RuleId rule) {
  return op_text(g, id, rule) + " at " + loc_text(g.node(id).loc);
}

std::string choose_name(const Grammar& g, NodeId id, RuleId rule) {
  const bool is_body = rule != kNone && g.rules[rule].body == id;
  return is_body ? g.rules[rule].label : "choice at " + loc_text(g.node(id).loc);
}

}  // namespace vern::check_detail
