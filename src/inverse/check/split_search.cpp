// The search for a split's placement (split_search.hpp): part by part,
// each one empty or spanning cuts, narrowing the possible scale as it
// goes; a placement that fits the sizes is completed by matching the
// parts' children.
#include "inverse/check/split_search.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

#include "inverse/check/check_matcher.hpp"

namespace vern::check_detail {

SplitSearch::SplitSearch(Matcher& m, NodeId id, const Split& op, const Scope& s, SplitSetup& st, const FreeScope* free)
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

bool SplitSearch::run(Mode mode, bool floating) {
  mode_ = mode;
  floating_ = floating;
  return place(0, 0, 0, parts_.size(), initial());
}

ScaleState SplitSearch::initial(bool track_set) const {
  ScaleState sc;
  sc.track_set = track_set;
  if (mode_ == Mode::Fill) sc.limit(kTiny, kInf);
  if (mode_ == Mode::Overflow) sc.limit(1.0, kInf);
  return sc;
}

bool SplitSearch::may_float(std::size_t i, std::size_t e) const {
  const std::size_t last = cuts_.at.size() - 1;
  if (!floating_ || free_ || mode_ == Mode::Overflow || parts_[i].primitive || e >= last) return false;
  if (cuts_.between(e, e + 1) != 0 || cuts_.between(e - 1, e) == 0) return false;
  if (i + 1 == parts_.size() && mode_ != Mode::NoFill) return false;
  return m_.empty_.may_trail(parts_[i].child, static_cast<int>(axis_));
}

const Support& SplitSearch::floating_lengths(std::size_t i, std::size_t j, std::size_t e) {
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

bool SplitSearch::close_checked(std::size_t floating, std::size_t first, std::size_t last, std::size_t anchor,
                                double end, bool final, ScaleState& sc) const {
  close_run(floating, first, last, anchor, end, final, sc);
  return sc.ok();
}

bool SplitSearch::resolve_floating(ScaleState& sc) {
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

bool SplitSearch::place(std::size_t i, std::size_t anchor, std::size_t run_first, std::size_t floating, ScaleState sc) {
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

SplitSearch::Runs SplitSearch::runs() const {
  Runs out;
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

double SplitSearch::run_start(const Run& r) const {
  return r.floating < parts_.size() ? at(placement_[r.floating].from) + placement_[r.floating].length : at(r.anchor);
}

ScaleState SplitSearch::replay(bool track_set) const {
  ScaleState sc = initial(track_set);
  for (std::size_t i = 0; i < parts_.size(); ++i)
    if (placement_[i].filled && !placement_[i].floating)
      constrain_filled(parts_[i], at(placement_[i].to) - at(placement_[i].from), sc);
  for (const Run& r : runs()) close_run(r.floating, r.first, r.last, r.anchor, r.end, r.final, sc);
  return sc;
}

double SplitSearch::pick_scale(const ScaleState& sc) const {
  const Support set = sc.set();
  if (mode_ == Mode::NoFill || set.empty()) return 1;
  const auto& [lo, hi] = set.intervals.front();
  return std::isfinite(hi) ? (lo + hi) / 2 : std::max(lo, 1.0);
}

bool SplitSearch::complete(const ScaleState& sized) {
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
    m_.vars_.bind(st_.solve_for, *v);  // the sizes are evaluated at it already
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

bool SplitSearch::children_match(bool lone_runs) {
  Matcher::Finished finished(m_);
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
        finished.add(cuts_.between(pl.from, pl.to));
        continue;
      }
    }
    const std::size_t mark = m_.witness_.size(), trail = m_.vars_.trail_size();
    m_.slot_ = static_cast<std::uint32_t>(i + 1);
    const bool ok = m_.match(parts_[i].child, s_.slice(axis_, from, len), cuts_.boxes(pl.from, pl.to));
    // Remember the result unless it pinned down an unknown from outside.
    if (memo && m_.vars_.trail_size() == trail)
      memo_[key] = {ok, m_.answer_only_ ? std::vector<WitnessLine>{}
                                        : std::vector<WitnessLine>(m_.witness_.begin() + static_cast<std::ptrdiff_t>(mark),
                                                                   m_.witness_.end())};
    if (!ok) return false;
    finished.add(cuts_.between(pl.from, pl.to));
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

void SplitSearch::add_witness(double k) {
  if (m_.answer_only_) return;
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
      length[i] =
          mode_ == Mode::Overflow ? (parts_[i].relative ? 0.0 : value[i] / k) : (shares ? value[i] * k : value[i]);
    }
  }
  // The parts that draw; and where two or more do, the parts written as
  // numbers too: they set the scale the drawn ones are read in
  // (share_splits, which reads only such splits). A split drawing once
  // (the common `~rand : x | ~1 : nil`) records its one part only: this
  // runs for every placement check tries.
  const auto drawing = std::ranges::count_if(parts_, &PartInfo::random);
  if (drawing == 0) return;
  for (std::size_t i = 0; i < parts_.size(); ++i) {
    if (drawing < 2 && !parts_[i].random) continue;
    WitnessLine w = m_.line(WitnessLine::Kind::Part, id_);
    w.spelled = parts_[i].random;
    w.index = i;
    w.value = value[i];
    w.path = m_.path_.back();
    w.length = length[i];
    m_.witness_.push_back(std::move(w));
  }
}

}  // namespace vern::check_detail
