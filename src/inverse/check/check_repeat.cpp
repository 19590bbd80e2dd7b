// Matching repeat and repeatN (check_matcher.hpp): the tile counts their
// size or count allows, tried in order; a count fits when no box crosses a
// tile boundary and every tile's child matches its boxes.
#include "inverse/check/check_matcher.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "base/number_format.hpp"

namespace vern::check_detail {

namespace {

constexpr const char* kTileSizeHint = "give a tile length in metres, or use repeatN(axis, count) for a number of tiles";

// Counts from `first` to `last`, one by one: by index, so that counts
// beyond 2^53, where adding 1 to a double changes nothing, still end.
std::vector<double> counts_between(double first, double last) {
  std::vector<double> out;
  if (!(first <= last)) return out;
  const auto steps = static_cast<std::uint64_t>(last - first);
  for (std::uint64_t k = 0; k <= steps; ++k) out.push_back(first + static_cast<double>(k));
  return out;
}

}  // namespace

void Tiling::sort() {
  std::stable_sort(boxes_.begin(), boxes_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  next_ = 0;
}

const BoxList& Tiling::take(std::uint64_t i) {
  taken_.clear();
  for (; next_ < boxes_.size() && boxes_[next_].first == i; ++next_) taken_.push_back(boxes_[next_].second);
  return taken_;
}

std::string Matcher::repeat_what(NodeId id) const {
  const Operation& op = g_.op(id);
  if (const auto* r = std::get_if<Repeat>(&op)) return "size " + expr_text(r->size);
  return "count " + expr_text(std::get<RepeatN>(op).count);
}

std::optional<std::vector<TileCount>> Matcher::tile_counts(NodeId id, const Scope& s, Axis a, bool& random) {
  const Operation& op = g_.op(id);
  const double length = s.size[static_cast<int>(a)];
  std::vector<TileCount> out;
  if (const auto* r = std::get_if<Repeat>(&op)) {
    auto size = evaluate(r->size, id, s, "the tile size");
    if (!size) return std::nullopt;
    random = !size->exact;
    auto count_for = [&](double tile) { return repeat_tile_count(length, tile); };
    // Where derive() fails whatever it draws, generate stops with an input
    // error at the tile size; so does check.
    if (size->exact && size->value.is_number()) {
      const double tile = size->value.number();
      if (!(tile > 0))
        refuse(ErrorKind::Input, r->size.loc(),
               "the tile size of repeat is " + format_number(tile) + "; it must be > 0", kTileSizeHint);
      return std::vector<TileCount>{{count_for(tile), tile}};
    }
    const Support sizes = size->support.clamp(std::numeric_limits<double>::min(), kInf);
    if (sizes.empty()) {
      if (!size->exact)
        refuse(ErrorKind::Input, r->size.loc(), "the tile size of repeat, " + expr_text(r->size) + ", is never > 0",
               kTileSizeHint);
      if (recording()) fail(id, s, "the tile size " + expr_text(r->size) + " is never > 0, so derive() fails here");
      return std::nullopt;
    }
    const double n_min = count_for(sizes.upper()), n_max = count_for(sizes.lower());
    // Every count past the limit: refused, whatever the draw.
    tiles_within_limit(id, n_min);
    if (!std::isfinite(n_max) || n_max - n_min > kMaxTileCounts) {
      cannot_check(id, s, "the tile size " + expr_text(r->size) + " allows too many tile counts");
      return std::nullopt;
    }
    for (double n : counts_between(n_min, n_max)) {
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
    if (count->support.bounded()) tiles_within_limit(id, std::round(count->support.lower()));
    if (!count->support.bounded() || count->support.upper() - count->support.lower() > kMaxTileCounts) {
      cannot_check(id, s, "the count " + expr_text(rn.count) + " allows too many tile counts");
      return std::nullopt;
    }
    for (double v : counts_between(std::round(count->support.lower()), std::round(count->support.upper())))
      if (count->support.contains(v, 0.5)) counts.push_back(v);
  }
  std::sort(counts.begin(), counts.end());
  counts.erase(std::unique(counts.begin(), counts.end()), counts.end());
  for (double n : counts) out.push_back({std::max(n, 0.0), 0});
  return out;
}

std::uint64_t Matcher::tiles_within_limit(NodeId id, double n) const {
  const std::uint64_t limit = budget_.limit();
  if (n <= static_cast<double>(limit) && n < 0x1p64) return static_cast<std::uint64_t>(n);
  const std::string beyond =
      " tiles, more than check's limit of " + std::to_string(limit) + " matching steps (one per tile)";
  if (const auto* rn = std::get_if<RepeatN>(&g_.op(id)))
    refuse(ErrorKind::Limit, rn->count.loc(), "repeatN asks for " + format_number(n) + beyond,
           "raise the limit with --max-steps (CheckOptions::max_steps), or ask for fewer tiles");
  refuse(ErrorKind::Limit, g_.node(id).loc, "repeat would make " + format_number(n) + beyond,
         "raise the limit with --max-steps (CheckOptions::max_steps), or use a larger tile size");
}

bool Matcher::tiles_fit(const BoxList& inside, const AxisMap& am, double length, std::uint64_t n, Tiling& tiles) const {
  const double tile = length / static_cast<double>(n);
  tiles.clear();
  for (std::uint32_t k : inside) {
    double t0 = am.local(boxes_[k].min[am.world]), t1 = am.local(boxes_[k].max[am.world]);
    if (t0 > t1) std::swap(t0, t1);
    if (t0 < -tol_ || t1 > length + tol_) return false;
    std::uint64_t i = tile > 0 ? static_cast<std::uint64_t>(std::max(0.0, std::floor((t0 + tol_) / tile))) : 0;
    i = std::min(i, n - 1);
    // The box must end by the end of its tile: otherwise it crosses a boundary.
    if (i + 1 < n && t1 > tile * static_cast<double>(i + 1) + tol_) return false;
    tiles.add(i, k);
  }
  tiles.sort();
  return true;
}

std::optional<Matcher::RepeatSetup> Matcher::setup_repeat(NodeId id, const Scope& s) {
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

bool Matcher::match_repeat(NodeId id, const Scope& s, const BoxList& inside) {
  auto st = setup_repeat(id, s);
  if (!st) return false;
  const double length = s.size[static_cast<int>(st->axis)];
  Tiling tiles;
  std::string tried;
  for (const TileCount& c : st->counts) {
    budget_.step();
    const std::size_t mark = witness_.size();
    {
      // Spelled out where a draw chose the count; kept as data always, so
      // a repeat's tiles can be told apart in CheckResult::steps.
      WitnessLine w = line(WitnessLine::Kind::Tiles, id);
      w.value = c.n;
      w.size = c.size;
      w.spelled = st->random;
      w.length = c.n > 0 ? length / c.n : 0.0;
      w.path = path_.back();
      witness_.push_back(std::move(w));
    }
    if (c.n <= 0) {
      if (inside.empty()) return true;
      witness_.resize(mark);
      continue;
    }
    const std::uint64_t n = tiles_within_limit(id, c.n);
    if (!st->am) return cannot_check(id, s, "the scope is turned by an angle other than a quarter turn");
    if (tiles_fit(inside, *st->am, length, n, tiles)) {
      const double tile = length / c.n;
      bool ok = true;
      Finished finished(*this);
      for (std::uint64_t i = 0; i < n && ok; ++i) {
        const BoxList& boxes = tiles.take(i);
        const std::size_t count = boxes.size();
        ok = match(st->child, s.slice(st->axis, tile * static_cast<double>(i), tile), boxes);
        finished.add(count);
      }
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

}  // namespace vern::check_detail
