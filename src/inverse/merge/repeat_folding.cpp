#include "inverse/merge/repeat_folding.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>
#include <vector>

#include "base/hashing.hpp"
#include "graph/structural.hpp"
#include "inverse/sizes/tidy_numbers.hpp"

namespace vern {

namespace {

class Folder {
 public:
  Folder(Grammar& g, double tolerance, UnlikeTiles unlike, TileCounts* counts, const std::vector<bool>* kept,
         RowsSeen& rows_seen)
      : g_(g), tol_(tolerance), unlike_(unlike), counts_(counts), kept_(kept), rows_seen_(rows_seen) {}

  NodeId run(NodeId id) {
    if (id < memo_.size() && memo_[id] != kNotYet) return memo_[id];
    if (kept_ != nullptr && id < kept_->size() && (*kept_)[id]) return id;
    // Children first, by id: running them may intern nodes and move the
    // arena, so the operation is copied only when it must be rebuilt.
    const auto [done, changed] = map_children(g_.op(id), [&](NodeId c) { return run(c); });
    NodeId out = id;
    if (std::holds_alternative<Split>(g_.op(id))) {
      Split s = std::get<Split>(g_.op(id));  // a copy: folding interns, which may move the arena
      for (std::size_t i = 0; i < s.parts.size(); ++i) s.parts[i].child = done[i];
      out = fold_split(std::move(s), changed);
      if (out == kNotYet) out = id;
    } else if (changed) {
      Operation copy = g_.op(id);
      const std::vector<NodeId*> slots = child_slots(copy);
      for (std::size_t i = 0; i < slots.size(); ++i) *slots[i] = done[i];
      out = g_.intern({std::move(copy), {}});
    }
    // Grown by half again, not by the few nodes folding added since.
    if (memo_.size() <= id) memo_.resize(std::max<std::size_t>(g_.node_count() + g_.node_count() / 2, id + 1), kNotYet);
    memo_[id] = out;
    return out;
  }

 private:
  struct Run {
    std::size_t start = 0, period = 0, copies = 0;
    std::size_t parts() const { return period * copies; }
  };

  bool same(const SplitPart& a, const SplitPart& b) const {
    const auto x = a.size.value.literal(), y = b.size.value.literal();
    return a.size.relative == b.size.relative && x && y && std::abs(*x - *y) <= tol_ &&
           same_node(a.child, b.child);
  }

  // Inference interns its graphs, so equal children are one node; a
  // grammar read from text is compared structurally.
  bool same_node(NodeId a, NodeId b) const { return a == b || structurally_equal(g_, a, g_, b); }

  // How many times parts[start, start + period) repeats from start on.
  std::size_t copies(const std::vector<SplitPart>& parts, std::size_t start, std::size_t period) const {
    std::size_t k = 1;
    while (start + (k + 1) * period <= parts.size()) {
      bool equal = true;
      for (std::size_t j = 0; j < period && equal; ++j) equal = same(parts[start + j], parts[start + k * period + j]);
      if (!equal) break;
      ++k;
    }
    return k;
  }

  std::optional<Run> best_run(const std::vector<SplitPart>& parts) const {
    std::optional<Run> best;
    for (std::size_t start = 0; start < parts.size(); ++start) {
      for (std::size_t period = 1; period <= kMaxPeriod && start + 2 * period <= parts.size(); ++period) {
        const std::size_t k = copies(parts, start, period);
        if (k < 2) continue;
        const Run r{start, period, k};
        if (!best || r.parts() > best->parts() || (r.parts() == best->parts() && r.period < best->period)) best = r;
      }
    }
    return best;
  }

  bool is_nil(NodeId id) const { return std::holds_alternative<Nil>(g_.op(id)); }

  // The run as one part: repeat(axis, tile){ pattern }, or nullopt when
  // equal tiles would move some original cut by more than the tolerance.
  std::optional<SplitPart> fold(const Expr& axis, const std::vector<SplitPart>& parts, const Run& r) {
    double total = 0;
    std::vector<double> cuts;  // the run's original cut positions
    for (std::size_t i = r.start; i < r.start + r.parts(); ++i) {
      total += *parts[i].size.value.literal();
      cuts.push_back(total);
    }
    const double tile = total / static_cast<double>(r.copies);
    double pattern = 0;
    std::vector<double> inner;
    for (std::size_t j = 0; j < r.period; ++j) inner.push_back(pattern += *parts[r.start + j].size.value.literal());
    for (std::size_t i = 0; i < cuts.size(); ++i) {
      const std::size_t copy = i / r.period, j = i % r.period;
      const double at = static_cast<double>(copy) * tile + inner[j] * (tile / pattern);
      if (std::abs(at - cuts[i]) > tol_) return std::nullopt;
    }
    NodeId body = parts[r.start].child;
    if (r.period > 1) body = group(axis, parts, r.start, r.start + r.period);
    return repeat_part(axis, total, r.copies, body, parts[r.start].size.relative);
  }

