// Length queries (check_matcher.hpp, check_free_scope.hpp): for a part
// that ends in empty space, the lengths at which its child derives exactly
// its boxes. Each kind of operation answers for its own scope: terminals
// by their world bounds, splits by their placements (SplitSearch collects
// instead of matching), repeats by their tile counts.
#include "inverse/check/check_matcher.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

namespace vern::check_detail {

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
  Tiling tiles;
  Support acc;
  for (const TileCount& c : st->counts) {
    budget_.step();
    if (c.n <= 0) {
      if (inside.empty()) acc = Support::range(fs.lmin, fs.lmax);
      continue;
    }
    const std::uint64_t n = tiles_within_limit(id, c.n);
    if (!tiles_fit(inside, *st->am, length, n, tiles)) continue;
    const double tile = length / c.n;
    Support here = Support::range(fs.lmin, fs.lmax);
    for (std::uint64_t i = 0; i < n && !here.empty(); ++i) {
      const Axis a = st->axis;
      const double from = tile * static_cast<double>(i);
      here = here.intersect(lengths(
          st->child, compose(fs, [a, from, tile](const Scope& sc) { return sc.slice(a, from, tile); }), tiles.take(i)));
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
  Tiling tiles;
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
        ok = match(st.child, sc.slice(st.axis, tile * static_cast<double>(i), tile), tiles.take(i));
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

bool SplitSearch::collect_across(const ScaleState&) {
  const std::size_t trail_mark = m_.vars_.trail_size();
  if (st_.solve_for >= 0) {
    const auto v = solve();
    if (!v) return false;
    m_.vars_.bind(st_.solve_for, *v);  // the sizes are evaluated at it already
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

void SplitSearch::collect_open_end(std::size_t anchor, std::size_t run_first, const ScaleState& sc) {
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

}  // namespace vern::check_detail
