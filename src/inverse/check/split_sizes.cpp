// What a split's part sizes allow of a placement (split_search.hpp): each
// part or run of empty parts narrows the scale (check_scale.hpp), or adds
// to the penalty where a fixed length misses its size.
#include "inverse/check/split_search.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace vern::check_detail {

void SplitSearch::constrain_filled(const PartInfo& p, double len, ScaleState& sc) const {
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

Support SplitSearch::ratio(double len, const Support& share) const {
  Support out;
  for (const auto& [lo, hi] : hull_if_integer(share).intervals)
    if (hi > 0) out = out.unite(Support::range((len - tol_) / hi, lo > 0 ? (len + tol_) / lo : kInf));
  return out;
}

Support SplitSearch::inverse_ratio(const Support& share, double len) const {
  Support out;
  for (const auto& [lo, hi] : hull_if_integer(share).intervals)
    out = out.unite(Support::range(lo / (len + tol_), len > tol_ ? hi / (len - tol_) : kInf));
  return out;
}

bool SplitSearch::may_be_empty(const PartInfo& p, bool starts_run) const {
  if (p.vanishes || starts_run) return true;
  if (mode_ == Mode::Overflow && p.relative) return true;
  return p.share.contains(0.0);
}

bool SplitSearch::may_hold_boxes(const PartInfo& p) const {
  if (p.nil || p.vanishes) return false;
  return !(p.relative && mode_ != Mode::Fill);
}

SplitSearch::RunSums SplitSearch::run_sums(std::size_t first, std::size_t last, bool final) const {
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

void SplitSearch::constrain_run(std::size_t first, std::size_t last, double gap, bool final, ScaleState& sc) const {
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

void SplitSearch::floating_lines(std::size_t f, const RunSums& r, double end, bool final,
                                 std::pair<double, double> share, std::pair<double, double> len,
                                 std::vector<Line>& lowers, std::vector<Line>& uppers) const {
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

void SplitSearch::constrain_floating(std::size_t f, std::size_t first, std::size_t last, double end, bool final,
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

std::optional<double> SplitSearch::floating_length(std::size_t f, std::size_t first, std::size_t last, double end,
                                                   bool final, double k) const {
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

void SplitSearch::close_run(std::size_t floating, std::size_t first, std::size_t last, std::size_t anchor, double end,
                            bool final, ScaleState& sc) const {
  if (floating < parts_.size()) return constrain_floating(floating, first, last, end, final, sc);
  if (first < last) return constrain_run(first, last, end - at(anchor), final, sc);
  if (final && mode_ != Mode::NoFill) sc.require(end - at(anchor) - tol_);
}

}  // namespace vern::check_detail