  // A row of compound tiles (a pattern of two parts or more, seen twice
  // in a row somewhere) among other parts: the pattern's occurrences (the
  // same parts, of any sizes) cover at least half the row, and the rest
  // lies in stretches between them. Each run of equal occurrences (one
  // copy too: another example may show two) becomes a repeat of the
  // pattern, and each stretch of two parts or more one group, a split of
  // its own (the entrance bay between the shop bays; merging's simplifier
  // may write it in place again). So rows with the entrance after one, two or no bays are one
  // structure but for where the runs are, and each bay one node, not a
  // long split per example (issue 15, "compound tiles"). False, leaving
  // parts as they were, when there is no such row or a repeat would move
  // a cut by more than the tolerance. r is best_run(parts), which the
  // caller has already found.
  bool segment_row(const Expr& axis, std::vector<SplitPart>& parts, std::optional<Run> r) {
    // Tiles whose sizes inside differ from tile to tile (a window width
    // drawn for each bay) repeat no run exactly: where unlike tiles may
    // fold, the pattern is found among occurrences alike but for sizes.
    const bool alike_tiles = unlike_ == UnlikeTiles::Fold;
    const bool exact = r && r->period >= 2;
    if (!exact && alike_tiles)
      if (auto alike = alike_run(parts)) r = alike;
    // Else a run of one equal part (bare wall bays either side of a door)
    // is the pattern, where every copy of it in the row is one length (not
    // piers of bays whose windows differ, two by two between them) and no
    // part as long as it stands beside a run: that row is tiles of unlike
    // kinds, left to merging.
    const bool single = r && r->period == 1;
    if (!r) return false;
    // The row cut into runs of occurrences and stretches between them,
    // for the pattern as run r reads it.
    struct Segment {
      std::size_t from, to, copies;  // copies: 0 for a stretch of other parts
    };
    struct Row {
      std::vector<Segment> segments;
      std::size_t covered = 0;  // parts in occurrences
    };
    auto segment = [&](const Run& run) {
      // An occurrence has the pattern's children and kinds of size; its
      // sizes may differ (a bay 4 m wide before the entrance, 3.4 m
      // after). A run is a sequence of occurrences equal to each other.
      auto occurs_at = [&](std::size_t i) { return alike(parts, run.start, i, run.period); };
      auto equal_copies = [&](std::size_t i, std::size_t k) {
        for (std::size_t j = 0; j < run.period; ++j)
          if (!same(parts[i + j], parts[k + j])) return false;
        return true;
      };
      // Occurrences of one length are one run where unlike tiles may
      // fold: a repeat of a choice of the occurrences, which merging
      // unites.
      auto one_run = [&](std::size_t i, std::size_t k) {
        return equal_copies(i, k) ||
               (alike_tiles && std::abs(length_of(parts, i, run.period) - length_of(parts, k, run.period)) <= tol_);
      };
      Row row;
      auto& segments = row.segments;
      for (std::size_t i = 0; i < parts.size();) {
        if (occurs_at(i)) {
          if (!segments.empty() && segments.back().copies > 0 && segments.back().to == i &&
              one_run(segments.back().from, i)) {
            segments.back().to += run.period;
            ++segments.back().copies;
          } else {
            segments.push_back({i, i + run.period, 1});
          }
          row.covered += run.period;
          i += run.period;
        } else {
          if (!segments.empty() && segments.back().copies == 0) ++segments.back().to;
          else segments.push_back({i, i + 1, 0});
          ++i;
        }
      }
      return row;
    };
    // The pattern in the tiles' own phase: a bay whose piers share a
    // label with the entrance's walls (pier, panes, pier) is also read a
    // part later (pier, pier, panes), and that phase may repeat as often.
    // Of the pattern's phases, the one whose occurrences cover the most
    // of the row, in the fewest segments.
    Row row = segment(*r);
    for (std::size_t shift = 1; shift < r->period; ++shift) {
      const Run turned{r->start + shift, r->period, 0};
      if (!alike(parts, turned.start, turned.start + turned.period, turned.period)) continue;
      Row other = segment(turned);
      if (other.covered > row.covered || (other.covered == row.covered && other.segments.size() < row.segments.size()))
        row = std::move(other);
    }
    const std::vector<Segment>& segments = row.segments;
    const std::size_t covered = row.covered;
    if (2 * covered < parts.size() || segments.size() < 2) return false;
    if (single)
      for (std::size_t k = 0; k < segments.size(); ++k) {
        if (segments[k].copies == 0) continue;
        const double tile = length_of(parts, segments[k].from, 1);
        if (std::abs(tile - length_of(parts, r->start, 1)) > tol_ ||
            part_as_long_beside(parts, segments[k].from, segments[k].to, tile))
          return false;
      }
    // Found among alike occurrences: only where some run repeats.
    if (!exact && std::none_of(segments.begin(), segments.end(), [](const Segment& seg) { return seg.copies > 1; }))
      return false;
    std::vector<SplitPart> out;
    for (const Segment& seg : segments) {
      if (seg.copies > 0) {
        auto folded = fold(axis, parts, Run{seg.from, r->period, seg.copies});
        if (!folded && alike_tiles) folded = fold_alike(axis, parts, Run{seg.from, r->period, seg.copies});
        if (!folded) return false;
        out.push_back(*folded);
      } else if (seg.to - seg.from == 1) {
        out.push_back(parts[seg.from]);
      } else {
        double length = 0;
        bool relative = true;
        for (std::size_t j = seg.from; j < seg.to; ++j) {
          length += *parts[j].size.value.literal();
          relative = relative && parts[j].size.relative;
        }
        if (!relative) return false;
        SplitPart grouped;
        grouped.child = group(axis, parts, seg.from, seg.to);
        grouped.size = Size{Expr::number(length), true};
        out.push_back(std::move(grouped));
      }
    }
    parts = std::move(out);
    return true;
  }

