#include "inverse/check.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <tuple>
#include <unordered_map>

#include "forward/evaluate.hpp"
#include "forward/scope.hpp"
#include "graph/error.hpp"
#include "graph/writer.hpp"
#include "inverse/check_bindings.hpp"
#include "inverse/check_budget.hpp"
#include "inverse/check_cuts.hpp"
#include "inverse/check_emptiness.hpp"
#include "inverse/check_scale.hpp"
#include "inverse/check_text.hpp"
#include "inverse/check_witness.hpp"
#include "inverse/deterministic_subtree.hpp"
#include "inverse/support.hpp"

namespace vern {

using namespace check_detail;

namespace {

// derive()'s default nesting limit: deeper recursion is an error there, so
// no derivation goes deeper.
constexpr std::size_t kMaxDepth = 1000;
// Random values with at most this many possibilities (randint(2, 5),
// choice(...)) are tried one by one, which is exact.
constexpr std::size_t kMaxEnumerated = 64;
// Repeat tile counts tried for one random tile size.
constexpr double kMaxTileCounts = 100000;

struct Mismatch {
  int depth = -1;
  std::string message;
};

struct PartInfo {
  bool relative = false;
  Support share;  // the size's support, negative values removed (derive() fails on them)
  NodeId child = 0;
  bool nil = false;
  bool primitive = false;  // a leaf taking exactly one box
  bool vanishes = false;   // derives nothing on any scope
  bool random = false;     // the size draws or uses an unknown: reported in the witness
};

struct Placement {
  bool filled = false;    // holds boxes: spans cuts [from, to]
  bool floating = false;  // its end lies inside the empty stretch after cut `to`
  std::size_t from = 0, to = 0;
  Support lengths;       // floating: the lengths its child accepts (until queried: all up to the next box)
  double length = 0;     // floating: the length chosen for the witness and the match
  bool queried = false;  // floating: `lengths` comes from the child
};

// A scope whose length along one world axis is left open: at(l) is the
// scope for length l in [lmin, lmax]. A part whose end lies in empty space
// asks its child which lengths it accepts (Matcher::lengths), so a
// boundary no box face marks (the top of a skyscraper plot above its
// towers) is found exactly.
struct FreeScope {
  std::function<Scope(double)> at;
  int world = 0;
  double lmin = 0, lmax = 0;
};

FreeScope compose(const FreeScope& fs, std::function<Scope(const Scope&)> f) {
  return {[at = fs.at, f = std::move(f)](double l) { return f(at(l)); }, fs.world, fs.lmin, fs.lmax};
}

// The parts of a split and how their sizes are evaluated, shared by
// matching and length queries.
struct SplitSetup {
  Axis axis = Axis::X;
  AxisMap am;
  double length = 0;                    // the scope's length along the axis (free axis: the last box face)
  bool free_axis = false;               // the split runs along a FreeScope's open axis
  double l0_length = 0, l1_length = 0;  // free axis: the scope's length at lmin and at lmax
  std::shared_ptr<const Cuts> cuts;
  std::vector<PartInfo> parts;
  std::vector<int> finite;  // unknowns with few values, tried one by one
  std::vector<std::vector<double>> finite_values;
  int solve_for = -1;  // the one continuous unknown, solved per placement
};

struct ArgChoice {
  std::size_t arg;
  std::vector<double> values;
};

struct TileCount {
  double n = 0;
  double size = 0;  // repeat: a tile size giving n tiles
};

class SplitSearch;

class Matcher {
 public:
  // floating: whether a part may end inside empty space (a boundary no box
  // face marks); a first attempt without is far cheaper and settles every
  // example whose boundaries all lie on box faces.
  Matcher(const Grammar& g, const std::vector<LabelledBox>& boxes, double tolerance, Budget& budget,
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

  bool run(const Scope& start, const BoxList& all) {
    const Rule& rule = g_.rules[g_.start_rule];
    vars_.enter({g_.start_rule, {}});
    if (!rule.params.empty()) {
      depth_ = 0;
      return fail(rule.body, start, "cannot check: the start rule '" + rule.label + "' takes parameters");
    }
    return match(rule.body, start, all);
  }

  std::vector<MatchedPart> matched_parts() const {
    std::vector<MatchedPart> out;
    for (const WitnessLine& w : witness_)
      if (w.kind == WitnessLine::Kind::Part) out.push_back({w.path, w.node, w.index, w.length, w.value});
    return out;
  }

  std::vector<std::string> witness() const {
    std::vector<std::string> out;
    out.reserve(witness_.size());
    for (const WitnessLine& w : witness_) out.push_back(witness_text(g_, w));
    return out;
  }
  const Mismatch& mismatch() const { return best_; }
  const std::string& uncheckable() const { return uncheckable_; }
  bool open_ends_unsupported() const { return open_ends_unsupported_; }

 private:
  friend class SplitSearch;

  // Restores what a match or query added: on failure, its witness lines
  // and bindings; always, the unknowns drawn inside it (out of scope now).
  struct Marks {
    std::size_t witness, trail, unknowns;
  };
  Marks marks() const { return {witness_.size(), vars_.trail_size(), vars_.unknown_count()}; }
  void restore(const Marks& m, bool keep) {
    if (!keep) {
      witness_.resize(m.witness);
      vars_.undo(m.trail);
    }
    vars_.drop_unknowns(m.unknowns);
  }

  // ---- messages ----

  std::string rule_label() const { return vars_.rule() == kNone ? "?" : g_.rules[vars_.rule()].label; }

  RuleId current_rule() const { return vars_.rule(); }

  std::string expr_text(const Expr& e, RuleId rule) const { return check_detail::expr_text(g_, e, rule); }
  std::string expr_text(const Expr& e) const { return expr_text(e, current_rule()); }
  std::string node_ref(NodeId id, RuleId rule) const { return check_detail::node_ref(g_, id, rule); }
  std::string node_ref(NodeId id) const { return node_ref(id, current_rule()); }

  WitnessLine line(WitnessLine::Kind kind, NodeId node) const {
    WitnessLine w;
    w.kind = kind;
    w.rule = current_rule();
    w.node = node;
    return w;
  }

  void note_value(NodeId node, const std::string& name, double v, const Origin& origin) {
    WitnessLine w = line(WitnessLine::Kind::Value, node);
    w.name = name;
    w.value = v;
    w.origin = origin;
    witness_.push_back(std::move(w));
  }

  std::string where(NodeId id, const Scope& s) const {
    const Bounds b = world_bounds(s);
    std::string t = "at " + rule_label();
    if (vars_.rule() != kNone) t += " (" + loc_text(g_.rules[vars_.rule()].loc) + ")";
    return t + ", " + node_ref(id) + " on " + bounds_text(b.min, b.max);
  }

  std::string list_boxes(const BoxList& list) const {
    std::string t;
    for (std::size_t k = 0; k < list.size() && k < 3; ++k) t += (k ? ", " : "") + box_text(boxes_[list[k]]);
    if (list.size() > 3) t += ", ... (" + std::to_string(list.size()) + " in all)";
    return t;
  }

  // Would a failure here be recorded? Messages are built only then: most
  // attempts fail, and their text would cost more than the attempt.
  bool recording() const { return quiet_ == 0 && depth_ > best_.depth; }

  // Records why a match failed, keeping the deepest; length queries
  // (quiet) record nothing: their failures are not the example's.
  bool fail(NodeId id, const Scope& s, const std::string& what) {
    if (quiet_ > 0) return false;
    if (depth_ > best_.depth) best_ = {depth_, where(id, s) + ": " + what};
    return false;
  }

  bool cannot_check(NodeId id, const Scope& s, const std::string& what) {
    if (quiet_ > 0) {
      open_ends_unsupported_ = true;
      return false;
    }
    if (uncheckable_.empty()) uncheckable_ = where(id, s) + ": " + what;
    return fail(id, s, "cannot check: " + what);
  }

  // ---- expressions ----

  // What an expression can be here. `what` (and `number`, when not 0)
  // name it in messages. Expressions that use no parameter and no random
  // constant are the same everywhere: their values are kept.
  std::optional<Possible> evaluate(const Expr& e, NodeId id, const Scope& s, const char* what, std::size_t number = 0) {
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

  std::optional<double> exact_number(const Expr& e, NodeId id, const Scope& s, const char* what) {
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

  std::optional<Axis> exact_axis(const Expr& e, NodeId id, const Scope& s, const char* what) {
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

  // ---- matching ----

  // Does node `id`, run on scope s, derive exactly the boxes `inside`?
  bool match(NodeId id, const Scope& s, const BoxList& inside) {
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

  // A node the matcher could not follow, derived on s and compared
  // (deterministic_subtree.hpp): exact, so its verdict replaces what the
  // attempt recorded.
  bool derives_here(NodeId id, const Scope& s, const BoxList& inside, const Mismatch& before) {
    for (std::size_t k = 0; k < inside.size(); ++k) budget_.step();
    const auto why = deterministic_.difference(id, s, boxes_, inside, tol_, box_text);
    if (quiet_ == 0) best_ = before;
    if (!why) return true;
    return fail(id, s, *why);
  }

  bool dispatch(NodeId id, const Scope& s, const BoxList& inside) {
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

  bool match_terminal(NodeId id, const std::string& label, const Scope& s, const BoxList& inside) {
    const Bounds b = world_bounds(s);
    if (inside.empty())
      return recording() && fail(id, s, "expected a '" + label + "' box filling the scope, found none");
    if (inside.size() > 1)
      return recording() && fail(id, s,
                                 "expected one '" + label + "' box, found " + std::to_string(inside.size()) + ": " +
                                     list_boxes(inside));
    const LabelledBox& box = boxes_[inside[0]];
    if (box.label != label) return recording() && fail(id, s, "expected a '" + label + "' box, found " + box_text(box));
    for (int k = 0; k < 3; ++k)
      if (std::abs(box.min[k] - b.min[k]) > tol_ || std::abs(box.max[k] - b.max[k]) > tol_)
        return recording() && fail(id, s, "the box " + box_text(box) + " does not fill the scope");
    return true;
  }

  // T, S and R as functions of the scope (their values must be exact).
  std::optional<std::function<Scope(const Scope&)>> transform(NodeId id, const Scope& s) {
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

  // ---- split ----

  std::string sizes_text(const Split& op) const {
    std::string t;
    for (std::size_t i = 0; i < op.parts.size(); ++i) {
      t += (i ? " : " : "");
      t += (op.parts[i].size.relative ? "~" : "") + expr_text(op.parts[i].size.value);
    }
    return t;
  }

  // The axis, cuts and parts of a split on scope s; with fs, the scope's
  // length along fs's open axis is free (s is its longest form).
  std::optional<SplitSetup> setup_split(NodeId id, const Split& op, const Scope& s, const BoxList& inside,
                                        const FreeScope* fs) {
    SplitSetup st;
    const auto a = exact_axis(op.axis, id, s, "the axis of split");
    if (!a) return std::nullopt;
    st.axis = *a;
    const auto am = axis_map(s, *a);
    if (!am) {
      cannot_check(id, s, "the scope is turned by an angle other than a quarter turn");
      return std::nullopt;
    }
    st.am = *am;
    st.length = s.size[static_cast<int>(*a)];
    if (fs && am->world == fs->world) {
      // Along the open axis: only a split whose start stays put is
      // supported; the last box face ends what is fixed.
      const Scope s0 = fs->at(fs->lmin);
      if (std::abs(s0.origin[am->world] - s.origin[am->world]) > tol_) {
        cannot_check(id, s, "a boundary in empty space at the start of a split");
        return std::nullopt;
      }
      st.free_axis = true;
      st.l0_length = s0.size[static_cast<int>(*a)];
      st.l1_length = st.length;
      double last = 0;
      for (std::uint32_t k : inside)
        last = std::max({last, am->local(boxes_[k].min[am->world]), am->local(boxes_[k].max[am->world])});
      st.length = last;
    }
    st.cuts = cuts_.of(inside, *am, st.length);
    if (!st.cuts->outside.empty()) {
      if (recording()) fail(id, s, "the boxes " + list_boxes(st.cuts->outside) + " lie outside the scope");
      return std::nullopt;
    }
    // Which unknowns the sizes use: few-valued ones are tried value by
    // value, one continuous one is solved for per placement.
    std::vector<int> open;
    for (const auto& part : op.parts) vars_.open_unknowns(part.size.value, open);
    std::vector<int> continuous;
    for (int u : open) {
      if (auto v = vars_.unknown(u).support.values(kMaxEnumerated)) {
        st.finite.push_back(u);
        st.finite_values.push_back(*v);
      } else {
        continuous.push_back(u);
      }
    }
    if (continuous.size() > 1) {
      std::string names;
      for (int u : continuous) names += (names.empty() ? "" : ", ") + vars_.unknown(u).name;
      cannot_check(id, s, "the sizes depend on several random values at once (" + names + ")");
      return std::nullopt;
    }
    st.solve_for = continuous.empty() ? -1 : continuous[0];
    st.parts.resize(op.parts.size());
    for (std::size_t i = 0; i < op.parts.size(); ++i) {
      const Operation& child = g_.op(op.parts[i].child);
      st.parts[i].relative = op.parts[i].size.relative;
      st.parts[i].child = op.parts[i].child;
      st.parts[i].nil = std::holds_alternative<Nil>(child);
      st.parts[i].primitive = std::holds_alternative<Primitive>(child) || std::holds_alternative<Colour>(child);
      st.parts[i].vanishes = empty_.vanishes(op.parts[i].child);
    }
    return st;
  }

  // Calls f() for every combination of the few-valued unknowns, bound, with
  // the part sizes evaluated; stops at the first f() that returns true.
  template <typename F>
  bool each_sizing(NodeId id, const Split& op, const Scope& s, SplitSetup& st, F f) {
    std::vector<std::size_t> pick(st.finite.size(), 0);
    while (true) {
      const std::size_t trail_mark = vars_.trail_size(), witness_mark = witness_.size();
      for (std::size_t k = 0; k < st.finite.size(); ++k) {
        const Unknown& u = vars_.unknown(st.finite[k]);
        const double v = st.finite_values[k][pick[k]];
        vars_.bind(st.finite[k], v);
        note_value(id, u.name, v, u.origin);
      }
      for (std::size_t i = 0; i < op.parts.size(); ++i) {
        auto p = evaluate(op.parts[i].size.value, id, s, "the size of part", i + 1);
        if (!p) return false;
        st.parts[i].share = p->support.clamp(0, kInf);
        st.parts[i].random = !p->exact;
        if (st.parts[i].share.empty()) {
          if (recording())
            fail(id, s,
                 "the size of part " + std::to_string(i + 1) + " (" + expr_text(op.parts[i].size.value) +
                     ") is negative, so derive() fails here");
          return false;
        }
      }
      if (f()) return true;
      vars_.undo(trail_mark);
      witness_.resize(witness_mark);
      std::size_t k = 0;
      while (k < pick.size() && ++pick[k] == st.finite_values[k].size()) pick[k++] = 0;
      if (k == pick.size()) return false;
    }
  }

  bool match_split(NodeId id, const Split& op, const Scope& s, const BoxList& inside);
  Support lengths_split(NodeId id, const Split& op, const FreeScope& fs, const BoxList& inside);

  // ---- repeat ----

  // The tile counts a repeat or repeatN may make on scope s, in order.
  // "size 1" or "count randint(3, 5)": what decides a repeat's tile count.
  std::string repeat_what(NodeId id) const {
    const Operation& op = g_.op(id);
    if (const auto* r = std::get_if<Repeat>(&op)) return "size " + expr_text(r->size);
    return "count " + expr_text(std::get<RepeatN>(op).count);
  }

  std::optional<std::vector<TileCount>> tile_counts(NodeId id, const Scope& s, Axis a, bool& random) {
    const Operation& op = g_.op(id);
    const double length = s.size[static_cast<int>(a)];
    std::vector<TileCount> out;
    if (const auto* r = std::get_if<Repeat>(&op)) {
      auto size = evaluate(r->size, id, s, "the tile size");
      if (!size) return std::nullopt;
      random = !size->exact;
      auto count_for = [&](double tile) { return repeat_tile_count(length, tile); };
      const Support sizes = size->support.clamp(std::numeric_limits<double>::min(), kInf);
      if (sizes.empty()) {
        if (recording()) fail(id, s, "the tile size " + expr_text(r->size) + " is never > 0, so derive() fails here");
        return std::nullopt;
      }
      if (size->exact) return std::vector<TileCount>{{count_for(sizes.lower()), sizes.lower()}};
      const double n_min = count_for(sizes.upper()), n_max = count_for(sizes.lower());
      if (!std::isfinite(n_max) || n_max - n_min > kMaxTileCounts) {
        cannot_check(id, s, "the tile size " + expr_text(r->size) + " allows too many tile counts");
        return std::nullopt;
      }
      for (double n = n_min; n <= n_max; n += 1) {
        // Some size of the support must give exactly n tiles.
        const Support fitting = sizes.clamp(length / n * (1 - 1e-9), n > 1 ? length / (n - 1) : kInf);
        if (!fitting.empty())
          out.push_back({n, fitting.bounded() ? (fitting.lower() + fitting.upper()) / 2 : fitting.lower()});
      }
      return out;
    }
    const auto& rn = std::get<RepeatN>(op);
    auto count = evaluate(rn.count, id, s, "the count of repeatN");
    if (!count) return std::nullopt;
    random = !count->exact;
    std::vector<double> counts;
    if (auto values = count->support.values(kMaxEnumerated)) {
      for (double v : *values) counts.push_back(std::round(v));
    } else {
      if (!count->support.bounded() || count->support.upper() - count->support.lower() > kMaxTileCounts) {
        cannot_check(id, s, "the count " + expr_text(rn.count) + " allows too many tile counts");
        return std::nullopt;
      }
      for (double v = std::round(count->support.lower()); v <= std::round(count->support.upper()); v += 1)
        if (count->support.contains(v, 0.5)) counts.push_back(v);
    }
    std::sort(counts.begin(), counts.end());
    counts.erase(std::unique(counts.begin(), counts.end()), counts.end());
    for (double n : counts) out.push_back({std::max(n, 0.0), 0});
    return out;
  }

  // Do n equal tiles put every boundary where no box crosses? Fills `tiles`.
  bool tiles_fit(const BoxList& inside, const AxisMap& am, double length, std::uint64_t n,
                 std::vector<BoxList>& tiles) const {
    const double tile = length / static_cast<double>(n);
    tiles.assign(n, {});
    for (std::uint32_t k : inside) {
      double t0 = am.local(boxes_[k].min[am.world]), t1 = am.local(boxes_[k].max[am.world]);
      if (t0 > t1) std::swap(t0, t1);
      if (t0 < -tol_ || t1 > length + tol_) return false;
      std::uint64_t i = tile > 0 ? static_cast<std::uint64_t>(std::max(0.0, std::floor((t0 + tol_) / tile))) : 0;
      i = std::min(i, n - 1);
      // The box must end by the end of its tile: otherwise it crosses a boundary.
      if (i + 1 < n && t1 > tile * static_cast<double>(i + 1) + tol_) return false;
      tiles[i].push_back(k);
    }
    return true;
  }

  struct RepeatSetup {
    Axis axis = Axis::X;
    std::optional<AxisMap> am;
    NodeId child = 0;
    std::vector<TileCount> counts;
    bool random = false;
  };

  std::optional<RepeatSetup> setup_repeat(NodeId id, const Scope& s) {
    const Operation& op = g_.op(id);
    const auto* r = std::get_if<Repeat>(&op);
    const auto* rn = std::get_if<RepeatN>(&op);
    RepeatSetup st;
    const auto a = exact_axis(r ? r->axis : rn->axis, id, s, r ? "the axis of repeat" : "the axis of repeatN");
    if (!a) return std::nullopt;
    st.axis = *a;
    st.am = axis_map(s, *a);
    st.child = r ? r->child : rn->child;
    auto counts = tile_counts(id, s, *a, st.random);
    if (!counts) return std::nullopt;
    st.counts = std::move(*counts);
    return st;
  }

  bool match_repeat(NodeId id, const Scope& s, const BoxList& inside) {
    auto st = setup_repeat(id, s);
    if (!st) return false;
    const double length = s.size[static_cast<int>(st->axis)];
    std::vector<BoxList> tiles;
    std::string tried;
    for (const TileCount& c : st->counts) {
      budget_.step();
      const std::size_t mark = witness_.size();
      if (st->random) {
        WitnessLine w = line(WitnessLine::Kind::Tiles, id);
        w.value = c.n;
        w.size = c.size;
        witness_.push_back(std::move(w));
      }
      if (c.n <= 0) {
        if (inside.empty()) return true;
        witness_.resize(mark);
        continue;
      }
      if (!st->am) return cannot_check(id, s, "the scope is turned by an angle other than a quarter turn");
      const auto n = static_cast<std::uint64_t>(c.n);
      if (tiles_fit(inside, *st->am, length, n, tiles)) {
        const double tile = length / c.n;
        bool ok = true;
        for (std::uint64_t i = 0; i < n && ok; ++i)
          ok = match(st->child, s.slice(st->axis, tile * static_cast<double>(i), tile), tiles[i]);
        if (ok) return true;
      } else if (tried.size() < 200) {
        tried += (tried.empty() ? "" : ", ") + num(c.n);
      }
      witness_.resize(mark);
    }
    if (!recording()) return false;
    if (st->counts.empty()) return fail(id, s, "no tile count fits the tile " + repeat_what(id));
    if (tried.empty())
      return fail(id, s, "the tiles' contents do not match for any tile count of the " + repeat_what(id));
    return fail(id, s, "boxes cross the tile boundaries of " + tried + " tiles (" + repeat_what(id) + ")");
  }

  // ---- choices and calls ----

  struct Options {
    std::vector<bool> applicable;
    bool nil_possible = true;  // every option may fail: the label derives nothing
    bool any = false;
  };

  std::optional<Options> options_of(NodeId id, const Choose& op, const Scope& s) {
    Options o;
    o.applicable.assign(op.options.size(), false);
    for (std::size_t i = 0; i < op.options.size(); ++i) {
      const ChooseOption& opt = op.options[i];
      bool can_hold = true, can_fail = false;
      if (!opt.condition.empty()) {
        auto c = evaluate(opt.condition, id, s, "the condition of alternative", i + 1);
        if (!c) return std::nullopt;
        can_hold = !c->support.empty() && !(c->support.is_point() && c->support.lower() == 0.0);
        can_fail = c->support.contains(0.0);
      }
      bool can_win = true, can_lose = false;
      if (can_hold && !opt.priority.empty()) {
        auto p = evaluate(opt.priority, id, s, "the priority of alternative", i + 1);
        if (!p) return std::nullopt;
        can_win = p->support.upper() > 0;
        can_lose = p->support.lower() <= 0;
      }
      o.applicable[i] = can_hold && can_win;
      o.any = o.any || o.applicable[i];
      o.nil_possible = o.nil_possible && (!o.applicable[i] || can_fail || can_lose);
    }
    return o;
  }

  bool match_choose(NodeId id, const Choose& op, const Scope& s, const BoxList& inside) {
    auto o = options_of(id, op, s);
    if (!o) return false;
    for (std::size_t i = 0; i < op.options.size(); ++i) {
      if (!o->applicable[i]) continue;
      const std::size_t mark = witness_.size();
      if (op.options.size() > 1) {
        WitnessLine w = line(WitnessLine::Kind::Alternative, id);
        w.index = i;
        w.count = op.options.size();
        witness_.push_back(std::move(w));
      }
      slot_ = static_cast<std::uint32_t>(i + 1);
      if (match(op.options[i].child, s, inside)) return true;
      witness_.resize(mark);
    }
    if (o->nil_possible && inside.empty()) {
      witness_.push_back(line(WitnessLine::Kind::NoAlternative, id));
      return true;
    }
    const std::string name = check_detail::choose_name(g_, id, current_rule());
    if (!o->any)
      return recording() &&
             fail(id, s,
                  "no alternative of '" + name + "' applies here (conditions false or priorities <= 0), " +
                      "so it derives nothing, but the example has " + list_boxes(inside));
    return recording() && fail(id, s, "no alternative of '" + name + "' matches");
  }

  // The callee's frame: known values, unknowns for continuous random
  // arguments, and the few-valued random arguments to try one by one.
  std::optional<std::pair<Frame, std::vector<ArgChoice>>> setup_call(NodeId id, const Call& op, const Scope& s) {
    const Rule& callee = g_.rules[op.rule];
    if (vars_.depth() >= kMaxDepth) {
      if (recording())
        fail(id, s, "rule calls nested deeper than " + std::to_string(kMaxDepth) + " (derive() stops there)");
      return std::nullopt;
    }
    Frame frame{op.rule, std::vector<Slot>(op.args.size())};
    std::vector<ArgChoice> choices;
    for (std::size_t k = 0; k < op.args.size(); ++k) {
      const Expr& arg = op.args[k];
      const ExprNode& root = arg.node(arg.root());
      // A parameter or constant passed on keeps its identity: a random
      // value used twice stays one value.
      if (arg.nodes().size() == 1 && (root.kind == ExprKind::Param || root.kind == ExprKind::Constant)) {
        frame.params[k] =
            root.kind == ExprKind::Param ? vars_.param(root.index) : vars_.constant(root.index);
        continue;
      }
      auto p = evaluate(arg, id, s, "argument", k + 1);
      if (!p) return std::nullopt;
      if (p->exact) {
        frame.params[k].value = p->value;
      } else if (auto values = p->support.values(kMaxEnumerated)) {
        if (values->empty()) {
          if (recording())
            fail(id, s,
                 "argument " + std::to_string(k + 1) + " of " + callee.label + " (" + expr_text(arg) +
                     ") has no possible value");
          return std::nullopt;
        }
        choices.push_back({k, *values});
      } else {
        // Continuous: an unknown, pinned down by the first split that uses it.
        frame.params[k].unknown = vars_.add({p->support, std::nullopt, k < callee.params.size() ? callee.params[k] : "?",
                                             Origin{&arg, current_rule(), id}});
      }
    }
    return std::make_pair(std::move(frame), std::move(choices));
  }

  // Runs body() in the callee's frame for each combination of the
  // few-valued arguments; stops at the first body() that returns true.
  template <typename F>
  bool each_binding(NodeId id, const Call& op, Frame& frame, const std::vector<ArgChoice>& choices, std::size_t next,
                    F& body) {
    if (next == choices.size()) {
      vars_.enter(frame);
      const bool ok = body();
      vars_.leave();
      return ok;
    }
    const Rule& callee = g_.rules[op.rule];
    const ArgChoice& c = choices[next];
    for (double v : c.values) {
      budget_.step();
      frame.params[c.arg] = Slot{Value(v), -1};
      const std::size_t mark = witness_.size();
      note_value(id, c.arg < callee.params.size() ? callee.params[c.arg] : "?", v,
                 Origin{&op.args[c.arg], current_rule(), kNone});
      if (each_binding(id, op, frame, choices, next + 1, body)) return true;
      witness_.resize(mark);
    }
    return false;
  }

  bool match_call(NodeId id, const Call& op, const Scope& s, const BoxList& inside) {
    auto setup = setup_call(id, op, s);
    if (!setup) return false;
    const NodeId body_id = g_.rules[op.rule].body;
    auto body = [&] { return match(body_id, s, inside); };
    return each_binding(id, op, setup->first, setup->second, 0, body);
  }

  // ---- faces ----

  bool match_comp(NodeId id, const Comp& op, const Scope& s, const BoxList& inside) {
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

  // ---- length queries: which lengths along an open axis fit ----

  // The lengths l in [fs.lmin, fs.lmax] for which node `id`, run on
  // fs.at(l), derives exactly `inside`. A query: it leaves no witness,
  // binding or mismatch behind. Exact where matching is, except that a
  // continuous unknown in the sizes of a split along the open axis counts
  // as independent values (verified when the length is then matched).
  Support lengths(NodeId id, const FreeScope& fs, const BoxList& inside) {
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

  Support lengths_dispatch(NodeId id, const FreeScope& fs, const BoxList& inside) {
    const Operation& op = g_.op(id);
    const Support all = Support::range(fs.lmin, fs.lmax);
    if (const auto* p = std::get_if<Primitive>(&op)) return lengths_terminal(g_.label(p->label), fs, inside);
    if (std::holds_alternative<Colour>(op)) return lengths_terminal("rect", fs, inside);
    if (std::holds_alternative<Nil>(op)) return inside.empty() ? all : Support{};
    if (const auto* sp = std::get_if<Split>(&op)) return lengths_split(id, *sp, fs, inside);
    const Scope probe = fs.at(fs.lmax);
    if (std::holds_alternative<Repeat>(op) || std::holds_alternative<RepeatN>(op))
      return lengths_repeat(id, fs, inside);
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

  // A terminal fills its scope: the one length (if any) at which the
  // scope's world box is the box's. World bounds move linearly with l.
  Support lengths_terminal(const std::string& label, const FreeScope& fs, const BoxList& inside) {
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

  Support lengths_repeat(NodeId id, const FreeScope& fs, const BoxList& inside) {
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

  // Tiles along the open axis: n tiles of L / n, where L moves with l.
  // With two tiles or more, the first boundary must fall where no box
  // crosses, so each face c of a box gives the candidate L = n * c, checked
  // by matching; one tile is the scope itself.
  Support lengths_repeat_along(NodeId id, const FreeScope& fs, const BoxList& inside, const RepeatSetup& st) {
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

  const Grammar& g_;
  const std::vector<LabelledBox>& boxes_;
  const double tol_;
  Budget& budget_;
  DeterministicSubtrees& deterministic_;
  Bindings vars_;
  // Where the node being matched lies (derivation_path), and the part or
  // option the next match() enters through.
  std::vector<std::uint64_t> path_{0};
  std::uint32_t slot_ = 0;
  std::vector<WitnessLine> witness_;
  std::unordered_map<const Expr*, Possible> fixed_values_;
  CutsCache cuts_;
  BindingLookup lookup_;
  Emptiness empty_;
  Mismatch best_;
  std::string uncheckable_;
  bool open_ends_unsupported_ = false;
  bool floating_ = true;
  int depth_ = 0;
  int quiet_ = 0;
};

// The search for one split: where each part begins and ends.
//
// Parts that hold boxes begin on cuts and end on cuts, or (floating) inside
// the empty stretch after their last box, at a length their child accepts.
// Consecutive parts that hold no box form a run of empty space whose inner
// boundaries are free. A placement is accepted when its lengths fit the
// part sizes (ScaleState: one scale k for the relative parts, or the
// overflow factor c), and then every part's child matches its boxes.
//
// In a length query (free != nullptr) every placement is visited and the
// lengths they allow are collected instead: for a split across the open
// axis, the lengths all children accept; for one along it, the lengths the
// last run of empty space can stretch to.
class SplitSearch {
 public:
  SplitSearch(Matcher& m, NodeId id, const Split& op, const Scope& s, SplitSetup& st, const FreeScope* free)
      : m_(m),
        id_(id),
        op_(op),
        s_(s),
        st_(st),
        cuts_(*st.cuts),
        parts_(st.parts),
        axis_(st.axis),
        length_(st.length),
        tol_(m.tol_),
        free_(free),
        placement_(st.parts.size()) {}

  // Normal: true when a placement matched. Query: false; see collected().
  // With floating false, every part ends on a cut (the first pass: enough
  // for any example whose boundaries all lie on box faces, and far cheaper).
  bool run(Mode mode, bool floating = true) {
    mode_ = mode;
    floating_ = floating;
    return place(0, 0, 0, parts_.size(), initial());
  }

  bool any_sized() const { return any_sized_; }
  const Support& collected() const { return collected_; }

 private:
  static constexpr double kTiny = std::numeric_limits<double>::min();

  ScaleState initial(bool track_set = true) const {
    ScaleState sc;
    sc.track_set = track_set;
    if (mode_ == Mode::Fill) sc.limit(kTiny, kInf);
    if (mode_ == Mode::Overflow) sc.limit(1.0, kInf);
    return sc;
  }

  std::size_t none() const { return parts_.size(); }
  double at(std::size_t cut) const { return cuts_.at[cut]; }

  // ---- the size constraints ----

  // A part that holds boxes, of length len.
  void constrain_filled(const PartInfo& p, double len, ScaleState& sc) const {
    switch (mode_) {
      case Mode::Fill:
        if (!p.relative) return sc.require(distance_to(p.share, len) - tol_);
        if (!sc.track_set || (p.share.intervals.size() == 1 && !p.share.integer))
          return sc.limit((len - tol_) / p.share.upper(), p.share.lower() > 0 ? (len + tol_) / p.share.lower() : kInf);
        return sc.limit(ratio(len, p.share));
      case Mode::Overflow:
        if (p.relative) return sc.require(len);
        if (!sc.track_set || (p.share.intervals.size() == 1 && !p.share.integer))
          return sc.limit(p.share.lower() / (len + tol_), len > tol_ ? p.share.upper() / (len - tol_) : kInf);
        return sc.limit(inverse_ratio(p.share, len));
      case Mode::NoFill:
        if (p.relative) return sc.require(len);
        return sc.require(distance_to(p.share, len) - tol_);
    }
  }

  static Support hull_if_integer(const Support& s) { return s.integer ? Support::range(s.lower(), s.upper()) : s; }

  // k with k * r = len (within the tolerance) for some r of the share.
  Support ratio(double len, const Support& share) const {
    Support out;
    for (const auto& [lo, hi] : hull_if_integer(share).intervals)
      if (hi > 0) out = out.unite(Support::range((len - tol_) / hi, lo > 0 ? (len + tol_) / lo : kInf));
    return out;
  }

  // c with a = c * len for some a of the share.
  Support inverse_ratio(const Support& share, double len) const {
    Support out;
    for (const auto& [lo, hi] : hull_if_integer(share).intervals)
      out = out.unite(Support::range(lo / (len + tol_), len > tol_ ? hi / (len - tol_) : kInf));
    return out;
  }

  // May part p hold no box (a member of a run)? A part that derives
  // something must then have length 0: a zero share (Fill, NoFill) or a
  // relative part under overflow. A lone part between two cuts is checked
  // for real in complete(), so it may try.
  bool may_be_empty(const PartInfo& p, bool starts_run) const {
    if (p.vanishes || starts_run) return true;
    if (mode_ == Mode::Overflow && p.relative) return true;
    return p.share.contains(0.0);
  }

  bool may_hold_boxes(const PartInfo& p) const {
    if (p.nil || p.vanishes) return false;
    return !(p.relative && mode_ != Mode::Fill);
  }

  // What the parts of a run can add up to: al..ah metres plus rl..rh
  // shares of the scale.
  struct RunSums {
    double al = 0, ah = 0, rl = 0, rh = 0;
    bool possible = true;
  };

  RunSums run_sums(std::size_t first, std::size_t last, bool final) const {
    // A lone part between two fixed ends may derive nothing at positive
    // length (matched for real in complete()); in a longer run, or where
    // the end is open, a part that derives something must have length 0.
    const bool lone = last - first == 1 && !(final && (mode_ == Mode::NoFill || free_axis()));
    RunSums r;
    for (std::size_t i = first; i < last; ++i) {
      const PartInfo& p = parts_[i];
      if (p.relative && mode_ == Mode::Overflow) continue;
      Support share = p.share;
      if ((p.relative && mode_ == Mode::NoFill) || (!p.vanishes && !lone)) {
        if (!share.contains(0.0)) r.possible = false;
        share = Support::point(0.0);
      }
      (p.relative ? r.rl : r.al) += share.lower();
      (p.relative ? r.rh : r.ah) += share.upper();
    }
    return r;
  }

  // Parts [first, last) share an empty stretch of length gap.
  void constrain_run(std::size_t first, std::size_t last, double gap, bool final, ScaleState& sc) const {
    const RunSums r = run_sums(first, last, final);
    if (!r.possible) return sc.require(kInf);
    switch (mode_) {
      case Mode::Fill: {
        // gap = k * r + a for some r in [rl, rh], a in [al, ah].
        const double upper = r.rl > 0 ? (gap + tol_ - r.al) / r.rl : kInf;
        const double lower = r.rh > 0 ? (gap - tol_ - r.ah) / r.rh : -kInf;
        if (r.rl <= 0) sc.require(r.al - gap - tol_);
        if (r.rh <= 0) sc.require(gap - tol_ - r.ah);
        return sc.limit(lower, upper);
      }
      case Mode::Overflow:
        // The absolute parts here, shrunk by c, fill the gap.
        return sc.limit(r.al / (gap + tol_), gap > tol_ ? r.ah / (gap - tol_) : kInf);
      case Mode::NoFill:
        sc.require(r.al - gap - tol_);
        if (!final) sc.require(gap - tol_ - r.ah);
        return;
    }
  }

  // The lines bounding a floating part's length as functions of the scale,
  // for one interval of its share and one of its child's lengths. The run
  // after it, parts [first, last), fills the rest up to end.
  void floating_lines(std::size_t f, const RunSums& r, double end, bool final, std::pair<double, double> share,
                      std::pair<double, double> len, std::vector<Line>& lowers, std::vector<Line>& uppers) const {
    const PartInfo& p = parts_[f];
    const bool scaled = mode_ == Mode::Fill;
    const bool rel = p.relative && scaled;
    const double total = end - at(placement_[f].from);
    const double ah = final && mode_ == Mode::NoFill ? kInf : r.ah;
    lowers.clear();
    uppers.clear();
    lowers.push_back(rel ? Line{share.first, 0} : Line{0, share.first});
    if (std::isfinite(share.second)) uppers.push_back(rel ? Line{share.second, 0} : Line{0, share.second});
    lowers.push_back({0, len.first});
    uppers.push_back({0, len.second});
    // The run's length, total - length, lies within [k rl + al, k rh + ah].
    if (std::isfinite(ah) && std::isfinite(r.rh)) lowers.push_back({scaled ? -r.rh : 0, total - ah});
    uppers.push_back({scaled ? -r.rl : 0, total - r.al});
  }

  // A floating part and the run after it: its length l and the scale must
  // satisfy every line at once.
  void constrain_floating(std::size_t f, std::size_t first, std::size_t last, double end, bool final,
                          ScaleState& sc) const {
    const RunSums r = run_sums(first, last, final);
    if (!r.possible) return sc.require(kInf);
    const bool scaled = mode_ == Mode::Fill;
    const double klo = scaled ? std::max(sc.lo, kTiny) : 0, khi = scaled ? sc.hi : 0;
    Support ks;
    double excess = kInf;
    std::vector<Line> lowers, uppers;
    for (const auto& share : hull_if_integer(parts_[f].share).intervals)
      for (const auto& len : placement_[f].lengths.intervals) {
        floating_lines(f, r, end, final, share, len, lowers, uppers);
        const auto [a, b] = feasible_scales(lowers, uppers, klo, khi, tol_);
        if (a <= b)
          ks = ks.unite(Support::range(a, b));
        else
          excess = std::min(excess, least_excess(lowers, uppers, klo, khi));
      }
    if (ks.empty()) return sc.require(std::max(excess, kTiny));
    if (scaled) sc.limit(ks);
  }

  // A length for floating part f at scale k: the middle of what fits.
  std::optional<double> floating_length(std::size_t f, std::size_t first, std::size_t last, double end, bool final,
                                        double k) const {
    const RunSums r = run_sums(first, last, final);
    std::vector<Line> lowers, uppers;
    const double kk = mode_ == Mode::Fill ? k : 0;
    for (const auto& share : hull_if_integer(parts_[f].share).intervals)
      for (const auto& len : placement_[f].lengths.intervals) {
        floating_lines(f, r, end, final, share, len, lowers, uppers);
        double lo = -kInf, hi = kInf;
        for (const Line& l : lowers) lo = std::max(lo, l.slope * kk + l.offset);
        for (const Line& l : uppers) hi = std::min(hi, l.slope * kk + l.offset);
        if (lo <= hi + tol_) return std::clamp((lo + hi) / 2, len.first, len.second);
      }
    return std::nullopt;
  }

  // Closes the run [first, last) that ends at `end`; it began at cut
  // `anchor`, or at the end of floating part `floating`.
  void close_run(std::size_t floating, std::size_t first, std::size_t last, std::size_t anchor, double end, bool final,
                 ScaleState& sc) const {
    if (floating < parts_.size()) return constrain_floating(floating, first, last, end, final, sc);
    if (first < last) return constrain_run(first, last, end - at(anchor), final, sc);
    if (final && mode_ != Mode::NoFill) sc.require(end - at(anchor) - tol_);
  }

  // ---- the search ----

  bool free_axis() const { return free_ && st_.free_axis; }

  // May part i, holding the boxes of cuts [j, e], end in the empty stretch after e?
  bool may_float(std::size_t i, std::size_t e) const {
    const std::size_t last = cuts_.at.size() - 1;
    if (!floating_ || free_ || mode_ == Mode::Overflow || parts_[i].primitive || e >= last) return false;
    if (cuts_.between(e, e + 1) != 0 || cuts_.between(e - 1, e) == 0) return false;
    if (i + 1 == parts_.size() && mode_ != Mode::NoFill) return false;
    return m_.empty_.may_trail(parts_[i].child, static_cast<int>(axis_));
  }

  // The lengths part i's child accepts beyond its last box, up to the next box.
  const Support& floating_lengths(std::size_t i, std::size_t j, std::size_t e) {
    const auto key = std::make_tuple(i, j, e);
    auto hit = floating_memo_.find(key);
    if (hit != floating_memo_.end()) return hit->second;
    const std::size_t last = cuts_.at.size() - 1;
    std::size_t g = e;
    while (g < last && cuts_.between(g, g + 1) == 0) ++g;
    FreeScope fs{[s = s_, a = axis_, from = at(j)](double l) { return s.slice(a, from, l); }, st_.am.world,
                 at(e) - at(j) + tol_, at(g) - at(j)};
    Support result = fs.lmin <= fs.lmax ? m_.lengths(parts_[i].child, fs, cuts_.boxes(j, e)) : Support{};
    return floating_memo_[key] = std::move(result);
  }

  bool close_checked(std::size_t floating, std::size_t first, std::size_t last, std::size_t anchor, double end,
                     bool final, ScaleState& sc) const {
    close_run(floating, first, last, anchor, end, final, sc);
    return sc.ok();
  }

  // A floating part asks its child for the lengths it accepts only once
  // the whole placement fits with any length up to the next box: the query
  // costs far more than the test. Then the placement is tested again.
  bool resolve_floating(ScaleState& sc) {
    bool asked = false;
    for (std::size_t f = 0; f < parts_.size(); ++f) {
      Placement& pl = placement_[f];
      if (!pl.floating || pl.queried) continue;
      pl.lengths = floating_lengths(f, pl.from, pl.to);
      pl.queried = true;
      asked = true;
    }
    if (!asked) return true;
    sc = replay();
    return sc.ok();
  }

  bool place(std::size_t i, std::size_t anchor, std::size_t run_first, std::size_t floating, ScaleState sc) {
    m_.budget_.step();
    const std::size_t n = parts_.size();
    const std::size_t last = cuts_.at.size() - 1;
    if (i == n) {
      if (cuts_.between(anchor, last) != 0) return false;
      if (free_axis()) {
        collect_open_end(anchor, run_first, sc);
        return false;
      }
      if (!close_checked(floating, run_first, n, anchor, length_, true, sc) || !resolve_floating(sc)) return false;
      any_sized_ = true;
      return complete(sc);
    }
    const PartInfo& p = parts_[i];
    if (may_be_empty(p, run_first == i)) {
      placement_[i] = {};
      if (place(i + 1, anchor, run_first, floating, sc)) return true;
    }
    if (!may_hold_boxes(p)) return false;
    // A floating part needs empty parts after it.
    if (floating < n && run_first == i) return false;
    // After empty parts the part may begin anywhere up to the first box.
    std::size_t last_start = anchor;
    if (run_first < i)
      while (last_start < last && cuts_.between(anchor, last_start + 1) == 0) ++last_start;
    for (std::size_t j = anchor; j <= last_start; ++j) {
      ScaleState sj = sc;
      if (!close_checked(floating, run_first, i, anchor, at(j), false, sj)) continue;
      for (std::size_t e = j + 1; e <= last; ++e) {
        const std::size_t count = cuts_.between(j, e);
        if (count == 0) continue;
        if (p.primitive && count > 1) break;
        const double len = at(e) - at(j);
        if (len <= tol_) continue;  // a part of zero length is not derived
        ScaleState se = sj;
        constrain_filled(p, len, se);
        if (se.ok()) {
          placement_[i] = {true, false, j, e, {}, len};
          if (place(i + 1, e, i + 1, none(), se)) return true;
        }
        if (may_float(i, e)) {
          std::size_t g = e;
          while (g < last && cuts_.between(g, g + 1) == 0) ++g;
          placement_[i] = {true, true, j, e, Support::range(at(e) - at(j) + tol_, at(g) - at(j)), 0, false};
          if (place(i + 1, e, i + 1, i, sj)) return true;
        }
      }
    }
    return false;
  }

  // The runs of the current placement, as place() closed them.
  struct Run {
    std::size_t first, last, anchor;
    double end;
    bool final;
    std::size_t floating;  // the floating part before it, or none()
  };

  std::vector<Run> runs() const {
    std::vector<Run> out;
    const std::size_t n = parts_.size();
    std::size_t anchor = 0, floating = n, i = 0;
    while (true) {
      std::size_t j = i;
      while (j < n && !placement_[j].filled) ++j;
      const bool final = j == n;
      const double end = final ? length_ : at(placement_[j].from);
      if (j > i || floating < n || final) out.push_back({i, j, anchor, end, final, floating});
      if (final) return out;
      anchor = placement_[j].to;
      floating = placement_[j].floating ? j : n;
      i = j + 1;
    }
  }

  double run_start(const Run& r) const {
    return r.floating < parts_.size() ? at(placement_[r.floating].from) + placement_[r.floating].length : at(r.anchor);
  }

  // The whole placement's scale state, replayed (for solving).
  ScaleState replay(bool track_set = true) const {
    ScaleState sc = initial(track_set);
    for (std::size_t i = 0; i < parts_.size(); ++i)
      if (placement_[i].filled && !placement_[i].floating)
        constrain_filled(parts_[i], at(placement_[i].to) - at(placement_[i].from), sc);
    for (const Run& r : runs()) close_run(r.floating, r.first, r.last, r.anchor, r.end, r.final, sc);
    return sc;
  }

  // How far the placement is from fitting: 0 when it fits. Misses in
  // metres count in tolerances, so a length that cannot fit at all (a run
  // whose shares fall to 0) never looks better than a scale that almost
  // fits: the scan in solve() must not be drawn to it.
  double violation(const ScaleState& sc) const {
    double v = sc.penalty / tol_;
    if (sc.lo > sc.hi) v += (sc.lo - sc.hi) / std::max({std::abs(sc.hi), std::abs(sc.lo), 1e-300});
    if (v == 0 && !sc.ok()) v = 1e-12;
    return v;
  }

  // Re-evaluates the part sizes (after an unknown was bound or unbound).
  bool refresh_shares() {
    for (std::size_t i = 0; i < parts_.size(); ++i) {
      try {
        parts_[i].share = expression_support(op_.parts[i].size.value, m_.lookup_).clamp(0, kInf);
      } catch (const EvaluationError&) {
        return false;
      } catch (const NotCheckable&) {
        return false;
      }
    }
    return true;
  }

  // Where the unknown enters the sizes of parts holding boxes linearly (a
  // share ~s1 beside ~(10 - s1), a height 0.5 * s1 + 1), their lengths pin
  // it down: the values solving those equations, to try before scanning.
  // Only a shortcut: each is still tried in full.
  std::vector<double> linear_guesses(Unknown& u) {
    std::vector<double> out;
    if (mode_ != Mode::Fill) return out;
    const double lo = u.support.lower(), hi = u.support.upper();
    const double u0 = lo + (hi - lo) / 4, step = (hi - lo) / 4;
    if (!(step > 0)) return out;
    std::vector<std::array<double, 3>> size(parts_.size());
    std::vector<bool> linear(parts_.size(), true);
    for (int k = 0; k < 3; ++k) {
      u.value = u0 + k * step;
      const bool ok = refresh_shares();
      for (std::size_t i = 0; i < parts_.size(); ++i) {
        if (!ok || !parts_[i].share.is_point()) linear[i] = false;
        else size[i][static_cast<std::size_t>(k)] = parts_[i].share.lower();
      }
    }
    u.value.reset();
    refresh_shares();
    struct SizeLine {  // size = a + b * unknown, on a part this long
      double a, b, length;
      bool relative;
    };
    std::vector<SizeLine> lines;
    for (std::size_t i = 0; i < parts_.size(); ++i) {
      const Placement& pl = placement_[i];
      if (!linear[i] || !pl.filled || pl.floating) continue;
      const auto& v = size[i];
      const double b = (v[1] - v[0]) / step;
      if (std::abs((v[2] - v[1]) - (v[1] - v[0])) > 1e-9 * std::max(1.0, std::abs(v[2]))) continue;
      lines.push_back({v[0] - b * u0, b, at(pl.to) - at(pl.from), parts_[i].relative});
    }
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const SizeLine& p = lines[i];
      if (!p.relative) {
        if (p.b != 0) out.push_back((p.length - p.a) / p.b);
        continue;
      }
      // Two relative parts: their lengths in the ratio of their sizes.
      for (std::size_t j = i + 1; j < lines.size(); ++j) {
        const SizeLine& q = lines[j];
        if (!q.relative) continue;
        const double d = p.length * q.b - q.length * p.b;
        if (d != 0) out.push_back((q.length * p.a - p.length * q.a) / d);
      }
    }
    // Every size a point on a line: the relative parts share what the
    // absolute ones leave of the scope, so one part holding boxes is
    // enough (a tower of share s1 under air of share 77 - s1).
    if (std::ranges::all_of(linear, [](bool l) { return l; })) {
      double sum_a = 0, sum_b = 0, fixed = 0;
      bool absolute_move = false;
      for (std::size_t i = 0; i < parts_.size(); ++i) {
        const auto& v = size[i];
        const double b = (v[1] - v[0]) / step;
        if (parts_[i].relative) {
          sum_a += v[0] - b * u0;
          sum_b += b;
        } else {
          fixed += v[0];
          absolute_move = absolute_move || b != 0;
        }
      }
      const double rest = length_ - fixed;
      if (!absolute_move && rest > 0)
        for (const SizeLine& p : lines) {
          if (!p.relative) continue;
          // length * (sum_a + sum_b u) = (a + b u) * rest
          const double d = p.length * sum_b - p.b * rest;
          if (d != 0) out.push_back((p.a * rest - p.length * sum_a) / d);
        }
    }
    std::erase_if(out, [&](double v) { return !(v >= lo && v <= hi); });
    return out;
  }

  // Finds a value of the unknown st_.solve_for that makes this placement
  // fit: a scan of its support, then a golden-section refinement around the
  // best point (the misfit is piecewise linear and V-shaped at a solution).
  std::optional<double> solve() {
    Unknown& u = m_.vars_.unknown(st_.solve_for);
    auto misfit = [&](double v) {
      u.value = v;
      const double r = refresh_shares() ? violation(replay(false)) : kInf;
      u.value.reset();
      return r;
    };
    auto fits = [&](double v) {
      u.value = v;
      const bool ok = refresh_shares() && replay().ok();
      u.value.reset();
      return ok;
    };
    std::optional<double> found;
    if (!u.support.values(256) && u.support.bounded())
      for (double v : linear_guesses(u))
        if (fits(v)) return v;
    if (auto values = u.support.values(256)) {
      for (double v : *values)
        if (fits(v)) {
          found = v;
          break;
        }
    } else if (u.support.bounded()) {
      std::vector<double> xs;
      for (const auto& [lo, hi] : u.support.intervals)
        for (int k = 0; k <= 32; ++k) xs.push_back(lo + (hi - lo) * k / 32.0);
      std::vector<double> fs;
      for (double x : xs) {
        m_.budget_.step();
        fs.push_back(misfit(x));
        if (fs.back() == 0 && fits(x)) {
          found = x;
          break;
        }
      }
      if (found) xs.clear();
      // Refine around the lowest few local minima of the scan: the misfit
      // mixes terms that jump where a share reaches 0, so the lowest
      // sample need not lie in the basin of the solution.
      std::vector<std::size_t> minima;
      for (std::size_t i = 0; i < xs.size(); ++i)
        if ((i == 0 || fs[i] <= fs[i - 1]) && (i + 1 == xs.size() || fs[i] <= fs[i + 1])) minima.push_back(i);
      std::sort(minima.begin(), minima.end(), [&](std::size_t p, std::size_t q) { return fs[p] < fs[q]; });
      if (minima.size() > 6) minima.resize(6);
      for (std::size_t best : minima) {
        double a = std::max(xs[best > 0 ? best - 1 : best], u.support.lower());
        double b = std::min(xs[best + 1 < xs.size() ? best + 1 : best], u.support.upper());
        const double phi = (std::sqrt(5.0) - 1) / 2;
        double c = b - phi * (b - a), d = a + phi * (b - a);
        double fc = misfit(c), fd = misfit(d);
        // Until the bracket is float noise or a point fits (misfit 0).
        for (int k = 0; k < 80 && fc > 0 && fd > 0 && b - a > 1e-15 * std::max(1.0, std::abs(b)); ++k) {
          m_.budget_.step();
          if (fc <= fd) {
            b = d;
            d = c;
            fd = fc;
            c = b - phi * (b - a);
            fc = misfit(c);
          } else {
            a = c;
            c = d;
            fc = fd;
            d = a + phi * (b - a);
            fd = misfit(d);
          }
        }
        for (double v : {fc == 0 ? c : d, xs[best], (a + b) / 2, c, d})
          if (u.support.contains(v, 0) && fits(v)) {
            found = v;
            break;
          }
        if (found) break;
      }
    }
    if (found) {
      auto zero = [&](double v) { return misfit(v) == 0; };
      const double mid = centre(*found, zero);
      if (fits(mid)) found = mid;
    }
    refresh_shares();
    return found;
  }

  // The middle of the stretch of values around v that fit, found by
  // bisection: a value at the edge of what fits would leave no slack for
  // the parts below (which see it through their own tolerance).
  template <typename Fits>
  double centre(double v, Fits& fits) const {
    const Unknown& u = m_.vars_.unknown(st_.solve_for);
    double lo_bound = u.support.lower(), hi_bound = u.support.upper();
    for (const auto& [lo, hi] : u.support.intervals)
      if (v >= lo && v <= hi) lo_bound = lo, hi_bound = hi;
    auto edge = [&](double bound) {
      if (fits(bound)) return bound;
      double in = v, out = bound;
      for (int k = 0; k < 12; ++k) {  // to 2.4e-4 of the stretch: plenty for a middle
        const double mid = (in + out) / 2;
        (fits(mid) ? in : out) = mid;
      }
      return in;
    };
    if (lo_bound == hi_bound) return v;
    return (edge(lo_bound) + edge(hi_bound)) / 2;
  }

  // A scale inside the set that fits: the middle of its first interval.
  double pick_scale(const ScaleState& sc) const {
    const Support set = sc.set();
    if (mode_ == Mode::NoFill || set.empty()) return 1;
    const auto& [lo, hi] = set.intervals.front();
    return std::isfinite(hi) ? (lo + hi) / 2 : std::max(lo, 1.0);
  }

  // A placement fits the sizes: bind what it pins down, match every part.
  bool complete(const ScaleState& sized) {
    if (free_) return collect_across(sized);
    const std::size_t witness_mark = m_.witness_.size(), trail_mark = m_.vars_.trail_size();
    auto give_up = [&] {
      m_.witness_.resize(witness_mark);
      m_.vars_.undo(trail_mark);
      if (st_.solve_for >= 0) refresh_shares();
      return false;
    };
    ScaleState sc = sized;
    if (st_.solve_for >= 0) {
      const auto v = solve();
      if (!v) return false;
      m_.vars_.bind(st_.solve_for, *v);
      refresh_shares();
      sc = replay();
      const Unknown& u = m_.vars_.unknown(st_.solve_for);
      m_.note_value(id_, u.name, *v, u.origin);
    }
    const double k = pick_scale(sc);
    for (const Run& r : runs()) {
      if (r.floating >= parts_.size()) continue;
      const auto l = floating_length(r.floating, r.first, r.last, r.end, r.final, k);
      if (!l) return give_up();
      placement_[r.floating].length = *l;
    }
    add_witness(k);
    if (children_match(true)) return true;
    return give_up();
  }

  // Matches the children of the parts that hold boxes (and of lone empty
  // parts, which must derive nothing there).
  bool children_match(bool lone_runs) {
    for (std::size_t i = 0; i < parts_.size(); ++i) {
      const Placement& pl = placement_[i];
      if (!pl.filled) continue;
      const double from = at(pl.from), len = pl.floating ? pl.length : at(pl.to) - from;
      const auto key = std::make_tuple(i, pl.from, pl.to);
      const bool memo = st_.solve_for < 0 && !pl.floating;
      if (memo) {
        const auto hit = memo_.find(key);
        if (hit != memo_.end()) {
          if (!hit->second.first) return false;
          m_.witness_.insert(m_.witness_.end(), hit->second.second.begin(), hit->second.second.end());
          continue;
        }
      }
      const std::size_t mark = m_.witness_.size(), trail = m_.vars_.trail_size();
      m_.slot_ = static_cast<std::uint32_t>(i + 1);
      const bool ok = m_.match(parts_[i].child, s_.slice(axis_, from, len), cuts_.boxes(pl.from, pl.to));
      // Remember the result unless it pinned down an unknown from outside.
      if (memo && m_.vars_.trail_size() == trail)
        memo_[key] = {
            ok, std::vector<WitnessLine>(m_.witness_.begin() + static_cast<std::ptrdiff_t>(mark), m_.witness_.end())};
      if (!ok) return false;
    }
    if (!lone_runs) return true;
    for (const Run& r : runs()) {
      const double start = run_start(r), gap = r.end - start;
      if (r.last - r.first != 1 || gap <= tol_ || (r.final && mode_ == Mode::NoFill)) continue;
      const PartInfo& p = parts_[r.first];
      if (p.vanishes || (p.relative && mode_ == Mode::Overflow)) continue;
      m_.slot_ = static_cast<std::uint32_t>(r.first + 1);
      if (!m_.match(p.child, s_.slice(axis_, start, gap), {})) return false;
    }
    return true;
  }

  // Query across the open axis: the lengths every child accepts.
  bool collect_across(const ScaleState&) {
    const std::size_t trail_mark = m_.vars_.trail_size();
    if (st_.solve_for >= 0) {
      const auto v = solve();
      if (!v) return false;
      m_.vars_.bind(st_.solve_for, *v);
      refresh_shares();
    }
    auto part_scope = [&](double from, double len) {
      return compose(*free_, [a = axis_, from, len](const Scope& sc) { return sc.slice(a, from, len); });
    };
    Support acc = Support::range(free_->lmin, free_->lmax);
    for (std::size_t i = 0; i < parts_.size() && !acc.empty(); ++i) {
      const Placement& pl = placement_[i];
      if (!pl.filled) continue;
      const auto key = std::make_tuple(i, pl.from, pl.to);
      auto hit = lengths_memo_.find(key);
      if (hit == lengths_memo_.end() || st_.solve_for >= 0)
        hit = lengths_memo_
                  .insert_or_assign(key, m_.lengths(parts_[i].child, part_scope(at(pl.from), at(pl.to) - at(pl.from)),
                                                    cuts_.boxes(pl.from, pl.to)))
                  .first;
      acc = acc.intersect(hit->second);
    }
    for (const Run& r : runs()) {
      if (acc.empty()) break;
      const double start = run_start(r), gap = r.end - start;
      if (r.last - r.first != 1 || gap <= tol_ || (r.final && mode_ == Mode::NoFill)) continue;
      const PartInfo& p = parts_[r.first];
      if (p.vanishes || (p.relative && mode_ == Mode::Overflow)) continue;
      acc = acc.intersect(m_.lengths(p.child, part_scope(start, gap), {}));
    }
    collected_ = collected_.unite(acc);
    m_.vars_.undo(trail_mark);
    if (st_.solve_for >= 0) refresh_shares();
    return false;
  }

  // Query along the open axis: the last run, from cut `anchor` to the
  // scope's open end, can be any length its parts and the scale allow.
  void collect_open_end(std::size_t anchor, std::size_t run_first, const ScaleState& sc) {
    if (!sc.ok()) return;
    const RunSums r = run_sums(run_first, parts_.size(), true);
    if (!r.possible) return;
    Support gaps;
    switch (mode_) {
      case Mode::Fill:
        for (const auto& [ka, kb] : sc.set().intervals)
          gaps = gaps.unite(Support::range(ka * r.rl + r.al - tol_, (r.rh > 0 ? kb * r.rh : 0.0) + r.ah + tol_));
        break;
      case Mode::Overflow:
        for (const auto& [ca, cb] : sc.set().intervals)
          gaps = gaps.unite(Support::range(std::isfinite(cb) ? r.al / cb - tol_ : -tol_, r.ah / ca + tol_));
        break;
      case Mode::NoFill:
        gaps = Support::range(r.al - tol_, kInf);
        break;
    }
    // The scope's length moves linearly with l.
    const double span = free_->lmax - free_->lmin;
    const double slope = span > 0 ? (st_.l1_length - st_.l0_length) / span : 0;
    Support ls;
    for (const auto& [g0, g1] : gaps.intervals) {
      if (std::abs(slope) > 1e-12) {
        ls = ls.unite(Support::range(free_->lmin + (at(anchor) + g0 - st_.l0_length) / slope,
                                     free_->lmin + (at(anchor) + g1 - st_.l0_length) / slope));
      } else if (st_.l0_length - at(anchor) >= g0 && st_.l0_length - at(anchor) <= g1) {
        ls = Support::range(free_->lmin, free_->lmax);
      }
    }
    ls = ls.clamp(free_->lmin, free_->lmax);
    if (ls.empty()) return;
    any_sized_ = true;
    const std::size_t witness_mark = m_.witness_.size(), trail_mark = m_.vars_.trail_size();
    if (children_match(false)) collected_ = collected_.unite(ls);
    m_.witness_.resize(witness_mark);
    m_.vars_.undo(trail_mark);
  }

  // One line per part whose size is random: the value that reproduces it.
  void add_witness(double k) {
    std::vector<double> value(parts_.size(), 0.0), length(parts_.size(), 0.0);
    for (std::size_t i = 0; i < parts_.size(); ++i) {
      const Placement& pl = placement_[i];
      if (!pl.filled) continue;
      const double len = pl.floating ? pl.length : at(pl.to) - at(pl.from);
      length[i] = len;
      value[i] = mode_ == Mode::Fill && parts_[i].relative ? len / k : (mode_ == Mode::Overflow ? len * k : len);
    }
    for (const Run& r : runs()) {
      // Shares interpolated between their bounds so the run's lengths add up.
      double lo = 0, hi = 0;
      for (std::size_t i = r.first; i < r.last; ++i) {
        const PartInfo& p = parts_[i];
        if (p.relative && mode_ != Mode::Fill) continue;
        const double f = p.relative ? k : 1.0;
        lo += f * p.share.lower();
        hi += f * p.share.upper();
      }
      const double gap = r.end - run_start(r);
      const double target = mode_ == Mode::Overflow ? gap * k : gap;
      double t = 0;
      if (std::isfinite(hi) && hi > lo && !(r.final && mode_ == Mode::NoFill))
        t = std::clamp((target - lo) / (hi - lo), 0.0, 1.0);
      for (std::size_t i = r.first; i < r.last; ++i) {
        const Support& sh = parts_[i].share;
        value[i] = std::isfinite(sh.upper()) ? sh.lower() + t * (sh.upper() - sh.lower()) : sh.lower();
        const bool shares = parts_[i].relative && mode_ == Mode::Fill;
        length[i] = mode_ == Mode::Overflow ? (parts_[i].relative ? 0.0 : value[i] / k) : (shares ? value[i] * k : value[i]);
      }
    }
    for (std::size_t i = 0; i < parts_.size(); ++i) {
      if (!parts_[i].random) continue;
      WitnessLine w = m_.line(WitnessLine::Kind::Part, id_);
      w.index = i;
      w.value = value[i];
      w.path = m_.path_.back();
      w.length = length[i];
      m_.witness_.push_back(std::move(w));
    }
  }

  Matcher& m_;
  NodeId id_;
  const Split& op_;
  const Scope& s_;
  SplitSetup& st_;
  const Cuts& cuts_;
  std::vector<PartInfo>& parts_;
  Axis axis_;
  double length_;
  double tol_;
  const FreeScope* free_;
  Mode mode_ = Mode::Fill;
  bool floating_ = true;
  std::vector<Placement> placement_;
  std::map<std::tuple<std::size_t, std::size_t, std::size_t>, std::pair<bool, std::vector<WitnessLine>>> memo_;
  std::map<std::tuple<std::size_t, std::size_t, std::size_t>, Support> lengths_memo_;
  std::map<std::tuple<std::size_t, std::size_t, std::size_t>, Support> floating_memo_;
  bool any_sized_ = false;
  Support collected_;
};

bool Matcher::match_split(NodeId id, const Split& op, const Scope& s, const BoxList& inside) {
  auto st = setup_split(id, op, s, inside, nullptr);
  if (!st) return false;
  bool any_sized = false;
  const bool found = each_sizing(id, op, s, *st, [&] {
    double abs_max = 0;
    bool zero_relative = true, any_absolute = false;
    for (const auto& p : st->parts) {
      if (p.relative) {
        zero_relative = zero_relative && p.share.contains(0.0);
      } else {
        abs_max += p.share.upper();
        any_absolute = true;
      }
    }
    SplitSearch search(*this, id, op, s, *st, nullptr);
    const bool overflow = any_absolute && abs_max >= st->length - tol_;
    // First with every boundary on a cut, then with ends in empty space.
    bool ok = false;
    for (bool floating : {false, true})
      ok = ok || ((!floating || floating_) &&
                  (search.run(Mode::Fill, floating) || (overflow && search.run(Mode::Overflow, floating)) ||
                   (zero_relative && search.run(Mode::NoFill, floating))));
    any_sized = any_sized || search.any_sized();
    return ok;
  });
  if (found) return true;
  if (st->cuts->at.size() < 2 && !inside.empty())
    return recording() &&
           fail(id, s, "the scope has no length along " + expr_text(op.axis) + " but holds " + list_boxes(inside));
  if (!any_sized)
    return recording() && fail(id, s,
                               "no placement of the parts on the cuts of the example's boxes fits sizes " +
                                   sizes_text(op) + " (cuts at " + cuts_text(*st->cuts, st->am) + ")");
  return recording() &&
         fail(id, s, "the parts' contents do not match for any placement that fits sizes " + sizes_text(op));
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

// ---- constants and the entry point ----

struct ConstantChoice {
  std::vector<Slot> slots;
  std::vector<Unknown> unknowns;
  std::vector<std::string> lines;  // "constant N = 9 (randint(8, 10))"
  std::string prefix;              // "with N = 9: " for mismatches
};

class Checker {
 public:
  Checker(const Grammar& g, const std::vector<LabelledBox>& boxes, double tol, Budget& budget, const Scope& start,
          bool text)
      : g_(g), boxes_(boxes), tol_(tol), budget_(budget), deterministic_(g), start_(start), text_(text) {
    for (std::size_t k = 0; k < boxes.size(); ++k) all_.push_back(static_cast<std::uint32_t>(k));
  }

  CheckResult run() {
    // First with every part ending on a box face, then also in empty space.
    for (bool floating : {false, true}) {
      floating_ = floating;
      ConstantChoice choice;
      constants(0, choice);
      if (found_) break;
    }
    CheckResult r;
    r.derivable = found_;
    if (found_) {
      r.witness = witness_;
      r.parts = parts_;
    } else {
      r.mismatch = best_.message.empty() ? "the grammar does not derive the example" : best_.message;
      if (!uncheckable_.empty() && best_.message.find("cannot check") == std::string::npos)
        r.mismatch += "\n  note: some alternatives could not be checked: " + uncheckable_;
      if (open_ends_)
        r.mismatch +=
            "\n  note: some boundaries in empty space were not tried (they would move a repeat's tiles, "
            "a comp's faces or a split's start)";
    }
    return r;
  }

 private:
  // Evaluates constants in file order; few-valued random ones are tried
  // value by value (each a derivation of its own), continuous ones become
  // unknowns pinned down by their first use.
  void constants(std::size_t i, ConstantChoice& c) {
    if (found_) return;
    if (i == g_.constants.size()) return attempt(c);
    const Constant& k = g_.constants[i];
    const BindingLookup lookup = [&](ExprKind kind, std::uint32_t index) -> Binding {
      if (kind != ExprKind::Constant || index >= c.slots.size()) return {false, {}, Support::everything()};
      const Slot& s = c.slots[index];
      if (s.unknown < 0) return {true, s.value, {}};
      return {false, {}, c.unknowns[static_cast<std::size_t>(s.unknown)].support};
    };
    Possible p;
    try {
      p = possible_values(k.value, lookup);
    } catch (const EvaluationError& e) {
      return note({0, "the constant '" + k.name + "' cannot be evaluated (" + e.message + "), so derive() fails"});
    } catch (const NotCheckable& e) {
      uncheckable_ = "the constant '" + k.name + "': " + e.message;
      return note({0, "cannot check: the constant '" + k.name + "': " + e.message});
    }
    if (p.exact) {
      c.slots.push_back({p.value, -1});
      constants(i + 1, c);
      c.slots.pop_back();
      return;
    }
    if (auto values = p.support.values(kMaxEnumerated)) {
      for (double v : *values) {
        budget_.step();
        c.slots.push_back({Value(v), -1});
        c.lines.push_back("constant " + k.name + " = " + num(v) + " (" + write_expression(g_, k.value, {}) + ")");
        const std::string prefix = c.prefix;
        c.prefix += (prefix.empty() ? "with " : ", ") + k.name + " = " + num(v);
        constants(i + 1, c);
        c.prefix = prefix;
        c.lines.pop_back();
        c.slots.pop_back();
        if (found_) return;
      }
      return;
    }
    c.unknowns.push_back({p.support, std::nullopt, k.name, Origin{&k.value, kNone, kNone}});
    c.slots.push_back({Value(), static_cast<int>(c.unknowns.size() - 1)});
    constants(i + 1, c);
    c.slots.pop_back();
    c.unknowns.pop_back();
  }

  void attempt(const ConstantChoice& c) {
    Matcher m(g_, boxes_, tol_, budget_, deterministic_, c.slots, c.unknowns, floating_);
    if (m.run(start_, all_)) {
      found_ = true;
      // The first line says what was matched, so even a grammar without
      // choices has a witness.
      parts_ = m.matched_parts();
      if (!text_) return;
      witness_ = {"start: " + g_.rules[g_.start_rule].label + " on " + bounds_text(start_.origin, start_.size) + ", " +
                  std::to_string(boxes_.size()) + " boxes"};
      witness_.insert(witness_.end(), c.lines.begin(), c.lines.end());
      const std::vector<std::string> lines = m.witness();
      witness_.insert(witness_.end(), lines.begin(), lines.end());
      return;
    }
    Mismatch mm = m.mismatch();
    if (!c.prefix.empty()) mm.message = c.prefix + ": " + mm.message;
    note(mm);
    if (uncheckable_.empty()) uncheckable_ = m.uncheckable();
    open_ends_ = open_ends_ || m.open_ends_unsupported();
  }

  void note(const Mismatch& m) {
    if (m.depth > best_.depth) best_ = m;
  }

  const Grammar& g_;
  const std::vector<LabelledBox>& boxes_;
  double tol_;
  Budget& budget_;
  DeterministicSubtrees deterministic_;
  Scope start_;
  BoxList all_;
  bool found_ = false;
  std::vector<std::string> witness_;
  std::vector<MatchedPart> parts_;
  bool text_ = true;  // spell the witness out
  Mismatch best_;
  std::string uncheckable_;
  bool open_ends_ = false;
  bool floating_ = false;
};

}  // namespace

CheckResult check_example(const Grammar& grammar, const std::vector<LabelledBox>& boxes, glm::dvec3 scope_size,
                          const CheckOptions& options) {
  double tol = options.tolerance;
  if (!(tol > 0)) {
    glm::dvec3 lo(kInf), hi(-kInf);
    for (const auto& b : boxes) {
      lo = glm::min(lo, b.min);
      hi = glm::max(hi, b.max);
    }
    tol = boxes.empty() ? default_tolerance(glm::dvec3(0), scope_size) : default_tolerance(lo, hi);
    if (!(tol > 0)) tol = 1e-9;
  }
  Scope start;
  start.size = scope_size;
  CheckResult r;
  if (grammar.rules.empty()) {
    r.derivable = boxes.empty();
    if (!r.derivable) r.mismatch = "the grammar has no rules, so it derives nothing, but the example has boxes";
    return r;
  }
  Budget budget(options.max_steps);
  return Checker(grammar, boxes, tol, budget, start, options.witness).run();
}

}  // namespace vern
