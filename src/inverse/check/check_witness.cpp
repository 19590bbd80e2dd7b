#include "inverse/check/check_witness.hpp"

#include <variant>

namespace vern::check_detail {

namespace {

// "randint(3, 5) in floors at 12:7", "constant randint(8, 10)".
std::string origin_text(const Grammar& g, const Origin& o) {
  if (!o.expr) return "?";
  if (o.rule == kNone && o.call == kNone) return "constant " + expr_text(g, *o.expr, kNone);
  const std::string text = expr_text(g, *o.expr, o.rule);
  return o.call == kNone ? text : text + " in " + node_ref(g, o.call, o.rule);
}

}  // namespace

std::string witness_text(const Grammar& g, const WitnessLine& w) {
  const std::string rule = w.rule == kNone ? "?" : g.rules[w.rule].label;
  switch (w.kind) {
    case WitnessLine::Kind::Alternative: {
      const auto& op = std::get<Choose>(g.op(w.node));
      return choose_name(g, w.node, w.rule) + ": alternative " + std::to_string(w.index + 1) + " of " +
             std::to_string(w.count) + " (" + node_ref(g, op.options[w.index].child, w.rule) + ")";
    }
    case WitnessLine::Kind::NoAlternative:
      return choose_name(g, w.node, w.rule) + ": no alternative applies, nothing derived";
    case WitnessLine::Kind::Value:
      return rule + ", " + node_ref(g, w.node, w.rule) + ": " + w.name + " = " + num(w.value) + " (" +
             origin_text(g, w.origin) + ")";
    case WitnessLine::Kind::Part: {
      const Size& size = std::get<Split>(g.op(w.node)).parts[w.index].size;
      return rule + ", " + node_ref(g, w.node, w.rule) + ", part " + std::to_string(w.index + 1) + ": " + num(w.value) +
             " (" + (size.relative ? "~" : "") + expr_text(g, size.value, w.rule) + ")";
    }
    case WitnessLine::Kind::Tiles: {
      const Operation& op = g.op(w.node);
      const auto* r = std::get_if<Repeat>(&op);
      const std::string what =
          r ? "size " + expr_text(g, r->size, w.rule) : "count " + expr_text(g, std::get<RepeatN>(op).count, w.rule);
      return rule + ", " + node_ref(g, w.node, w.rule) + ": " + num(w.value) + " tiles" +
             (w.size > 0 ? ", size " + num(w.size) : "") + " (" + what + ")";
    }
  }
  return {};
}

}  // namespace vern::check_detail