  // A row of tiles of a few kinds, each tile drawn from them, with an odd
  // tile among them (bays each a balcony or a window bay, the entrance or
  // a bay of paired windows at some place): no pattern recurs part for
  // part, but the row is runs of pieces of one length. Read left to
  // right, each run is a piece (not a bare primitive) that the next piece
  // repeats in length, for as long as pieces of that length follow (of
  // several, the longest run, then the one of fewest kinds; but a run
  // whose pieces are each pieces of a run of shorter tiles gives way to
  // that one: two bays are no tile where one bay is). A piece
  // whose kind (its shape, sizes aside: tile_shape) is the only one of its
  // kind in the row, and no other row showed trading places
  // (RowsSeen::shapes_seen), is the odd tile: it stands alone,
  // between runs. Each run becomes a repeat of a choice of its pieces
  // (merging unites them), each stretch between runs a part or one
  // group. Only where the runs hold tiles of two kinds or more, or of a
  // kind seen trading in other rows (a row of one kind is segment_row's),
  // and cover half the row.
  bool segment_kinds(const Expr& axis, std::vector<SplitPart>& parts) {
    const std::size_t n = parts.size();
    if (n < 4) return false;
    std::vector<double> at{0};
    for (const SplitPart& p : parts) at.push_back(at.back() + *p.size.value.literal());
    // The end of the piece of `length` starting at `from`, if a cut is there.
    auto piece_end = [&](std::size_t from, double length) -> std::optional<std::size_t> {
      for (std::size_t j = from + 1; j <= n && j - from <= kMaxPartsPerTile; ++j) {
        const double l = at[j] - at[from];
        if (std::abs(l - length) <= tol_) return j;
        if (l > length + tol_) break;
      }
      return std::nullopt;
    };
    auto bare = [&](std::size_t from, std::size_t to) { return to - from == 1 && is_primitive(parts[from].child); };
    struct PieceRun {
      std::vector<std::size_t> starts;  // each piece's first part, then the run's end
    };
    // Of the runs starting at a part, the one reaching furthest, then of
    // the fewest kinds: a row of bays wall | window | wall in equal
    // thirds is also pieces of two thirds (wall window, wall wall, window
    // wall), of three kinds where the bays are of one.
    auto kinds_in = [&](const PieceRun& run) {
      std::set<std::size_t> seen;
      for (std::size_t k = 0; k + 1 < run.starts.size(); ++k)
        seen.insert(group_shape(axis, parts, run.starts[k], run.starts[k + 1]));
      return seen.size();
    };
    std::vector<PieceRun> runs;
    for (std::size_t i = 0; i < n;) {
      std::optional<PieceRun> run;
      std::size_t run_kinds = 0;
      for (std::size_t j = i + 1; j < n && j - i <= kMaxPartsPerTile; ++j) {
        if (bare(i, j)) continue;
        const double length = at[j] - at[i];
        const auto next = piece_end(j, length);
        if (!next || bare(j, *next)) continue;
        PieceRun here{{i, j, *next}};
        for (auto more = piece_end(*next, length); more && !bare(here.starts.back(), *more);
             more = piece_end(here.starts.back(), length))
          here.starts.push_back(*more);
        const std::size_t here_kinds = kinds_in(here);
        // A run whose pieces are each pieces of a run of shorter tiles (two
        // bays taken as one) gives way to it, however far it reaches.
        auto coarser_of = [](const PieceRun& coarse, const PieceRun& fine) {
          if (coarse.starts[1] <= fine.starts[1]) return false;
          for (const std::size_t cut : coarse.starts) {
            if (cut > fine.starts.back()) break;
            if (!std::binary_search(fine.starts.begin(), fine.starts.end(), cut)) return false;
          }
          return true;
        };
        const bool finer = run && coarser_of(*run, here);
        const bool coarser = run && coarser_of(here, *run);
        if (!run || finer || (!coarser && (here.starts.back() > run->starts.back() ||
            (here.starts.back() == run->starts.back() && here_kinds < run_kinds)))) {
          run = std::move(here);
          run_kinds = here_kinds;
        }
      }
      if (!run) {
        ++i;
        continue;
      }
      i = run->starts.back();
      runs.push_back(std::move(*run));
    }
    if (runs.empty()) return false;
    // The kinds of the row's pieces; a kind seen once is the odd tile
    // unless other rows showed it trading places.
    std::map<std::size_t, std::size_t> kinds;  // shape -> pieces
    std::vector<std::vector<std::size_t>> shapes(runs.size());
    for (std::size_t r = 0; r < runs.size(); ++r)
      for (std::size_t k = 0; k + 1 < runs[r].starts.size(); ++k) {
        shapes[r].push_back(group_shape(axis, parts, runs[r].starts[k], runs[r].starts[k + 1]));
        ++kinds[shapes[r].back()];
      }
    auto trades = [&](std::size_t shape) { return kinds[shape] >= 2 || rows_seen_.shapes_seen.count(shape) > 0; };
    // Runs cut around odd tiles; segments in order: runs of pieces, and
    // stretches of parts between.
    struct Segment {
      std::size_t from, to;
      std::vector<std::size_t> starts;  // empty: a stretch
    };
    std::vector<Segment> segments;
    auto stretch = [&](std::size_t from, std::size_t to) {
      if (from == to) return;
      if (!segments.empty() && segments.back().starts.empty() && segments.back().to == from) segments.back().to = to;
      else segments.push_back({from, to, {}});
    };
    std::size_t covered = 0;
    std::size_t done = 0;  // parts placed in segments so far
    for (std::size_t r = 0; r < runs.size(); ++r) {
      stretch(done, runs[r].starts.front());
      std::vector<std::size_t> current;
      auto close = [&] {
        if (current.size() >= 2) {
          segments.push_back({current.front(), current.back(), current});
          covered += current.back() - current.front();
        }
        current.clear();
      };
      for (std::size_t k = 0; k + 1 < runs[r].starts.size(); ++k) {
        const std::size_t from = runs[r].starts[k], to = runs[r].starts[k + 1];
        if (!trades(shapes[r][k])) {
          rows_seen_.shapes_lone.insert(shapes[r][k]);  // another row may show it trading
          close();
          stretch(from, to);
          continue;
        }
        if (current.empty()) current.push_back(from);
        current.push_back(to);
      }
      close();
      done = runs[r].starts.back();
    }
    stretch(done, n);
    // Tiles of two kinds or more in the runs, or of a kind other rows
    // showed trading places: runs of balcony bays and of window bays
    // around the odd bay are runs of the one choice.
    std::set<std::size_t> in_runs;
    std::map<std::size_t, std::pair<double, double>> run_lengths;  // shape -> the lengths of its pieces in runs
    for (const Segment& seg : segments)
      for (std::size_t k = 0; k + 1 < seg.starts.size(); ++k) {
        const std::size_t shape = group_shape(axis, parts, seg.starts[k], seg.starts[k + 1]);
        in_runs.insert(shape);
        const double length = at[seg.starts[k + 1]] - at[seg.starts[k]];
        const auto [it, added] = run_lengths.try_emplace(shape, length, length);
        it->second = {std::min(it->second.first, length), std::max(it->second.second, length)};
      }
    const bool mixed = in_runs.size() >= 2 || std::any_of(in_runs.begin(), in_runs.end(), [&](std::size_t k) {
                         return rows_seen_.shapes_seen.count(k) > 0;
                       });
    // A stretch that starts (or ends) with tiles of the runs' kinds holds
    // runs of them, one tile long too, beside the odd tile: the bay before
    // a door as wide as the bays (the bays after it a little wider), as
    // two bays before it would be a run; rows with the door after none,
    // one or two bays are then one structure but for how long the run is.
    // The rest of the stretch stays one piece: a stretch of tiles of kinds
    // seen once here stays as it was.
    auto tile_of_runs = [&](std::size_t p, std::size_t q) {
      if (bare(p, q)) return false;
      const auto known = run_lengths.find(group_shape(axis, parts, p, q));
      // About as long as the runs' tiles of its kind (the rest of a row
      // shared out differs by a little, not by a quarter).
      return known != run_lengths.end() && at[q] - at[p] <= kTileGap * known->second.second &&
             kTileGap * (at[q] - at[p]) >= known->second.first;
    };
    // The cuts of tiles of the runs' kinds from `from` on (forward) or
    // back from `to`, each the shortest such piece, within [from, to],
    // ascending.
    auto tiles = [&](std::size_t from, std::size_t to, bool forward) {
      std::vector<std::size_t> cuts{forward ? from : to};
      for (bool found = true; found;) {
        found = false;
        const std::size_t at_cut = cuts.back();
        for (std::size_t step = 1; step <= kMaxPartsPerTile && !found; ++step) {
          if (forward ? at_cut + step > to : at_cut < from + step) break;
          const std::size_t p = forward ? at_cut : at_cut - step, q = forward ? at_cut + step : at_cut;
          if (tile_of_runs(p, q)) {
            cuts.push_back(forward ? q : p);
            found = true;
          }
        }
      }
      if (!forward) std::reverse(cuts.begin(), cuts.end());
      return cuts;
    };
    std::vector<Segment> with_runs;
    auto add_tiles = [&](const std::vector<std::size_t>& cuts) {
      // Tiles of one length (within the tolerance) are one run.
      for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
        const double length = at[cuts[k + 1]] - at[cuts[k]];
        Segment* last = with_runs.empty() ? nullptr : &with_runs.back();
        if (last && !last->starts.empty() && last->to == cuts[k] &&
            std::abs(length - (at[last->starts[1]] - at[last->starts[0]])) <= tol_) {
          last->starts.push_back(cuts[k + 1]);
          last->to = cuts[k + 1];
        } else {
          with_runs.push_back({cuts[k], cuts[k + 1], {cuts[k], cuts[k + 1]}});
        }
        covered += cuts[k + 1] - cuts[k];
      }
    };
    for (Segment& seg : segments) {
      if (!seg.starts.empty()) {
        with_runs.push_back(std::move(seg));
        continue;
      }
      // Only beside an odd tile that is a bare primitive (a door), the
      // whole rest of the stretch: where the odd tile is built, the runs
      // already reach it (a run of one is a run there too).
      const std::vector<std::size_t> ahead = tiles(seg.from, seg.to, true);
      if (ahead.size() > 1 && (ahead.back() == seg.to || bare(ahead.back(), seg.to))) {
        add_tiles(ahead);
        if (ahead.back() < seg.to) with_runs.push_back({ahead.back(), seg.to, {}});
        continue;
      }
      const std::vector<std::size_t> behind = tiles(seg.from, seg.to, false);
      if (behind.size() > 1 && bare(seg.from, behind.front())) {
        with_runs.push_back({seg.from, behind.front(), {}});
        add_tiles(behind);
        continue;
      }
      with_runs.push_back(std::move(seg));
    }
    segments = std::move(with_runs);
    if (2 * covered < n) return false;
    if (!mixed) {
      // A row of one kind here, which another row may show trading.
      rows_seen_.shapes_lone.insert(in_runs.begin(), in_runs.end());
      return false;
    }
    // Note what the row showed: kinds in two tiles or more trade places.
    for (const auto& [shape, count] : kinds) (count >= 2 ? rows_seen_.shapes_seen : rows_seen_.shapes_lone).insert(shape);
    std::vector<SplitPart> out;
    for (const Segment& seg : segments) {
      if (!seg.starts.empty()) {
        std::vector<double> local;
        std::vector<std::size_t> starts;
        for (std::size_t i = seg.from; i <= seg.to; ++i) local.push_back(at[i] - at[seg.from]);
        for (std::size_t st : seg.starts) starts.push_back(st - seg.from);
        const double tile = local.back() / static_cast<double>(starts.size() - 1);
        auto part = fold_tiles(axis, parts, seg.from, local, starts, tile, false, Exchange::Shapes);
        if (!part) return false;
        out.push_back(*part);
      } else if (seg.to - seg.from == 1) {
        out.push_back(parts[seg.from]);
      } else {
        bool relative = true;
        for (std::size_t j = seg.from; j < seg.to; ++j) relative = relative && parts[j].size.relative;
        if (!relative) return false;
        out.push_back({Size{Expr::number(at[seg.to] - at[seg.from]), true}, group(axis, parts, seg.from, seg.to)});
      }
    }
    parts = std::move(out);
    return true;
  }

