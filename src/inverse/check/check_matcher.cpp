// The matcher's walk (check_matcher.hpp): one node at a time, each kind of
// operation sent to where it is matched; terminals, nil, transforms and
// comp faces here, with the evaluation of expressions they all use.
#include "inverse/check/check_matcher.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "forward/evaluate.hpp"

namespace vern::check_detail {

Matcher::Matcher(const Grammar& g, const std::vector<LabelledBox>& boxes, double tolerance, double cut_tolerance,
                 Budget& budget,
                 DeterministicSubtrees& deterministic, std::vector<Slot> constants, std::vector<Unknown> unknowns,
                 bool floating, bool learned_order, bool answer_only)
    : g_(g),
      boxes_(boxes),
      tol_(tolerance),
      budget_(budget),
      deterministic_(deterministic),
      vars_(std::move(constants), std::move(unknowns)),
      cuts_(boxes, tolerance, cut_tolerance),
      empty_(g, lookup_),
      floating_(floating),
      learned_order_(learned_order),
      answer_only_(answer_only) {
  lookup_ = [this](ExprKind kind, std::uint32_t index) {
    if (kind != kScopeSize) return vars_.binding(kind, index);
    if (scope_) return Binding{true, Value(scope_->size[static_cast<glm::length_t>(index)]), {}};
    return Binding{false, {}, Support::range(0, kInf)};
  };
}

bool Matcher::run(const Scope& start, const BoxList& all) {
  const Rule& rule = g_.rules[g_.start_rule];
  vars_.enter({g_.start_rule, {}});
  if (!rule.params.empty()) {
    depth_ = 0;
    return fail(rule.body, start, "cannot check: the start rule '" + rule.label + "' takes parameters");
  }
  return match(rule.body, start, all);
}

void Matcher::restore(const Marks& m, bool keep) {
  if (!keep) {
    witness_.resize(m.witness);
    vars_.undo(m.trail);
  }
  vars_.drop_unknowns(m.unknowns);
}

std::optional<Possible> Matcher::evaluate(const Expr& e, NodeId id, const Scope& s, const char* what,
                                          std::size_t number) {
  // Kept once computed where it reads nothing that changes: no parameter,
  // no constant still unknown, not the scope.
  const bool fixed = std::none_of(e.nodes().begin(), e.nodes().end(), [&](const ExprNode& n) {
    return n.kind == ExprKind::Param || (n.kind == ExprKind::Constant && vars_.constant(n.index).unknown >= 0) ||
           (n.kind == ExprKind::Call && static_cast<Function>(n.op) == Function::Size);
  });
  if (fixed) {
    const auto hit = fixed_values_.find(&e);
    if (hit != fixed_values_.end()) return hit->second;
  }
  auto name = [&] { return std::string(what) + (number ? " " + std::to_string(number) : ""); };
  scope_ = &s;
  try {
    Possible p = possible_values(e, lookup_);
    if (fixed) fixed_values_.emplace(&e, p);
    return p;
  } catch (const EvaluationError& err) {
    if (recording()) fail(id, s, name() + " cannot be evaluated (" + err.message + "), so derive() fails here");
  } catch (const NotCheckable& nc) {
    cannot_check(id, s, name() + ": " + nc.message);
  }
  return std::nullopt;
}

std::optional<double> Matcher::exact_number(const Expr& e, NodeId id, const Scope& s, const char* what) {
  auto p = evaluate(e, id, s, what);
  if (!p) return std::nullopt;
  if (!p->exact) {
    cannot_check(id, s, std::string(what) + " is random (" + expr_text(e) + ")");
    return std::nullopt;
  }
  if (!p->value.is_number()) {
    if (recording()) fail(id, s, std::string(what) + " must be a number, found " + p->value.describe());
    return std::nullopt;
  }
  return p->value.number();
}

std::optional<Axis> Matcher::exact_axis(const Expr& e, NodeId id, const Scope& s, const char* what) {
  auto p = evaluate(e, id, s, what);
  if (!p) return std::nullopt;
  if (!p->exact) {
    cannot_check(id, s, std::string(what) + " is random (" + expr_text(e) + ")");
    return std::nullopt;
  }
  if (auto a = p->value.to_axis()) return a;
  if (recording()) fail(id, s, std::string(what) + " must be an axis, found " + p->value.describe());
  return std::nullopt;
}

bool Matcher::match(NodeId id, const Scope& s, const BoxList& inside) {
  budget_.step();
  const Marks m = marks();
  ++depth_;
  path_.push_back(derivation_path(path_.back(), id, slot_));
  slot_ = 0;
  // Only where the grammar below has one outcome and places contents
  // with T or S: the one place the matcher may not follow it.
  const bool placed = deterministic_.placed(id);
  const Mismatch before = placed ? best_ : Mismatch{};
  bool ok = dispatch(id, s, inside);
  if (!ok && placed) {
    restore(m, false);
    ok = derives_here(id, s, inside, before);
  }
  path_.pop_back();
  --depth_;
  restore(m, ok);
  return ok;
}

bool Matcher::derives_here(NodeId id, const Scope& s, const BoxList& inside, const Mismatch& before) {
  for (std::size_t k = 0; k < inside.size(); ++k) budget_.step();
  const auto why = deterministic_.difference(id, s, boxes_, inside, tol_, box_text);
  if (quiet_ == 0) best_ = before;
  if (!why) return true;
  return fail(id, s, *why);
}

bool Matcher::dispatch(NodeId id, const Scope& s, const BoxList& inside) {
  const Operation& op = g_.op(id);
  if (const auto* p = std::get_if<Primitive>(&op)) return match_terminal(id, g_.label(p->label), s, inside);
  if (std::holds_alternative<Colour>(op)) return match_terminal(id, "rect", s, inside);
  if (std::holds_alternative<Nil>(op)) {
    if (inside.empty()) return true;
    return recording() && fail(id, s, "expected empty space, found " + list_boxes(inside));
  }
  if (const auto* sp = std::get_if<Split>(&op)) return match_split(id, *sp, s, inside);
  if (std::holds_alternative<Repeat>(op) || std::holds_alternative<RepeatN>(op)) return match_repeat(id, s, inside);
  if (const auto* c = std::get_if<Choose>(&op)) return match_choose(id, *c, s, inside);
  if (const auto* c = std::get_if<Call>(&op)) return match_call(id, *c, s, inside);
  if (const auto* c = std::get_if<Comp>(&op)) return match_comp(id, *c, s, inside);
  if (auto f = transform(id, s)) return match(node_children(op)[0], (*f)(s), inside);
  return false;
}

bool Matcher::match_terminal(NodeId id, const std::string& label, const Scope& s, const BoxList& inside) {
  const Bounds b = world_bounds(s);
  if (inside.empty()) return recording() && fail(id, s, "expected a '" + label + "' box filling the scope, found none");
  if (inside.size() > 1)
    return recording() &&
           fail(id, s,
                "expected one '" + label + "' box, found " + std::to_string(inside.size()) + ": " + list_boxes(inside));
  const LabelledBox& box = boxes_[inside[0]];
  if (box.label != label) return recording() && fail(id, s, "expected a '" + label + "' box, found " + box_text(box));
  for (int k = 0; k < 3; ++k)
    if (std::abs(box.min[k] - b.min[k]) > tol_ || std::abs(box.max[k] - b.max[k]) > tol_)
      return recording() && fail(id, s, "the box " + box_text(box) + " does not fill the scope");
  return true;
}

std::optional<std::function<Scope(const Scope&)>> Matcher::transform(NodeId id, const Scope& s) {
  const Operation& op = g_.op(id);
  if (const auto* t = std::get_if<Translate>(&op)) {
    std::array<double, 3> v{};
    std::array<bool, 3> rel{};
    for (std::size_t i = 0; i < 3; ++i) {
      auto x = exact_number(t->offset[i].value, id, s, "a T offset");
      if (!x) return std::nullopt;
      v[i] = *x;
      rel[i] = t->offset[i].relative;
    }
    return [v, rel](const Scope& in) {
      glm::dvec3 d(0.0);
      for (int i = 0; i < 3; ++i) d[i] = rel[i] ? v[i] * in.size[i] : v[i];
      Scope out = in;
      out.origin += in.frame * d;
      return out;
    };
  }
  if (const auto* sc = std::get_if<Scale>(&op)) {
    std::array<double, 3> v{};
    std::array<bool, 3> rel{};
    for (std::size_t i = 0; i < 3; ++i) {
      auto x = exact_number(sc->size[i].value, id, s, "an S size");
      if (!x) return std::nullopt;
      if (*x < 0) {
        if (recording()) fail(id, s, "an S size is negative (" + num(*x) + "), so derive() fails here");
        return std::nullopt;
      }
      v[i] = *x;
      rel[i] = sc->size[i].relative;
    }
    return [v, rel](const Scope& in) {
      Scope out = in;
      for (int i = 0; i < 3; ++i) out.size[i] = rel[i] ? v[i] * in.size[i] : v[i];
      return out;
    };
  }
  if (const auto* r = std::get_if<Rotate>(&op)) {
    const auto a = exact_axis(r->axis, id, s, "the axis of R");
    if (!a) return std::nullopt;
    const auto angle = exact_number(r->angle, id, s, "the angle of R");
    if (!angle) return std::nullopt;
    return [a = *a, angle = *angle](const Scope& in) { return rotated(in, a, angle); };
  }
  if (recording()) fail(id, s, std::string("unknown operation ") + operation_name(op));
  return std::nullopt;
}

bool Matcher::match_comp(NodeId id, const Comp& op, const Scope& s, const BoxList& inside) {
  std::vector<Scope> faces;
  std::vector<BoxList> parts(op.parts.size());
  for (const auto& part : op.parts) faces.push_back(face_scope(s, part.face));
  for (std::uint32_t k : inside) {
    const LabelledBox& b = boxes_[k];
    bool placed = false;
    for (std::size_t i = 0; i < faces.size() && !placed; ++i) {
      const Bounds f = world_bounds(faces[i]);
      bool within = true;
      for (int w = 0; w < 3; ++w) within = within && b.min[w] >= f.min[w] - tol_ && b.max[w] <= f.max[w] + tol_;
      if (within) {
        parts[i].push_back(k);
        placed = true;
      }
    }
    if (!placed) return recording() && fail(id, s, "the box " + box_text(b) + " lies on none of the faces");
  }
  Finished finished(*this);
  for (std::size_t i = 0; i < op.parts.size(); ++i) {
    if (!match(op.parts[i].child, faces[i], parts[i])) return false;
    finished.add(parts[i].size());
  }
  return true;
}

}  // namespace vern::check_detail
