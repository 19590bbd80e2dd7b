// Matching a split (check_matcher.hpp): its axis, the cuts of the boxes
// along it and the sizes of its parts; the placements are searched by
// SplitSearch (split_search.hpp), once for every sizing of few-valued
// random values, in three modes (docs/grammar.md, split).
#include "inverse/check/check_matcher.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace vern::check_detail {

std::string Matcher::sizes_text(const Split& op) const {
  std::string t;
  for (std::size_t i = 0; i < op.parts.size(); ++i) {
    t += (i ? " : " : "");
    t += (op.parts[i].size.relative ? "~" : "") + expr_text(op.parts[i].size.value);
  }
  return t;
}

std::optional<SplitSetup> Matcher::setup_split(NodeId id, const Split& op, const Scope& s, const BoxList& inside,
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

}  // namespace vern::check_detail