  // A node's shape: its structure with every size and amount left out
  // (memoised), so that tiles of one kind whose sizes were drawn tile by
  // tile are one kind.
  std::size_t tile_shape(NodeId id) {
    if (const auto it = shapes_.find(id); it != shapes_.end()) return it->second;
    const Operation& op = g_.op(id);
    std::size_t h = 0;
    if (const auto* sp = std::get_if<Split>(&op)) {
      h = split_shape(sp->axis, sp->parts, 0, sp->parts.size(), false);
    } else {
      h = hash_combine(kShapeSeed, op.index());
      if (const auto* p = std::get_if<Primitive>(&op)) h = hash_combine(h, p->label);
      if (const auto* r = std::get_if<Repeat>(&op)) h = hash_combine(h, shape_axis(r->axis));
      if (const auto* r = std::get_if<RepeatN>(&op)) h = hash_combine(h, shape_axis(r->axis));
      std::vector<NodeId> children;
      for_each_child(op, [&](NodeId c) { children.push_back(c); });
      for (NodeId c : children) h = hash_combine(h, tile_shape(c));
    }
    shapes_.emplace(id, h);
    return h;
  }

  // The shape group(axis, parts, from, to) would have, without interning
  // the group: segment_kinds weighs every piece of every run it tries.
  std::size_t group_shape(const Expr& axis, const std::vector<SplitPart>& parts, std::size_t from, std::size_t to) {
    return split_shape(axis, parts, from, to, true);
  }

