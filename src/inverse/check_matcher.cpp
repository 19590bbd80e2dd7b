// The matcher's walk (check_matcher.hpp): one node at a time, each kind of
// operation sent to where it is matched; terminals, nil, transforms and
// comp faces here, with the evaluation of expressions they all use.
#include "inverse/check_matcher.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <variant>
#include <vector>

#include "forward/evaluate.hpp"

namespace vern::check_detail {

Matcher::Matcher(const Grammar& g, const std::vector<LabelledBox>& boxes, double tolerance, Budget& budget,
                 DeterministicSubtrees& deterministic, std::vector<Slot> constants, std::vector<Unknown> unknowns,
                 bool floating)
    : g_(g),
      boxes_(boxes),
      tol_(tolerance),
      budget_(budget),
      deterministic_(deterministic),
      vars_(std::move(constants), std::move(unknowns)),
      cuts_(boxes, tolerance),
      empty_(g, lookup_),
      floating_(floating) {
  lookup_ = [this](ExprKind kind, std::uint32_t index) { return vars_.binding(kind, index); };
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
  const bool fixed = std::none_of(e.nodes().begin(), e.nodes().end(), [&](const ExprNode& n) {
    return n.kind == ExprKind::Param || (n.kind == ExprKind::Constant && vars_.constant(n.index).unknown >= 0);
  });
  if (fixed) {
    const auto hit = fixed_values_.find(&e);
    if (hit != fixed_values_.end()) return hit->second;
  }
  auto name = [&] { return std::string(what) + (number ? " " + std::to_string(number) : ""); };
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
  for (std::size_t i = 0; i < op.parts.size(); ++i)
    if (!match(op.parts[i].child, faces[i], parts[i])) return false;
  return true;
}

// ---- lengths ----
// Length queries (check_matcher.hpp, check_free_scope.hpp): for a part
// that ends in empty space, the lengths at which its child derives exactly
// its boxes. Each kind of operation answers for its own scope: terminals
// by their world bounds, splits by their placements (SplitSearch collects
// instead of matching), repeats by their tile counts.

Support Matcher::lengths(NodeId id, const FreeScope& fs, const BoxList& inside) {
  budget_.step();
  const Marks m = marks();
  ++depth_;
  ++quiet_;
  Support r = lengths_dispatch(id, fs, inside);
  --quiet_;
  --depth_;
  restore(m, false);
  return r.clamp(fs.lmin, fs.lmax);
}

Support Matcher::lengths_dispatch(NodeId id, const FreeScope& fs, const BoxList& inside) {
  const Operation& op = g_.op(id);
  const Support all = Support::range(fs.lmin, fs.lmax);
  if (const auto* p = std::get_if<Primitive>(&op)) return lengths_terminal(g_.label(p->label), fs, inside);
  if (std::holds_alternative<Colour>(op)) return lengths_terminal("rect", fs, inside);
  if (std::holds_alternative<Nil>(op)) return inside.empty() ? all : Support{};
  if (const auto* sp = std::get_if<Split>(&op)) return lengths_split(id, *sp, fs, inside);
  const Scope probe = fs.at(fs.lmax);
  if (std::holds_alternative<Repeat>(op) || std::holds_alternative<RepeatN>(op)) return lengths_repeat(id, fs, inside);
  if (const auto* c = std::get_if<Choose>(&op)) {
    auto o = options_of(id, *c, probe);
    if (!o) return {};
    Support acc = o->nil_possible && inside.empty() ? all : Support{};
    for (std::size_t i = 0; i < c->options.size(); ++i)
      if (o->applicable[i]) acc = acc.unite(lengths(c->options[i].child, fs, inside));
    return acc;
  }
  if (const auto* c = std::get_if<Call>(&op)) {
    auto setup = setup_call(id, *c, probe);
    if (!setup) return {};
    const NodeId body_id = g_.rules[c->rule].body;
    Support acc;
    auto body = [&] {
      acc = acc.unite(lengths(body_id, fs, inside));
      return false;
    };
    each_binding(id, *c, setup->first, setup->second, 0, body);
    return acc;
  }
  if (std::holds_alternative<Comp>(op)) {
    open_ends_unsupported_ = true;
    return {};
  }
  if (auto f = transform(id, probe)) return lengths(node_children(op)[0], compose(fs, *f), inside);
  return {};
}

Support Matcher::lengths_terminal(const std::string& label, const FreeScope& fs, const BoxList& inside) {
  if (inside.size() != 1 || boxes_[inside[0]].label != label) return {};
  const LabelledBox& b = boxes_[inside[0]];
  const int w = fs.world;
  auto fits = [&](double l) {
    const Bounds sb = world_bounds(fs.at(l));
    for (int k = 0; k < 3; ++k)
      if (std::abs(b.min[k] - sb.min[k]) > tol_ || std::abs(b.max[k] - sb.max[k]) > tol_) return false;
    return true;
  };
  if (!(fs.lmax > fs.lmin)) return fits(fs.lmax) ? Support::point(fs.lmax) : Support{};
  const Bounds b0 = world_bounds(fs.at(fs.lmin)), b1 = world_bounds(fs.at(fs.lmax));
  const double span = fs.lmax - fs.lmin;
  const double dlo = (b1.min[w] - b0.min[w]) / span, dhi = (b1.max[w] - b0.max[w]) / span;
  double l;
  if (std::abs(dhi) > 1e-12)
    l = fs.lmin + (b.max[w] - b0.max[w]) / dhi;
  else if (std::abs(dlo) > 1e-12)
    l = fs.lmin + (b.min[w] - b0.min[w]) / dlo;
  else
    return fits(fs.lmin) ? Support::range(fs.lmin, fs.lmax) : Support{};
  if (l < fs.lmin - tol_ || l > fs.lmax + tol_) return {};
  l = std::clamp(l, fs.lmin, fs.lmax);
  return fits(l) ? Support::point(l) : Support{};
}

Support Matcher::lengths_repeat(NodeId id, const FreeScope& fs, const BoxList& inside) {
  const Scope probe = fs.at(fs.lmax);
  auto st = setup_repeat(id, probe);
  if (!st) return {};
  if (!st->am) {
    open_ends_unsupported_ = true;
    return {};
  }
  if (st->am->world == fs.world) return lengths_repeat_along(id, fs, inside, *st);
  const double length = probe.size[static_cast<int>(st->axis)];
  std::vector<BoxList> tiles;
  Support acc;
  for (const TileCount& c : st->counts) {
    budget_.step();
    if (c.n <= 0) {
      if (inside.empty()) acc = Support::range(fs.lmin, fs.lmax);
      continue;
    }
    const auto n = static_cast<std::uint64_t>(c.n);
    if (!tiles_fit(inside, *st->am, length, n, tiles)) continue;
    const double tile = length / c.n;
    Support here = Support::range(fs.lmin, fs.lmax);
    for (std::uint64_t i = 0; i < n && !here.empty(); ++i) {
      const Axis a = st->axis;
      const double from = tile * static_cast<double>(i);
      here = here.intersect(lengths(
          st->child, compose(fs, [a, from, tile](const Scope& sc) { return sc.slice(a, from, tile); }), tiles[i]));
    }
    acc = acc.unite(here);
  }
  return acc;
}

Support Matcher::lengths_repeat_along(NodeId id, const FreeScope& fs, const BoxList& inside, const RepeatSetup& st) {
  const Scope s0 = fs.at(fs.lmin), s1 = fs.at(fs.lmax);
  const AxisMap& am = *st.am;
  const int a = static_cast<int>(st.axis);
  const Support all = Support::range(fs.lmin, fs.lmax);
  const double span = fs.lmax - fs.lmin, l0 = s0.size[a], l1 = s1.size[a];
  if (!(span > 0) || std::abs(l1 - l0) < 1e-12 * std::max(1.0, span)) return match(id, s1, inside) ? all : Support{};
  if (std::abs(s0.origin[am.world] - s1.origin[am.world]) > tol_) {
    open_ends_unsupported_ = true;  // the tiles start at the moving end
    return {};
  }
  const double slope = (l1 - l0) / span;
  auto l_of = [&](double length) { return fs.lmin + (length - l0) / slope; };
  const Operation& op = g_.op(id);
  const auto* rep = std::get_if<Repeat>(&op);
  Support sizes;
  if (rep) {
    auto size = evaluate(rep->size, id, s1, "the tile size");
    if (!size) return {};
    sizes = size->support.clamp(std::numeric_limits<double>::min(), kInf);
  }
  // Does some tile size give n tiles on length L? (repeatN: its counts.)
  auto count_fits = [&](double n, double length) {
    if (!rep) return std::any_of(st.counts.begin(), st.counts.end(), [&](const TileCount& c) { return c.n == n; });
    return !sizes.clamp(length / n * (1 - 1e-9), n > 1 ? length / (n - 1) : kInf).empty();
  };
  double last = 0;
  std::vector<double> faces;
  for (std::uint32_t k : inside)
    for (double w : {boxes_[k].min[am.world], boxes_[k].max[am.world]}) {
      faces.push_back(am.local(w));
      last = std::max(last, faces.back());
    }
  std::sort(faces.begin(), faces.end());
  Support acc;
  // One tile: the scope itself.
  if (rep) {
    if (sizes.upper() >= l0 * (1 - 1e-9))
      acc = lengths(st.child, fs, inside).clamp(fs.lmin, sizes.upper() >= l1 ? fs.lmax : l_of(sizes.upper()));
  } else if (count_fits(1, 0)) {
    acc = lengths(st.child, fs, inside);
  }
  double n_max = rep ? std::floor(l1 / sizes.lower()) + 1 : 0;
  for (const TileCount& c : st.counts) n_max = std::max(n_max, c.n);
  n_max = std::min(n_max, static_cast<double>(2 * inside.size() + 2));
  std::vector<BoxList> tiles;
  for (double n = 2; n <= n_max; n += 1) {
    double previous = -kInf;
    for (double c : faces) {
      budget_.step();
      const double length = n * c;
      if (c - previous <= tol_ || length < last - tol_ || length > l1 + tol_ || length < l0 - tol_) continue;
      previous = c;
      if (!count_fits(n, length)) continue;
      const double l = std::clamp(l_of(length), fs.lmin, fs.lmax);
      const Scope sc = fs.at(l);
      const auto count = static_cast<std::uint64_t>(n);
      if (!tiles_fit(inside, am, sc.size[a], count, tiles)) continue;
      const double tile = sc.size[a] / n;
      bool ok = true;
      for (std::uint64_t i = 0; i < count && ok; ++i)
        ok = match(st.child, sc.slice(st.axis, tile * static_cast<double>(i), tile), tiles[i]);
      if (ok) acc = acc.unite(Support::point(l));
    }
  }
  return acc;
}

Support Matcher::lengths_split(NodeId id, const Split& op, const FreeScope& fs, const BoxList& inside) {
  const Scope probe = fs.at(fs.lmax);
  auto st = setup_split(id, op, probe, inside, &fs);
  if (!st) return {};
  Support acc;
  each_sizing(id, op, probe, *st, [&] {
    bool zero_relative = true, any_absolute = false;
    for (const auto& p : st->parts) {
      if (p.relative)
        zero_relative = zero_relative && p.share.contains(0.0);
      else
        any_absolute = true;
    }
    SplitSearch search(*this, id, op, probe, *st, &fs);
    search.run(Mode::Fill);
    if (any_absolute) search.run(Mode::Overflow);
    if (zero_relative) search.run(Mode::NoFill);
    acc = acc.unite(search.collected());
    return false;
  });
  return acc;
}

}  // namespace vern::check_detail
