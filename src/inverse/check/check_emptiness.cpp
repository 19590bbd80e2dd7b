#include "inverse/check/check_emptiness.hpp"

#include <variant>

namespace vern::check_detail {

namespace {

// The axis of x, y or z written as such; -1 for any other expression.
int literal_axis(const Expr& e) {
  const ExprNode& root = e.node(e.root());
  return e.nodes().size() == 1 && root.kind == ExprKind::Axis ? static_cast<int>(root.op) : -1;
}

}  // namespace

Emptiness::Emptiness(const Grammar& g, const BindingLookup& lookup)
    : g_(g),
      lookup_(lookup),
      vanishes_(g.node_count(), -1),
      trails_(3 * static_cast<std::size_t>(g.node_count()), -1),
      nothing_(g.node_count(), -1) {}

bool Emptiness::vanishes(NodeId id) {
  std::int8_t& memo = vanishes_[id];
  if (memo >= 0) return memo == 1;
  memo = 0;  // recursion: assume it derives something
  const Operation& op = g_.op(id);
  bool v = false;
  if (std::holds_alternative<Nil>(op)) {
    v = true;
  } else if (std::holds_alternative<Primitive>(op) || std::holds_alternative<Colour>(op)) {
    v = false;
  } else if (const auto* c = std::get_if<Call>(&op)) {
    v = vanishes(g_.rules[c->rule].body);
  } else {
    v = true;
    for (NodeId child : node_children(op)) v = v && vanishes(child);
  }
  vanishes_[id] = v ? 1 : 0;
  return v;
}

bool Emptiness::may_trail(NodeId id, int a) {
  std::int8_t& memo = trails_[static_cast<std::size_t>(id) * 3 + static_cast<std::size_t>(a)];
  if (memo >= 0) return memo == 1;
  memo = 1;  // recursion: assume it may
  const Operation& op = g_.op(id);
  bool v = true;
  if (std::holds_alternative<Primitive>(op) || std::holds_alternative<Colour>(op)) {
    v = false;
  } else if (const auto* sp = std::get_if<Split>(&op)) {
    const int b = literal_axis(sp->axis);
    if (b == a) {
      // Along a: the last part ends the split unless it may be empty.
      const SplitPart& last = sp->parts.back();
      v = share_may_be_zero(last.size.value) || may_derive_nothing(last.child) || may_trail(last.child, a);
    } else if (b >= 0) {
      // Across: the parts that hold boxes all reach the split's end.
      v = false;
      for (const auto& part : sp->parts) v = v || (!vanishes(part.child) && may_trail(part.child, a));
    }
  } else if (const auto* rep = std::get_if<Repeat>(&op)) {
    v = literal_axis(rep->axis) < 0 || may_trail(rep->child, a);
  } else if (const auto* rn = std::get_if<RepeatN>(&op)) {
    v = literal_axis(rn->axis) < 0 || may_trail(rn->child, a);
  } else if (const auto* ch = std::get_if<Choose>(&op)) {
    v = false;
    for (const auto& o : ch->options) v = v || (!vanishes(o.child) && may_trail(o.child, a));
  } else if (const auto* call = std::get_if<Call>(&op)) {
    v = may_trail(g_.rules[call->rule].body, a);
  }
  trails_[static_cast<std::size_t>(id) * 3 + static_cast<std::size_t>(a)] = v ? 1 : 0;
  return v;
}

bool Emptiness::may_derive_nothing(NodeId id) {
  std::int8_t& memo = nothing_[id];
  if (memo >= 0) return memo == 1;
  memo = 1;
  const Operation& op = g_.op(id);
  bool v = true;
  if (std::holds_alternative<Primitive>(op) || std::holds_alternative<Colour>(op)) {
    v = false;
  } else if (const auto* sp = std::get_if<Split>(&op)) {
    // Nothing at all only when every part may give nothing.
    v = literal_axis(sp->axis) < 0;
    bool all = true;
    for (const auto& part : sp->parts)
      all = all && (share_may_be_zero(part.size.value) || may_derive_nothing(part.child));
    v = v || all;
  } else if (const auto* rep = std::get_if<Repeat>(&op)) {
    v = may_derive_nothing(rep->child);
  } else if (const auto* ch = std::get_if<Choose>(&op)) {
    v = false;
    for (const auto& o : ch->options) {
      const auto priority = o.priority.literal();
      v = v || !o.condition.empty() || (!o.priority.empty() && !(priority && *priority > 0)) ||
          may_derive_nothing(o.child);
    }
  } else if (const auto* call = std::get_if<Call>(&op)) {
    v = may_derive_nothing(g_.rules[call->rule].body);
  }
  nothing_[id] = v ? 1 : 0;
  return v;
}

bool Emptiness::share_may_be_zero(const Expr& e) {
  if (e.uses_params() || e.reads_scope()) return true;  // known only where it stands
  try {
    const Support values = expression_support(e, lookup_);
    return values.empty() || values.contains(0.0);
  } catch (...) {
    return true;
  }
}

}  // namespace vern::check_detail