  // A split's shape from its parts [from, to), each relative where
  // `all_relative` (a group's parts are) or as it says.
  std::size_t split_shape(const Expr& axis, const std::vector<SplitPart>& parts, std::size_t from, std::size_t to,
                          bool all_relative) {
    std::size_t h = hash_combine(hash_combine(kShapeSeed, kSplitIndex), shape_axis(axis));
    for (std::size_t i = from; i < to; ++i)
      h = hash_combine(hash_combine(h, all_relative || parts[i].size.relative), tile_shape(parts[i].child));
    return h;
  }

  static std::size_t shape_axis(const Expr& e) { return static_cast<std::size_t>(e.literal_axis().value_or(9)); }

  // The length of parts[i, i + period), all literal.
  static double length_of(const std::vector<SplitPart>& parts, std::size_t i, std::size_t period) {
    double length = 0;
    for (std::size_t j = 0; j < period; ++j) length += *parts[i + j].size.value.literal();
    return length;
  }

  // Do parts[a, a + period) and parts[b, b + period) hold the same
  // children with the same kinds of size, whatever the sizes?
  bool alike(const std::vector<SplitPart>& parts, std::size_t a, std::size_t b, std::size_t period) const {
    if (b + period > parts.size()) return false;
    for (std::size_t j = 0; j < period; ++j) {
      const SplitPart& x = parts[a + j];
      const SplitPart& y = parts[b + j];
      if (x.size.relative != y.size.relative || !x.size.value.literal() || !y.size.value.literal() ||
          !same_node(x.child, y.child))
        return false;
    }
    return true;
  }

  // The run of consecutive alike occurrences of a pattern of two parts or
  // more whose occurrences most often come in a row of one length: the
  // tiles' own phase (wall, window, wall), not the same run read a part
  // later (window, wall, wall), whose occurrences' lengths differ where
  // the windows do. Then the longest, the shortest pattern, the leftmost.
  std::optional<Run> alike_run(const std::vector<SplitPart>& parts) const {
    std::optional<Run> best;
    std::size_t best_tiled = 0;
    for (std::size_t start = 0; start < parts.size(); ++start) {
      for (std::size_t period = 2; period <= kMaxPeriod && start + 2 * period <= parts.size(); ++period) {
        std::size_t k = 1;
        while (alike(parts, start, start + k * period, period)) ++k;
        if (k < 2) continue;
        // Occurrences with a neighbour of the same length.
        std::size_t tiled = 0;
        for (std::size_t c = 0; c < k; ++c) {
          const double here = length_of(parts, start + c * period, period);
          const bool before = c > 0 && std::abs(length_of(parts, start + (c - 1) * period, period) - here) <= tol_;
          const bool after = c + 1 < k && std::abs(length_of(parts, start + (c + 1) * period, period) - here) <= tol_;
          if (before || after) ++tiled;
        }
        const Run r{start, period, k};
        if (!best || tiled > best_tiled ||
            (tiled == best_tiled && (r.parts() > best->parts() || (r.parts() == best->parts() && r.period < best->period)))) {
          best = r;
          best_tiled = tiled;
        }
      }
    }
    return best;
  }

  // A run of occurrences of one length whose sizes inside differ: a
  // repeat of a choice of them (fold_tiles), every cut where it was.
  std::optional<SplitPart> fold_alike(const Expr& axis, const std::vector<SplitPart>& parts, const Run& r) {
    std::vector<double> at{0};
    for (std::size_t i = r.start; i < r.start + r.parts(); ++i) at.push_back(at.back() + *parts[i].size.value.literal());
    std::vector<std::size_t> starts;
    for (std::size_t c = 0; c <= r.copies; ++c) starts.push_back(c * r.period);
    return fold_tiles(axis, parts, r.start, at, starts, at.back() / static_cast<double>(r.copies));
  }

  // The parts [from, to) as one split of relative sizes (their lengths).
  NodeId group(const Expr& axis, const std::vector<SplitPart>& parts, std::size_t from, std::size_t to) {
    Split s{axis, {}};
    for (std::size_t j = from; j < to; ++j) s.parts.push_back({{parts[j].size.value, true}, parts[j].child});
    return g_.intern({std::move(s), {}});
  }

  // copies tiles of body on a part of length total, as repeat(axis, tile).
  SplitPart repeat_part(const Expr& axis, double total, std::size_t copies, NodeId body, bool relative) {
    // The written tile size: any size in (L / n, L / (n - 1)] makes n tiles
    // on L, and a size exactly L / n would make n + 1 once rounding nudges
    // L up. So the shortest decimal a hair above the tile, within a
    // percent (and a half tile count) of it: 2.9 for 2.8999997, not the
    // noise.
    const double n = static_cast<double>(copies);
    const double tile = total / n;
    const double low = tile * (1 + 1e-5), high = tile * (1 + std::min(0.01, 0.5 / n));
    const double written = shortest_decimal((low + high) / 2, (high - low) / 2);
    const NodeId tiles = g_.intern({Repeat{axis, Expr::number(written), body}, {}});
    if (counts_) (*counts_)[tiles].push_back({static_cast<std::uint32_t>(copies), total});
    const auto along = axis.literal_axis();
    if (copies >= 2 && along && !is_primitive(body) && !std::holds_alternative<Choose>(g_.op(body))) {
      // The longest tile size that still makes this count here.
      double& reach = rows_seen_.tiles[{tile_shape(body), *along}];
      reach = std::max(reach, total / (n - 1));
    }
    return SplitPart{{Expr::number(total), relative}, tiles};
  }

  // Equal tiles holding different things (issue 4, "repeats that
  // stretch", for rows of unlike buildings): parts [from, to) cut into
  // k >= 3 pieces of one length at cuts the split already has, each piece
  // one part or a group of parts (a plot of three tower strips), become
  // repeat(axis, tile){ choose{ what the pieces hold } }, weighted by how
  // often each occurs. Only where the pieces are built, not bare
  // primitives: a window and a door of one width in a row keep their
  // places. nullopt when no such tiling exists or it would move a cut by
  // more than the tolerance.
  std::optional<SplitPart> fold_unlike(const Expr& axis, const std::vector<SplitPart>& parts, std::size_t from,
                                       std::size_t to, std::optional<double> only_tile = std::nullopt) {
    if (to - from < 3) return std::nullopt;
    std::vector<double> at{0};  // cut positions from parts[from]
    at.reserve(to - from + 1);
    for (std::size_t i = from; i < to; ++i) at.push_back(at.back() + *parts[i].size.value.literal());
    const double total = at.back();
    // The first tile ends at one of the first cuts; the largest count wins
    // (along a run of copies the smallest count: a pair's bays before
    // their walls and openings taken two by two).
    const std::size_t last = std::min(at.size() - 2, kMaxPartsPerTile);
    for (std::size_t step = 0; step < last; ++step) {
      const std::size_t m = only_tile ? last - step : step + 1;
      const auto k = static_cast<std::size_t>(std::lround(total / at[m]));
      if (k < 3 || k > to - from) continue;
      const double tile = total / static_cast<double>(k);
      // Along a run of equal copies, the copies are the tiles: a row
      // window, balcony, window, balcony is a run of pairs (a pattern kept
      // in every row, as far as this row shows), unless other rows showed
      // these tiles trading places freely (RowsSeen): then each copy
      // is cut into tiles, none a bare primitive (a bay's walls and
      // opening are no tiles).
      const double per_copy = only_tile ? std::round(*only_tile / tile) : 1;
      if (only_tile && (per_copy < 1 || std::abs(tile * per_copy - *only_tile) > tol_)) continue;
      std::vector<std::size_t> starts{0};  // each tile's first part, from `from`
      starts.reserve(k + 1);
      for (std::size_t j = 1, i = 1; j < k && i < at.size(); ++j) {
        while (i < at.size() && at[i] < static_cast<double>(j) * tile - tol_) ++i;
        if (i == at.size() || std::abs(at[i] - static_cast<double>(j) * tile) > tol_) break;
        starts.push_back(i);
      }
      if (starts.size() != k) continue;
      starts.push_back(to - from);
      if (auto part = fold_tiles(axis, parts, from, at, starts, tile, per_copy > 1)) return part;
    }
    return std::nullopt;
  }

  // How fold_tiles tells tiles that may trade places: by the labels they
  // hold (exchangeable), or by their kinds, already told (segment_kinds).
  enum class Exchange { Labels, Shapes };

  std::optional<SplitPart> fold_tiles(const Expr& axis, const std::vector<SplitPart>& parts, std::size_t from,
                                      const std::vector<double>& at, const std::vector<std::size_t>& starts,
                                      double tile, bool within_copies = false, Exchange exchange = Exchange::Labels) {
    const std::size_t k = starts.size() - 1;
    // Every cut stays where it was: inside a tile, its parts keep their
    // shares of the tile.
    for (std::size_t t = 0; t < k; ++t) {
      const double begin = at[starts[t]], length = at[starts[t + 1]] - begin;
      for (std::size_t i = starts[t]; i <= starts[t + 1]; ++i) {
        const double moved = static_cast<double>(t) * tile + (at[i] - begin) * (tile / length);
        if (std::abs(moved - at[i]) > tol_) return std::nullopt;
      }
    }
    std::vector<std::pair<NodeId, double>> held;  // distinct tiles, with counts
    bool built = false, empty = false;
    for (std::size_t t = 0; t < k; ++t) {
      const std::size_t a = from + starts[t], b = from + starts[t + 1];
      NodeId piece = parts[a].child;
      if (b - a > 1) {
        Split grouped = std::get<Split>(g_.op(group(axis, parts, a, b)));
        piece = fold_split(std::move(grouped), true);
      }
      built = built || !is_primitive(piece);
      if (within_copies && is_primitive(piece)) return std::nullopt;
      empty = empty || is_nil(piece);
      auto it = std::find_if(held.begin(), held.end(), [&](const auto& h) {
        return same_node(h.first, piece);
      });
      if (it == held.end()) held.emplace_back(piece, 1.0);
      else it->second += 1;
    }
    // (Tiles segment_kinds found are exchangeable by their kinds already.)
    if (held.size() > 1 && exchange == Exchange::Labels &&
        (!built || empty || !(within_copies ? seen_trading(held) : exchangeable(held))))
      return std::nullopt;
    NodeId body = held[0].first;
    if (held.size() > 1) {
      Choose choose;
      choose.options.reserve(held.size());
      for (const auto& [piece, count] : held) choose.options.push_back({Expr{}, Expr::number(count), piece});
      body = g_.intern({std::move(choose), {}});
    }
    return repeat_part(axis, at.back(), k, body, parts[from].size.relative);
  }

  // Tiles that may trade places: none holds a primitive that no other
  // tile holds, here or in some other row (RowsSeen). A ground floor
  // with the only door, under storeys of windows, is not one of the
  // storeys; the storeys above it are. Notes what it saw in rows_seen_.
  bool exchangeable(const std::vector<std::pair<NodeId, double>>& held) {
    std::map<LabelId, std::size_t> tiles_with;  // label -> tiles holding it
    for (const auto& [piece, count] : held)
      for (LabelId label : labels_below(piece)) tiles_with[label] += static_cast<std::size_t>(count);
    bool lone = false;
    for (const auto& [label, tiles] : tiles_with)
      if (tiles < 2 && !rows_seen_.seen.count(label)) {
        rows_seen_.lone.insert(label);
        lone = true;
      }
    if (lone) return false;
    for (const auto& [label, tiles] : tiles_with)
      if (tiles >= 2) rows_seen_.seen.insert(label);
    return true;
  }

  // Tiles that other rows showed trading places: every label they hold
  // was seen so (nothing noted: a periodic row is no evidence).
  bool seen_trading(const std::vector<std::pair<NodeId, double>>& held) {
    for (const auto& [piece, count] : held)
      for (LabelId label : labels_below(piece))
        if (!rows_seen_.seen.count(label)) return false;
    return true;
  }

  // The labels of the primitives below a node, ascending (memoised).
  const std::vector<LabelId>& labels_below(NodeId id) {
    if (id < labels_known_.size() && labels_known_[id]) return labels_[id];
    std::vector<LabelId> out;
    if (const auto* p = std::get_if<Primitive>(&g_.op(id))) out.push_back(p->label);
    // All the children's labels, then sorted once: a union per child made
    // a vector per child.
    std::size_t count = out.size();
    for_each_child(g_.op(id), [&](NodeId c) { count += labels_below(c).size(); });
    out.reserve(count);
    for_each_child(g_.op(id), [&](NodeId c) {
      const std::vector<LabelId>& below = labels_below(c);
      out.insert(out.end(), below.begin(), below.end());
    });
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    if (id >= labels_.size()) {
      // Grown by half again: folding adds nodes as it goes.
      labels_.resize(std::max<std::size_t>(g_.node_count() + g_.node_count() / 2, id + 1));
      labels_known_.resize(labels_.size(), false);
    }
    labels_known_[id] = true;
    return labels_[id] = std::move(out);
  }

  // A primitive, turned or not, or empty space: what a tile may hold only
  // when all tiles hold the same.
  bool is_primitive(NodeId id) const {
    const Operation& op = g_.op(id);
    if (const auto* r = std::get_if<Rotate>(&op)) return is_primitive(r->child);
    return std::holds_alternative<Primitive>(op) || std::holds_alternative<Nil>(op);
  }

  // Adjacent empty parts are one empty part, in place; whether any were.
  bool join_empty_parts(std::vector<SplitPart>& parts) const {
    std::size_t kept = 0;
    bool joined = false;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      if (kept > 0 && is_nil(parts[i].child) && is_nil(parts[kept - 1].child) &&
          parts[kept - 1].size.relative == parts[i].size.relative) {
        Expr& last = parts[kept - 1].size.value;
        last = Expr::number(*last.literal() + *parts[i].size.value.literal());
        joined = true;
        continue;
      }
      if (kept != i) parts[kept] = std::move(parts[i]);
      ++kept;
    }
    parts.resize(kept);
    return joined;
  }

  // A run with at most two parts on each side, none of them a tile of
  // another kind: the storeys between a ground floor and a cornice and
  // roof, as many as the height allows. Two copies are a run too beside
  // other parts (two storeys there are the storeys' zone, as three are),
  // but not alone: two equal halves of a split are a pair, not tiles. A
  // part as long as a tile just beside the run (a storey with a balcony
  // above two without) makes it a mixed row, left to merging.
  bool between_ends(const std::vector<SplitPart>& parts, const Run& r) const {
    const std::size_t end = r.start + r.parts();
    if (r.start > 2 || end + 2 < parts.size() || (r.parts() < 3 && r.parts() == parts.size())) return false;
    const double tile = length_of(parts, r.start, r.period);
    const bool before = r.start >= r.period && std::abs(length_of(parts, r.start - r.period, r.period) - tile) <= tol_;
    const bool after = end + r.period <= parts.size() && std::abs(length_of(parts, end, r.period) - tile) <= tol_;
    return !before && !after;
  }

  // Does a part as long as `length` stand just before parts[from] or just
  // after parts[to - 1]? Then what lies between is one of a row of
  // unlike tiles, not a run or a part alone.
  bool part_as_long_beside(const std::vector<SplitPart>& parts, std::size_t from, std::size_t to,
                           double length) const {
    auto as_long = [&](std::size_t j) {
      const auto other = parts[j].size.value.literal();
      return other && std::abs(*other - length) <= tol_;
    };
    return (from > 0 && as_long(from - 1)) || (to < parts.size() && as_long(to));
  }

  // Two unlike tiles of one length between ends (two storeys above a
  // ground floor, each holding its own bays): tiles, as two equal storeys
  // there are (between_ends), where what they hold trades places
  // (fold_tiles: every label in both, or seen trading in other rows).
  // Both built (a bare part beside a storey keeps its place), and not
  // beside a part as long: a longer row of unlike tiles.
  bool unlike_pair(const Expr& axis, std::vector<SplitPart>& parts) {
    for (std::size_t i = 0; i + 1 < parts.size() && i <= 2; ++i) {
      if (parts.size() - (i + 2) > 2 || parts.size() < 3) continue;
      const auto a = parts[i].size.value.literal(), b = parts[i + 1].size.value.literal();
      if (!parts[i].size.relative || !parts[i + 1].size.relative || !a || !b || std::abs(*a - *b) > tol_ ||
          same_node(parts[i].child, parts[i + 1].child) || is_primitive(parts[i].child) ||
          is_primitive(parts[i + 1].child))
        continue;
      if (part_as_long_beside(parts, i, i + 2, *a)) continue;
      const std::vector<double> at{0, *a, *a + *b};
      if (auto part = fold_tiles(axis, parts, i, at, {0, 1, 2}, (*a + *b) / 2)) {
        parts.erase(parts.begin() + static_cast<std::ptrdiff_t>(i) + 1);
        parts[i] = *part;
        return true;
      }
    }
    return false;
  }

  // Each built part alone among other parts, of a kind (tile_shape) that
  // some row, here or in another example, folded as tiles along this
  // axis, becomes a repeat of one tile where some tile size that makes
  // such a row's count would make one tile of it (ceil: n tiles on L for
  // sizes in [L / n, L / (n - 1))): one storey above a ground floor is
  // the storeys of the taller houses. Kinds not yet known as tiles are
  // noted (RowsSeen::lone_tiles) for merging to fold again.
  bool lone_tiles(const Expr& axis, std::vector<SplitPart>& parts) {
    const auto along = axis.literal_axis();
    if (unlike_ != UnlikeTiles::Fold || !along || parts.size() < 2) return false;
    bool changed = false;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      SplitPart& p = parts[i];
      const auto length = p.size.value.literal();
      const auto* folded = std::get_if<Repeat>(&g_.op(p.child));
      if (!p.size.relative || !length || is_primitive(p.child) || (folded && folded->axis.literal_axis() == along))
        continue;
      // Beside a part as long, or of its kind, it is one of a row of
      // tiles that did not fold (storeys each holding their own bays),
      // not a part alone.
      auto alike = [&](std::size_t j) { return tile_shape(parts[j].child) == tile_shape(p.child); };
      if (part_as_long_beside(parts, i, i + 1, *length) || (i > 0 && alike(i - 1)) ||
          (i + 1 < parts.size() && alike(i + 1)))
        continue;
      const std::pair<std::size_t, std::uint8_t> key{tile_shape(p.child), *along};
      const auto tile = rows_seen_.tiles.find(key);
      if (tile == rows_seen_.tiles.end()) {
        rows_seen_.lone_tiles.insert(key);
      } else if (*length < tile->second) {
        p = repeat_part(axis, *length, 1, p.child, true);
        changed = true;
      }
    }
    return changed;
  }

  // The split with its parts' children already folded; kNotYet when
  // nothing changes (children_changed false and no run folded).
  NodeId fold_split(Split s, bool children_changed) {
    std::vector<SplitPart> parts = std::move(s.parts);
    bool literal = s.axis.nodes().size() == 1 && s.axis.node(0).kind == ExprKind::Axis;
    for (const SplitPart& p : parts) literal = literal && p.size.value.literal();
    bool changed = children_changed;
    if (literal) {
      changed = join_empty_parts(parts) || changed;
      // Only a run of three parts or more that is (almost) the whole split
      // is folded, or one between ends (between_ends): the walls or
      // margins at its ends may differ. A run inside a mixed row (a | a |
      // b) is left to merging, which lines alike rows up first and finds
      // what combines freely there.
      auto replace = [&](std::size_t from, std::size_t to, const SplitPart& folded) {
        parts.erase(parts.begin() + static_cast<std::ptrdiff_t>(from), parts.begin() + static_cast<std::ptrdiff_t>(to));
        parts.insert(parts.begin() + static_cast<std::ptrdiff_t>(from), folded);
        changed = true;
      };
      bool folded = false;
      const auto r = best_run(parts);
      const bool run_folds = r && ((r->parts() >= 3 && r->parts() + 2 >= parts.size()) || between_ends(parts, *r));
      // Equal tiles of unlike contents, over the whole split or all but
      // one or two end parts (the most parts first): bays each a window or
      // a door, two or more of each (fold_tiles: a door bay alone keeps its
      // place, below). Tried first, with the run's copies as tiles (or
      // each cut into tiles, fold_unlike), where they cover as many parts
      // as the run of equal parts or more: a balcony bay before three
      // window bays is a row of four tiles, not a run of window bays read
      // a wall late.
      const bool unlike = unlike_ == UnlikeTiles::Fold;
      auto fold_unlike_tiles = [&](std::size_t more_than, std::optional<double> only_tile) {
        for (std::size_t outside = 0; !folded && outside <= 2 && outside + 3 <= parts.size(); ++outside) {
          if (parts.size() - outside <= more_than) break;
          for (std::size_t head = 0; head <= outside && !folded; ++head) {
            const std::size_t from = head, to = parts.size() - (outside - head);
            if (auto part = fold_unlike(s.axis, parts, from, to, only_tile)) {
              replace(from, to, *part);
              folded = true;
            }
          }
        }
      };
      if (unlike && run_folds) fold_unlike_tiles(r->parts() - 1, length_of(parts, r->start, r->period));
      if (!folded && run_folds) {
        if (const std::optional<SplitPart> part = fold(s.axis, parts, *r)) {
          replace(r->start, r->start + r->parts(), *part);
          folded = true;
        }
      }
      if (unlike && !folded) fold_unlike_tiles(0, std::nullopt);
      // Else a row of tiles of a few kinds with odd tiles among them.
      if (unlike && !folded && segment_kinds(s.axis, parts)) {
        folded = true;
        changed = true;
      }
      // Else a row of compound tiles with other parts among them (a shop
      // front of bays with the entrance bay after some of them): each run
      // of the tiles a repeat, each stretch between runs one group.
      if (!folded && segment_row(s.axis, parts, r)) {
        folded = true;
        changed = true;
      }
      if (unlike && !folded && unlike_pair(s.axis, parts)) {
        folded = true;
        changed = true;
      }
      changed = lone_tiles(s.axis, parts) || changed;
    }
    if (parts.size() == 1 && parts[0].size.relative) return parts[0].child;
    if (!changed) return kNotYet;
    return g_.intern({Split{s.axis, std::move(parts)}, {}});
  }

  static constexpr std::size_t kMaxPeriod = 8;
  static constexpr double kTileGap = 1.25;  // how much longer or shorter a run of one may be than its kind's tiles
  static constexpr std::size_t kShapeSeed = 0x5eed;
  static inline const std::size_t kSplitIndex = Operation{std::in_place_type<Split>}.index();
  static constexpr std::size_t kMaxPartsPerTile = 16;
  static constexpr NodeId kNotYet = static_cast<NodeId>(-1);
  Grammar& g_;
  double tol_;
  UnlikeTiles unlike_;
  TileCounts* counts_;  // where to note each repeat's tile count, or null
  const std::vector<bool>* kept_;  // by node id: left as it is, or null
  RowsSeen& rows_seen_;
  std::unordered_map<NodeId, std::size_t> shapes_;  // tile_shape, by node id
  std::vector<NodeId> memo_;  // by node id; kNotYet until folded
  std::vector<std::vector<LabelId>> labels_;  // labels_below, by node id
  std::vector<bool> labels_known_;            // by node id: labels_ holds its labels
};

}  // namespace

NodeId fold_repeats(Grammar& g, NodeId root, double tolerance, UnlikeTiles unlike, TileCounts* counts,
                    const std::vector<bool>* kept, RowsSeen* rows_seen) {
  RowsSeen own;
  return Folder(g, tolerance, unlike, counts, kept, rows_seen != nullptr ? *rows_seen : own).run(root);
}

}  // namespace vern
