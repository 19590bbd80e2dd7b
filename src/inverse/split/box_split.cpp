// Ordered-box splitting, after
//   "Procedural Generation of Buildings", chapter 9.1 "The Box-Splitting
//   Problem", section 9.1.3 "Ordered-Box Algorithm"
//   (seeds/procedural-generation-of-buildings.txt),
// written anew for this project.
//
// The 1-D idea (9.1.2): sort the bounds of intervals, max bounds before min
// bounds at equal values, and sweep with a counter of open intervals; where
// the counter returns to zero, nothing straddles the point and a cut fits.
// The ordered-box algorithm (9.1.3) sorts the bounds once per axis and keeps
// one counter per container, so a single sweep along an axis cuts every
// container that can be cut along it, and sweeps repeat over x, y, z until
// every container holds one box exactly or is empty space. Each sweep costs
// O(n), and each round of three sweeps makes the tree at least one level
// deeper: O(n log n + n m) for n boxes and a tree m levels deep.
//
// How it is laid out here (same results, measured 5x faster at 1,000,000
// boxes): a container's sweep reads only its own boxes' bounds, so instead
// of one sweep over all bounds per axis, each container owns one segment of
// the three sorted arrays of bounds (the same positions in all three: every
// box has two bounds per axis) and is swept on its own, the counter kept in
// a register. Cutting a container along an axis leaves that axis's segment
// already grouped by piece; the other two axes' segments are regrouped by a
// stable counting pass, so every segment stays sorted. The work per tree
// level is the same O(n) as the thesis's, but it streams through memory
// instead of jumping between containers, and nothing is allocated per
// container. Containers are taken from a stack, not level by level: a
// container's result does not depend on when it is cut. The axes a
// container tries: the root x, y, z; a piece of a cut along a the other
// two, the horizontal one before z (the thesis's global rounds would give
// a piece of a y-cut z first); and a cut that only peels empty space off a
// container's ends waits for an axis that divides its parts (see cut),
// unless every part borders that space alike (uniform_peel: a yard before
// a whole building) or one part spans what lies between the space on both
// sides (framed_peel: the margins round a pediment and its colonnade).
// The bounds are sorted by radix sort on their
// order-preserving bit patterns (11 bits a pass), ties in input order.
//
// What this file adds to the thesis:
//   - Snapping: per axis, the sorted coordinates fall into clusters that
//     span at most the tolerance, closest neighbours joined first, never
//     chained (coordinate_clusters.hpp); each cluster is one rank. Every
//     decision compares ranks exactly, so float noise neither blocks a cut
//     nor makes a sliver part or a false overlap. Where a cut is placed is
//     measured locally: the smallest of the coordinates of the boxes that
//     meet at it. A global value per rank would move distinct coordinates
//     that merely fall within the tolerance of each other somewhere in the
//     building (two towers' heights across a city) and lose exactness.
//   - Flat boxes (a facade panel: one rank on an axis) open before and close
//     after everything else at their rank, so no cut passes through them,
//     and a piece that would have zero length joins its neighbour: the
//     derivation skips zero-length parts, so they could not carry a box.
//   - Gaps first, across axes: a container whose first axis only cuts
//     between touching pieces is cut along the other horizontal axis when
//     that one has empty space right across it (cut_at_gaps_across).
//   - Termination: a container that no sweep along any of the three axes
//     divides is final (Kind::Unsplittable), so a pinwheel neither loops nor
//     crashes.
//   - Overlaps are found where they must show up: two boxes whose insides
//     intersect can never be cut apart, so they end in the same
//     unsplittable container. Only those containers are searched (sweep
//     and prune on x), so a valid example pays nothing for the check.
#include "inverse/split/box_split.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <limits>
#include <string_view>

#include "base/error.hpp"
#include "inverse/load/coordinate_clusters.hpp"
#include "inverse/split/comp_faces.hpp"

namespace vern {

namespace {

using Rank = std::uint32_t;

// Order of events sharing a rank (9.1.2 puts max bounds before min bounds;
// flat boxes wrap around both so that no cut passes through them).
enum EventOrder : std::uint64_t { kOpenFlat = 0, kCloseSolid = 1, kOpenSolid = 2, kCloseFlat = 3 };

// A piece of a container found by a sweep: ranks and measured coordinates
// along the sweep axis (lo_val: the smallest min at rank lo, hi_val: the
// largest max at rank hi), and how many boxes it holds.
struct Span {
  Rank lo = 0, hi = 0;
  double lo_val = 0, hi_val = 0;
  std::uint32_t count = 0;

  // Takes in the piece that follows this one.
  void absorb(const Span& next) {
    if (next.lo == lo) lo_val = std::min(lo_val, next.lo_val);
    if (next.hi > hi) {
      hi = next.hi;
      hi_val = next.hi_val;
    } else if (next.hi == hi) {
      hi_val = std::max(hi_val, next.hi_val);
    }
    count += next.count;
  }
};

// An event is a bound in an axis's sweep order, written box << 1 | (1 for a
// max bound): 4 bytes, so sweeps and regrouping stream little memory. Its
// rank and coordinate are looked up only where a piece begins or ends.
using Event = std::uint32_t;

// A container waiting to be cut: its segment [begin, end) of every axis's
// events, its extent, and the axes it has still to try.
struct Work {
  SplitTree* node = nullptr;  // where its result goes
  std::uint32_t begin = 0, end = 0;
  std::array<Rank, 3> lo{}, hi{};
  std::array<double, 3> lo_val{}, hi_val{};
  std::array<int, 3> axes{0, 1, 2};  // the axes to try, in order
  int tries = 3;                     // how many of them
  // The upper storeys of a stack that narrows upwards: the empty space
  // round them is peeled (x, y) before anything else (see narrowing_stack).
  bool peel_first = false;
};

std::string amount(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

// A double's bits as an unsigned integer in the same order (no NaNs here;
// -0 sorts just before +0, which the rank pass treats as equal).
std::uint64_t ordered_bits(double v) {
  const auto bits = std::bit_cast<std::uint64_t>(v);
  return (bits >> 63) != 0 ? ~bits : bits | (std::uint64_t{1} << 63);
}

double from_ordered_bits(std::uint64_t k) {
  return std::bit_cast<double>((k >> 63) != 0 ? k & ~(std::uint64_t{1} << 63) : ~k);
}

// A bound to sort: its coordinate's ordered bits and box << 1 | is_max.
// Packed to 12 bytes: the radix sort's passes move a quarter less memory.
struct __attribute__((packed)) Bound {
  std::uint64_t key = 0;
  std::uint32_t id = 0;
};

// Stable LSD radix sort of bounds by key, 11 bits a pass (2048 buckets keep
// the scatter's write streams in cache); passes whose digit is the same
// for every key are skipped. Small inputs use std::sort: ids ascend within
// a key there too, as the stable sort leaves them.
void radix_sort(std::vector<Bound>& bounds) {
  const std::size_t n = bounds.size();
  if (n < 4096) {
    std::sort(bounds.begin(), bounds.end(),
              [](const Bound& p, const Bound& q) { return p.key != q.key ? p.key < q.key : p.id < q.id; });
    return;
  }
  constexpr int kBits = 11, kPasses = 6;
  constexpr std::uint64_t kMask = (1u << kBits) - 1;
  std::vector<std::array<std::uint32_t, 1u << kBits>> counts(kPasses);
  for (auto& c : counts) c.fill(0);
  for (const Bound& b : bounds)
    for (int d = 0; d < kPasses; ++d) ++counts[static_cast<std::size_t>(d)][(b.key >> (kBits * d)) & kMask];
  std::vector<Bound> other(n);
  for (int d = 0; d < kPasses; ++d) {
    auto& count = counts[static_cast<std::size_t>(d)];
    const int shift = kBits * d;
    if (count[(bounds[0].key >> shift) & kMask] == n) continue;
    std::uint32_t sum = 0;
    for (auto& c : count) {
      const std::uint32_t here = c;
      c = sum;
      sum += here;
    }
    for (const Bound& b : bounds) other[count[(b.key >> shift) & kMask]++] = b;
    bounds.swap(other);
  }
}

class Splitter {
 public:
  Splitter(const std::vector<LabelledBox>& boxes, double tolerance, const std::string& source)
      : boxes_(boxes), source_(source), tolerance_(tolerance), span_of_(boxes.size(), 0) {
    // One pass over the boxes (they are large; the bounds are not): check
    // them, measure the root, and list every axis's bounds to sort.
    const std::size_t n = boxes.size();
    std::array<std::vector<Bound>, 3> bounds;
    for (auto& list : bounds) list.resize(2 * n);
    root_lo_.fill(std::numeric_limits<double>::infinity());
    root_hi_.fill(-std::numeric_limits<double>::infinity());
    for (std::uint32_t b = 0; b < n; ++b) {
      const LabelledBox& box = boxes[b];
      for (glm::length_t a = 0; a < 3; ++a) {
        if (!(box.min[a] <= box.max[a])) {  // also catches NaN
          fail(ErrorKind::Input, source, {box.line, box.line != 0 ? 1u : 0u},
               "object " + describe_object(box) + " has a box whose minimum exceeds its maximum (or is not a number)",
               "give each part real geometry");
        }
        const auto ax = static_cast<std::size_t>(a);
        root_lo_[ax] = std::min(root_lo_[ax], box.min[a]);
        root_hi_[ax] = std::max(root_hi_[ax], box.max[a]);
        bounds[ax][2 * b] = {ordered_bits(box.min[a]), b << 1};
        bounds[ax][2 * b + 1] = {ordered_bits(box.max[a]), (b << 1) | 1u};
      }
    }
    for (std::size_t a = 0; a < 3; ++a) {
      radix_sort(bounds[a]);
      rank_axis(a, bounds[a], tolerance);
      bounds[a] = {};
    }
    for (std::uint32_t b = 0; b < n && !any_flat_; ++b)
      for (std::size_t a = 0; a < 3; ++a) any_flat_ = any_flat_ || lo_[a][b] == hi_[a][b];
    scratch_.resize(2 * n);
    scratch2_.resize(2 * n);
    starts_.resize(2 * n + 1);
  }

  SplitTree run() {
    // The root is the bounds of all boxes.
    SplitTree root;
    Work w;
    w.node = &root;
    w.end = static_cast<std::uint32_t>(2 * boxes_.size());
    for (std::size_t a = 0; a < 3; ++a) {
      w.lo[a] = 0;
      w.hi[a] = ranks_[a] - 1;
    }
    w.lo_val = root_lo_;
    w.hi_val = root_hi_;
    stack_.push_back(w);
    while (!stack_.empty()) {
      const Work next = stack_.back();
      stack_.pop_back();
      cut(next);
    }
    if (overlaps_) {
      for (const auto& group : groups_) overlaps_in(group, *overlaps_);
      std::sort(overlaps_->begin(), overlaps_->end());
    } else {
      check_overlaps();
    }
    return root;
  }

  // Overlapping pairs are listed here instead of refused.
  void collect_overlaps(std::vector<std::pair<std::uint32_t, std::uint32_t>>* out) { overlaps_ = out; }

 private:
  // Snaps and ranks the coordinates along axis a (its bounds sorted), and
  // puts the sweep events in order.
  void rank_axis(std::size_t ax, const std::vector<Bound>& bounds, double tolerance) {
    const std::size_t n = boxes_.size();
    // Each cluster of coordinates (none spanning more than the tolerance,
    // coordinate_clusters.hpp) is one rank.
    std::vector<Rank>& lo = lo_[ax];
    std::vector<Rank>& hi = hi_[ax];
    lo.resize(n);
    hi.resize(n);
    std::vector<std::uint32_t> run_start;  // first position of each rank
    run_start = cluster_starts(
        static_cast<std::uint32_t>(bounds.size()), [&](std::uint32_t i) { return from_ordered_bits(bounds[i].key); },
        tolerance);
    Rank rank = 0;
    for (std::size_t i = 0; i < bounds.size(); ++i) {
      if (rank + 1 < run_start.size() && run_start[rank + 1] == i) ++rank;
      ((bounds[i].id & 1u) != 0 ? hi : lo)[bounds[i].id >> 1] = rank;
    }
    ranks_[ax] = static_cast<Rank>(run_start.size());
    run_start.push_back(static_cast<std::uint32_t>(bounds.size()));

    // Within a rank, events go by order class, then by box. A rank whose
    // bounds all have one coordinate (bit for bit) keeps it, so the sweep
    // need not visit the boxes there; NaN marks a rank of snapped values.
    std::vector<Event>& events = events_[ax];
    events.resize(2 * n);
    std::vector<double>& value = rank_value_[ax];
    value.resize(ranks_[ax]);
    std::vector<std::uint64_t> order;  // class << 32 | box
    for (Rank r = 0; r < ranks_[ax]; ++r) {
      const std::uint32_t from = run_start[r], to = run_start[r + 1];
      value[r] = bounds[from].key == bounds[to - 1].key ? from_ordered_bits(bounds[from].key)
                                                        : std::numeric_limits<double>::quiet_NaN();
      if (to - from == 1) {  // alone at its rank: not flat (a flat box has both bounds here)
        events[from] = bounds[from].id;
        continue;
      }
      order.clear();
      for (std::uint32_t i = from; i < to; ++i) {
        const std::uint32_t b = bounds[i].id >> 1;
        const bool flat = lo[b] == hi[b];
        const bool close = (bounds[i].id & 1u) != 0;
        const std::uint64_t cls = close ? (flat ? kCloseFlat : kCloseSolid) : (flat ? kOpenFlat : kOpenSolid);
        order.push_back((cls << 32) | b);
      }
      std::sort(order.begin(), order.end());
      for (std::size_t k = 0; k < order.size(); ++k) {
        const std::uint64_t cls = order[k] >> 32;
        const auto b = static_cast<std::uint32_t>(order[k] & 0xffffffffu);
        const bool close = cls == kCloseSolid || cls == kCloseFlat;
        events[from + k] = (b << 1) | (close ? 1u : 0u);
      }
    }
  }

  // An event's rank and coordinate along axis a.
  Rank rank_of(std::size_t a, Event e) const { return ((e & 1u) != 0 ? hi_[a] : lo_[a])[e >> 1]; }
  double value_of(std::size_t a, Event e) const {
    const LabelledBox& b = boxes_[e >> 1];
    return (e & 1u) != 0 ? b.max[static_cast<glm::length_t>(a)] : b.min[static_cast<glm::length_t>(a)];
  }

  // A container: a leaf if it holds one box that fills it (a PrimContainer),
  // else cut along the first of its axes that divides it, else unsplittable.
  void cut(const Work& w) {
    if (w.end - w.begin == 2) {
      const std::uint32_t b = events_[0][w.begin] >> 1;
      bool fills = true;
      for (std::size_t a = 0; a < 3; ++a) fills = fills && lo_[a][b] == w.lo[a] && hi_[a][b] == w.hi[a];
      if (fills) {
        set_extent(*w.node, w.lo_val, w.hi_val);
        w.node->kind = SplitTree::Kind::Leaf;
        w.node->box = b;
        return;
      }
    }
    // A mass model's faces come before any cut: cuts through the open box
    // would slice its faces into columns whose bays happen to line up
    // front and back, each a flat part in empty space.
    if (faces_of_mass(w)) return;
    // The axes in order, but a cut that only peels empty space off the
    // ends (one piece: a row of buildings under the air above its lowest
    // roofs) waits while another axis divides the parts themselves: the row
    // is cut into buildings and each building keeps its own air, as a
    // person would model it, and rows of different heights share one
    // structure.
    if (w.peel_first) {
      for (int a = 0; a < 2; ++a) {
        if (w.lo[static_cast<std::size_t>(a)] == w.hi[static_cast<std::size_t>(a)]) continue;
        if (find_pieces(w, a) && pieces_.size() == 1) {
          cut_along(w, a, Peel::KeepPeeling);
          return;
        }
      }
    }
    int peel = -1;
    for (int i = 0; i < w.tries; ++i) {
      const int a = w.axes[static_cast<std::size_t>(i)];
      if (w.lo[static_cast<std::size_t>(a)] == w.hi[static_cast<std::size_t>(a)]) continue;  // flat along a
      if (!find_pieces(w, a)) continue;
      if (pieces_.size() == 1 && (uniform_peel(w, a) || framed_peel(w, a))) {
        cut_along(w, a);
        return;
      }
      if (pieces_.size() > 1) {
        if (a != 2 && storeys_first(w, a)) {
          cut_along(w, 2);
          return;
        }
        if (a != 2 && !interior_gap() && cut_at_gaps_across(w, i)) return;
        if (a != 2 && cut_along_faces_across(w, i)) return;
        if (a == 2 && narrowing_stack(w)) {
          cut_along(w, a, Peel::Upper);
          return;
        }
        group_partial_height_pieces(w, a);
        group_mass_faces(w, a);
        cut_along(w, a);
        return;
      }
      if (peel < 0) peel = a;
    }
    if (peel >= 0) {
      find_pieces(w, peel);
      cut_along(w, peel);
      return;
    }
    unsplittable(w);
  }

  // Does the one piece of the last sweep along a leave empty space that
  // every box borders alike: all its boxes start where the piece starts,
  // if there is space before it, and end where it ends, if there is space
  // after it? A front yard before a whole building, or air over a flat
  // row: one empty part, peeled first, where waiting would give every part
  // of the building its own strip of it (each leaf a split with a nil) and
  // the examples as many sizes to join as they have parts.
  //
  // Along a horizontal axis, a building whose upper parts are set back
  // (tiers above a ground floor) borders its yard alike too where its
  // front at the bottom runs right across: the boxes standing on the
  // container's bottom that meet the space cover the other horizontal
  // axis from end to end.
  bool uniform_peel(const Work& w, int a) const {
    const auto ax = static_cast<std::size_t>(a);
    const Span& piece = pieces_[0];
    const bool before = piece.lo != w.lo[ax], after = piece.hi != w.hi[ax];
    bool alike_before = true, alike_after = true;
    const Event* events = events_[ax].data();
    for (std::uint32_t i = w.begin; i < w.end; ++i) {
      const Event e = events[i];
      const bool is_max = (e & 1u) != 0;
      if (!is_max && before && rank_of(ax, e) != piece.lo) alike_before = false;
      if (is_max && after && rank_of(ax, e) != piece.hi) alike_after = false;
    }
    if (a != 2 && before && !alike_before) alike_before = front_right_across(w, a, false);
    if (a != 2 && after && !alike_after) alike_after = front_right_across(w, a, true);
    return (before || after) && (!before || alike_before) && (!after || alike_after);
  }

  // Does one box span the one piece of the last sweep along a from end to
  // end, with empty space on both sides of it? Then that space is a margin
  // of the whole piece (a portico set in on its front, its pediment right
  // across it over a colonnade), peeled first: waiting for the rows would
  // give each row its own margins, and a row whose last part stops short
  // of the frame (the colonnade's last column) would lose where the frame
  // ends, so nothing could keep it lined up with the pediment. Space on
  // one side only is not a frame: the air over a row of buildings, the
  // tallest of which may well be one box from the ground up, waits.
  bool framed_peel(const Work& w, int a) const {
    const auto ax = static_cast<std::size_t>(a);
    const Span& piece = pieces_[0];
    if (piece.lo == w.lo[ax] || piece.hi == w.hi[ax]) return false;
    const Event* events = events_[ax].data();
    for (std::uint32_t i = w.begin; i < w.end; ++i) {
      const Event e = events[i];
      if ((e & 1u) != 0) continue;
      const std::uint32_t box = e >> 1;
      if (lo_[ax][box] == piece.lo && hi_[ax][box] == piece.hi) return true;
    }
    return false;
  }

  // Do the boxes on the container's bottom that start where the one piece
  // along a starts (end where it ends: back) cover the other horizontal
  // axis from end to end?
  bool front_right_across(const Work& w, int a, bool back) const {
    const auto ax = static_cast<std::size_t>(a), bx = static_cast<std::size_t>(1 - a);
    const Span& piece = pieces_[0];
    std::vector<std::pair<Rank, Rank>> spans;
    const Event* events = events_[ax].data();
    for (std::uint32_t i = w.begin; i < w.end; ++i) {
      const Event e = events[i];
      if (((e & 1u) != 0) != back) continue;
      const std::uint32_t box = e >> 1;
      if (lo_[2][box] != w.lo[2] || rank_of(ax, e) != (back ? piece.hi : piece.lo)) continue;
      spans.emplace_back(lo_[bx][box], hi_[bx][box]);
    }
    return covers(spans, w.lo[bx], w.hi[bx]);
  }

  // Do the intervals (sorted here) cover [lo, hi] without a gap?
  static bool covers(std::vector<std::pair<Rank, Rank>>& intervals, Rank lo, Rank hi) {
    std::sort(intervals.begin(), intervals.end());
    Rank reached = lo;
    for (const auto& [from, to] : intervals) {
      if (from > reached) return false;
      reached = std::max(reached, to);
    }
    return reached >= hi;
  }

  // A piece at least this much of whose volume its boxes fill is full.
  static constexpr double kFull = 1 - 1e-6;

  // How much of each piece of the last sweep along a its boxes fill, as a
  // share of the piece's volume (of its area, in a container flat on an
  // axis).
  void piece_fill(const Work& w, int a, std::vector<double>& fill) const {
    const auto ax = static_cast<std::size_t>(a);
    fill.assign(pieces_.size(), 0.0);
    const Event* events = events_[ax].data();
    for (std::uint32_t i = w.begin; i < w.end; ++i) {
      const Event e = events[i];
      if ((e & 1u) != 0) continue;
      const LabelledBox& b = boxes_[e >> 1];
      double v = 1;
      for (std::size_t k = 0; k < 3; ++k)
        if (w.hi_val[k] > w.lo_val[k]) v *= b.max[static_cast<glm::length_t>(k)] - b.min[static_cast<glm::length_t>(k)];
      fill[target_[span_of_[e >> 1]]] += v;
    }
    for (std::size_t p = 0; p < pieces_.size(); ++p) {
      double v = 1;
      for (std::size_t k = 0; k < 3; ++k) {
        const double lo = k == ax ? pieces_[p].lo_val : w.lo_val[k], hi = k == ax ? pieces_[p].hi_val : w.hi_val[k];
        if (w.hi_val[k] > w.lo_val[k]) v *= hi - lo;
      }
      fill[p] = v > 0 ? fill[p] / v : 1.0;
    }
  }

  // Storeys before plots, where cutting along a first would not divide
  // the container into whole things:
  //   - the lowest storey is a slab right across the container (a podium
  //     under a set-back tower, a base under a house and its garage) and
  //     some piece of the cut along a is not full: a thin column of the
  //     podium with only air above it is no building;
  //   - or every piece along a is full but the cuts along a only happen to
  //     line up through the storeys: in every storey they are at most half
  //     of the storey's own boundaries along a (a door and bays below, a
  //     row of dormers above, meeting at one place by chance). Cuts that
  //     make up most of some storey's boundaries (end walls through a
  //     terrace's storeys and its roof band) are the building's own.
  // Leaves pieces_ as the sweep along z found them when it says so, else as
  // the sweep along a found them.
  bool storeys_first(const Work& w, int a) {
    piece_fill(w, a, fill_);
    const bool whole = std::all_of(fill_.begin(), fill_.end(), [](double f) { return f >= kFull; });
    pieces_fill_ = fill_;
    const std::size_t cuts_along_a = pieces_.size() - 1;
    cut_ranks_.clear();
    alike_pieces_ = true;
    const double first_length = pieces_[0].hi_val - pieces_[0].lo_val;
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
      alike_pieces_ = alike_pieces_ && std::abs(pieces_[i].hi_val - pieces_[i].lo_val - first_length) <= 2 * tolerance_;
      if (i + 1 == pieces_.size()) continue;
      cut_ranks_.push_back(pieces_[i].hi);
      cut_ranks_.push_back(pieces_[i + 1].lo);
    }
    if (w.hi[2] > w.lo[2] && find_pieces(w, 2) && pieces_.size() > 1) {
      if (!whole) {
        piece_fill(w, 2, fill_);
        if (fill_.front() >= kFull && !taller_neighbours_alike(w, a)) return true;
      } else if (cuts_line_up_by_chance(w, a, cuts_along_a)) {
        return true;
      }
    }
    find_pieces(w, a);
    return false;
  }

  // After a sweep along z whose lowest piece is a slab right across: are
  // the pieces along a buildings of different heights, side by side (a
  // terrace of houses of two to four storeys over their shops)? Each
  // piece that stops short of the top holds parts above the slab (it is
  // no column of the podium under air), and above its top the other
  // pieces hold only parts labelled as some part of its own: its taller
  // neighbours go on as it does. Not a podium beside its tower, nor
  // storeys beside a roof narrower than they are (a lantern, tiers): what
  // stands above those is of another kind. Leaves pieces_ as the sweep
  // along z found them.
  bool taller_neighbours_alike(const Work& w, int a) {
    const Rank slab_top = pieces_.front().hi;
    find_pieces(w, a);
    const bool alike = taller_neighbours_alike_pieces(w, a, slab_top);
    find_pieces(w, 2);
    return alike;
  }

  // taller_neighbours_alike on pieces_ as the sweep along a found them,
  // in O(n log n): a box above the tops of the k lowest pieces that stop
  // short must bear a label all k hold.
  bool taller_neighbours_alike_pieces(const Work& w, int a, Rank slab_top) const {
    const std::size_t n = pieces_.size();
    std::vector<Rank> top(n, w.lo[2]);
    std::vector<bool> storeyed(n, false);
    std::vector<std::vector<std::string_view>> labels(n);
    Rank highest_bottom = w.lo[2];
    const Event* events = events_[static_cast<std::size_t>(a)].data();
    for (std::uint32_t i = w.begin; i < w.end; ++i) {
      if (events[i] & 1u) continue;
      const std::uint32_t box = events[i] >> 1;
      const std::uint32_t p = target_[span_of_[box]];
      top[p] = std::max(top[p], hi_[2][box]);
      storeyed[p] = storeyed[p] || lo_[2][box] >= slab_top;
      highest_bottom = std::max(highest_bottom, lo_[2][box]);
      labels[p].push_back(boxes_[box].label);
    }
    std::vector<std::size_t> short_of_top;
    for (std::size_t p = 0; p < n; ++p) {
      if (top[p] >= w.hi[2]) continue;
      // Parts above the slab in it, and some in another piece above it.
      if (!storeyed[p] || highest_bottom < top[p]) return false;
      short_of_top.push_back(p);
    }
    std::sort(short_of_top.begin(), short_of_top.end(), [&](std::size_t x, std::size_t y) { return top[x] < top[y]; });
    std::vector<Rank> tops;
    std::vector<std::vector<std::string_view>> shared;  // labels the lowest k + 1 all hold
    for (const std::size_t p : short_of_top) {
      std::sort(labels[p].begin(), labels[p].end());
      labels[p].erase(std::unique(labels[p].begin(), labels[p].end()), labels[p].end());
      tops.push_back(top[p]);
      if (shared.empty()) {
        shared.push_back(labels[p]);
      } else {
        std::vector<std::string_view> both;
        std::set_intersection(shared.back().begin(), shared.back().end(), labels[p].begin(), labels[p].end(),
                              std::back_inserter(both));
        shared.push_back(std::move(both));
      }
    }
    for (std::uint32_t i = w.begin; i < w.end; ++i) {
      if (events[i] & 1u) continue;
      const std::uint32_t box = events[i] >> 1;
      const auto k = static_cast<std::size_t>(std::upper_bound(tops.begin(), tops.end(), lo_[2][box]) - tops.begin());
      if (k > 0 && !std::binary_search(shared[k - 1].begin(), shared[k - 1].end(), std::string_view(boxes_[box].label)))
        return false;
    }
    return true;
  }

  // After a sweep along z: does every piece have more than twice `cuts`
  // boundaries of its own along a (its boxes' faces strictly inside the
  // container)? Not where two cuts or more (cut_ranks_) make pieces of
  // one length (alike_pieces_) and run through every storey while the
  // storeys share no other boundary: storeys drawn apart (a door bay and
  // a window bay under a chimney and its roof) line up at one place by
  // chance, not at every party wall of a terrace of equal houses;
  // storeys that share their other boundaries too (aligned bays) are a
  // grid, read as storeys.
  bool cuts_line_up_by_chance(const Work& w, int a, std::size_t cuts) {
    const auto ax = static_cast<std::size_t>(a);
    faces_.clear();
    const Event* events = events_[ax].data();
    for (std::uint32_t i = w.begin; i < w.end; ++i) {
      const Event e = events[i];
      const Rank r = rank_of(ax, e);
      if (r <= w.lo[ax] || r >= w.hi[ax]) continue;
      faces_.push_back((std::uint64_t{target_[span_of_[e >> 1]]} << 32) | r);
    }
    std::sort(faces_.begin(), faces_.end());
    faces_.erase(std::unique(faces_.begin(), faces_.end()), faces_.end());
    std::vector<std::size_t> own(pieces_.size(), 0);
    for (const std::uint64_t f : faces_) ++own[static_cast<std::size_t>(f >> 32)];
    if (!std::all_of(own.begin(), own.end(), [&](std::size_t n) { return n > 2 * cuts; })) return false;
    if (cuts < 2 || !alike_pieces_) return true;
    // Is some boundary other than the cuts in two storeys?
    std::vector<Rank> ranks;
    for (const std::uint64_t f : faces_) {
      const auto r = static_cast<Rank>(f & 0xffffffffu);
      if (!std::binary_search(cut_ranks_.begin(), cut_ranks_.end(), r)) ranks.push_back(r);
    }
    std::sort(ranks.begin(), ranks.end());
    return std::adjacent_find(ranks.begin(), ranks.end()) != ranks.end();
  }

  // Is there empty space between two of the pieces find_pieces found?
  bool interior_gap() const {
    for (std::size_t i = 0; i + 1 < pieces_.size(); ++i)
      if (pieces_[i].hi < pieces_[i + 1].lo) return true;
    return false;
  }

  // Empty space separates buildings across axes too. The pieces of the
  // axis tried first (axes[i]) all touch; when the other horizontal axis,
  // still to be tried, has empty space right across the container (a
  // yard between a house's range and a barn's), the container is cut
  // there first, and each building is cut on its own. Else the first
  // axis's cut through all of them would depend on whether their bays
  // happen to line up, which differs from example to example. Leaves
  // pieces_ as find_pieces(w, axes[i]) found them when it does not cut.
  bool cut_at_gaps_across(const Work& w, int i) {
    for (int j = i + 1; j < w.tries; ++j) {
      const int b = w.axes[static_cast<std::size_t>(j)];
      if (b == 2 || w.lo[static_cast<std::size_t>(b)] == w.hi[static_cast<std::size_t>(b)]) continue;
      if (find_pieces(w, b) && pieces_.size() > 1 && interior_gap()) {
        cut_along(w, b);
        return true;
      }
    }
    find_pieces(w, w.axes[static_cast<std::size_t>(i)]);
    return false;
  }

  // Is the run of pieces_[first..last] of the last sweep along a storeys:
  // its boxes divide along z (a storey line runs right across the run) and
  // the lowest storey, at the container's bottom, fills the run right
  // across (a ground floor, not buildings of different heights side by
  // side)?
  bool storeyed_run(const Work& w, int a, std::size_t first, std::size_t last) const {
    const auto bx = static_cast<std::size_t>(1 - a);
    // The container's events along z are in order: a sweep over the run's
    // boxes finds its lowest storey, where no box of the run is open.
    const Event* events = events_[2].data();
    int open = 0;
    bool started = false;
    double volume = 0, top = w.lo_val[2];
    std::uint32_t i = w.begin;
    for (; i < w.end; ++i) {
      const Event e = events[i];
      const std::uint32_t box = e >> 1;
      const std::uint32_t p = target_[span_of_[box]];
      if (p < first || p > last) continue;
      if ((e & 1u) == 0) {
        if (!started && lo_[2][box] != w.lo[2]) return false;  // air under the run
        started = true;
        ++open;
        continue;
      }
      const LabelledBox& b = boxes_[box];
      volume += (b.max.x - b.min.x) * (b.max.y - b.min.y) * (b.max.z - b.min.z);
      top = std::max(top, b.max.z);
      if (--open == 0) break;
    }
    // Every box of the run closed there: where its last box ends is its
    // lowest storey's top; none below the container's top, no storey line.
    if (!started || i == w.end || hi_[2][events[i] >> 1] >= w.hi[2]) return false;
    const double along = pieces_[last].hi_val - pieces_[first].lo_val, across = w.hi_val[bx] - w.lo_val[bx];
    const double slab = along * across * (top - w.lo_val[2]);
    return slab > 0 && volume >= slab * (1 - 1e-6);
  }

  // Per cut of the last sweep along a (between pieces_[c] and
  // pieces_[c + 1]): is it met by parts along the whole container on
  // axis b, from one side at least? Leaves pieces_ as they are.
  void faces_right_across(const Work& w, int a, int b, std::vector<bool>& out) {
    const auto ax = static_cast<std::size_t>(a), bx = static_cast<std::size_t>(b);
    const std::size_t cuts = pieces_.size() - 1;
    // Per cut and side (0: the piece before it, 1: the one after), the
    // intervals along b of the boxes that end or start at the cut.
    auto& faces = cut_faces_;
    if (faces.size() < cuts) faces.resize(cuts);
    for (std::size_t c = 0; c < cuts; ++c)
      for (auto& side : faces[c]) side.clear();
    const Event* events = events_[ax].data();
    for (std::uint32_t i = w.begin; i < w.end; ++i) {
      const Event e = events[i];
      const std::uint32_t box = e >> 1;
      const std::uint32_t piece = target_[span_of_[box]];
      const std::pair<Rank, Rank> along_b{lo_[bx][box], hi_[bx][box]};
      if ((e & 1u) != 0) {
        if (piece < cuts && hi_[ax][box] == pieces_[piece].hi) faces[piece][0].push_back(along_b);
      } else if (piece > 0 && lo_[ax][box] == pieces_[piece].lo) {
        faces[piece - 1][1].push_back(along_b);
      }
    }
    out.assign(cuts, false);
    for (std::size_t c = 0; c < cuts; ++c)
      out[c] = covers(faces[c][0], w.lo[bx], w.hi[bx]) || covers(faces[c][1], w.lo[bx], w.hi[bx]);
  }

  // Columns that only line up (issue 23: bays aligned through every
  // storey). Where some cuts along a horizontal axis run along faces from
  // the container's bottom to its top (a pier, a building's end wall) and
  // others between touching pieces stop short of it on both sides (bays
  // of storeys beside a roof that crosses the others: the cut runs
  // through the air over the storeys), only the first are cut now; each
  // run of pieces between them is one piece, cut again later along the
  // other axes first. A facade of aligned bays under a roof is then
  // storeys, each a row of bays, and not columns each with its own
  // storey heights, which variants draw apart. Only runs that are
  // storeys are joined (storeyed_run): a row of houses of different
  // heights keeps its houses, and a city block its buildings.
  void group_partial_height_pieces(const Work& w, int a) {
    if (a == 2 || pieces_.size() < 3 || w.lo[2] == w.hi[2]) return;
    // A piece its boxes fill (storeys_first's fills, for these pieces)
    // meets its neighbours at faces right across: only two touching
    // pieces neither of which is full may meet short of the top.
    bool maybe = false;
    for (std::size_t c = 0; c + 1 < pieces_.size() && c + 1 < pieces_fill_.size() && !maybe; ++c)
      maybe = pieces_[c].hi == pieces_[c + 1].lo && pieces_fill_[c] < kFull && pieces_fill_[c + 1] < kFull;
    if (!maybe) return;
    faces_right_across(w, a, 2, across_);
    const std::size_t n = pieces_.size();
    std::vector<bool> joins(n, false);
    bool any_full = false;
    for (std::size_t c = 0; c + 1 < n; ++c) {
      const bool touching = pieces_[c].hi == pieces_[c + 1].lo;
      any_full = any_full || across_[c] || !touching;
      joins[c + 1] = touching && !across_[c];
    }
    for (std::size_t first = 0; first < n;) {
      std::size_t last = first;
      while (last + 1 < n && joins[last + 1]) ++last;
      if (last > first && !storeyed_run(w, a, first, last))
        for (std::size_t i = first + 1; i <= last; ++i) joins[i] = false;
      first = last + 1;
    }
    if (!any_full || std::none_of(joins.begin(), joins.end(), [](bool j) { return j; })) return;
    if (compound_.size() != n) compound_.assign(n, kNone);
    join_pieces(joins);
  }

  // Pieces along a that are all flat parts on the container's sides (or
  // on its ends along a) are bands of a mass model's faces: a tower cut
  // into its faces whose storeys line up round all four of them. Each
  // run of two or more such pieces is one piece, its faces read as comp
  // (faces_of_mass), so each face's storeys are its own repeat, not the
  // whole mass cut into storeys of four faces each (the top one with the
  // roof, another size).
  void group_mass_faces(const Work& w, int a) {
    if (!any_flat_) return;  // solid parts only: no faces
    const std::size_t n = pieces_.size();
    for (std::size_t k = 0; k < 3; ++k)
      if (w.lo[k] == w.hi[k]) return;
    const auto ax = static_cast<std::size_t>(a);
    // Each piece's events lie together in the sweep's order: found by
    // their rank, and read whole only where the first box opening there
    // is on a face (a building of solid parts pays a search per piece).
    std::vector<bool> faces(n, false);
    const Event* events = events_[ax].data();
    for (std::size_t p = 0; p < n; ++p) {
      const Rank lo = pieces_[p].lo;
      std::uint32_t i = static_cast<std::uint32_t>(
          std::lower_bound(events + w.begin, events + w.end, lo,
                           [&](Event e, Rank r) { return rank_of(ax, e) < r; }) -
          events);
      while (i < w.end && ((events[i] & 1u) != 0 || target_[span_of_[events[i] >> 1]] != p)) ++i;
      if (i == w.end || !on_face(w, events[i] >> 1)) continue;
      faces[p] = true;
      for (; i < w.end && rank_of(ax, events[i]) <= pieces_[p].hi && faces[p]; ++i)
        if ((events[i] & 1u) == 0 && target_[span_of_[events[i] >> 1]] == p && !on_face(w, events[i] >> 1))
          faces[p] = false;
    }
    std::vector<bool> joins(n, false);
    std::size_t joined = 0;
    for (std::size_t c = 1; c < n; ++c) {
      joins[c] = faces[c] && faces[c - 1] && pieces_[c - 1].hi == pieces_[c].lo;
      joined += joins[c] ? 1 : 0;
    }
    // Never all into one: that piece would be the container itself, cut
    // again the same way for ever (its faces were no mass: faces_of_mass
    // found none).
    if (joined == 0 || joined + 1 == n) return;
    if (compound_.size() != n) compound_.assign(n, kNone);
    join_pieces(joins);
  }

  // The first horizontal axis's cuts are not all along faces, and the
  // other horizontal axis, still to be tried, divides the container with
  // cuts that all are (a front across an L plan's plot, its wing behind
  // beside empty space): the container is cut there first. Where none of
  // the first axis's cuts is along faces, the other axis is cut at those
  // of its cuts that are, each run of pieces between them one piece cut
  // again later: a courtyard is its front and back ranges and, between
  // them, its side ranges round the yard, even where the side ranges'
  // bays line up with each other across the yard (and the ranges' bays
  // with the side ranges' ends) so that either axis cuts through open
  // air. Leaves pieces_ as find_pieces(w, axes[i]) found them when it
  // does not cut.
  bool cut_along_faces_across(const Work& w, int i) {
    const int a = w.axes[static_cast<std::size_t>(i)];
    const int b = 1 - a;
    bool later = false;
    for (int j = i + 1; j < w.tries; ++j) later = later || w.axes[static_cast<std::size_t>(j)] == b;
    if (!later || w.lo[static_cast<std::size_t>(b)] == w.hi[static_cast<std::size_t>(b)]) return false;
    faces_right_across(w, a, b, across_);
    if (std::all_of(across_.begin(), across_.end(), [](bool f) { return f; })) return false;
    const bool a_has_none = std::none_of(across_.begin(), across_.end(), [](bool f) { return f; });
    if (find_pieces(w, b) && pieces_.size() > 1) {
      faces_right_across(w, b, a, across_);
      const std::size_t along = static_cast<std::size_t>(std::count(across_.begin(), across_.end(), true));
      if (along == across_.size()) {
        cut_along(w, b);
        return true;
      }
      if (a_has_none && along > 0) {
        std::vector<bool> joins(pieces_.size(), false);
        for (std::size_t c = 0; c < across_.size(); ++c) joins[c + 1] = !across_[c];
        if (compound_.size() != pieces_.size()) compound_.assign(pieces_.size(), kNone);
        join_pieces(joins);
        cut_along(w, b);
        return true;
      }
    }
    find_pieces(w, a);
    return false;
  }

  // A stack that narrows upwards twice over (a tiered tower: each tier
  // within the footprint of the one below, the second tier and the rest
  // both leaving empty space round them) is cut at its lowest tier only
  // (a tier: the storeys of one footprint, a wall and its eaves band): the
  // rest is one piece, whose empty space is peeled before it is cut
  // again, and so on up. Each tier then stands on the one below, inset in
  // it, as a person models a tiered tower (tiered(n) --> split(z){ rect |
  // inset(tiered(n - 1)) }), and merging sees one structure nested, not a
  // slab per tier each inset on its own in the whole footprint, which
  // varies into tiers wider than the ones they stand on (the thesis's
  // floating tiers, figure 12.10). Storeys of one footprint on a wider
  // base (a house on its slab) stay a plain stack: they narrow once.
  // Joins the pieces above the lowest tier into one when it applies.
  bool narrowing_stack(const Work& w) {
    if (pieces_.size() < 3) return false;
    // The x, y rank extents of each piece.
    constexpr Rank kMax = std::numeric_limits<Rank>::max();
    using Extent = std::array<std::array<Rank, 2>, 2>;
    std::vector<Extent> ext(pieces_.size(), Extent{{{kMax, 0}, {kMax, 0}}});
    const Event* events = events_[2].data();
    for (std::uint32_t i = w.begin; i < w.end; ++i) {
      const Event e = events[i];
      if ((e & 1u) == 0) continue;
      const std::uint32_t b = e >> 1;
      Extent& x = ext[target_[span_of_[b]]];
      for (std::size_t a = 0; a < 2; ++a) {
        x[a][0] = std::min(x[a][0], lo_[a][b]);
        x[a][1] = std::max(x[a][1], hi_[a][b]);
      }
    }
    // A tier is a run of pieces of one footprint (a tier of a wall and its
    // eaves band is two pieces): the lowest tier, the second, and the rest.
    auto tier_end = [&](std::size_t from) {
      std::size_t to = from + 1;
      while (to < ext.size() && ext[to] == ext[from]) ++to;
      return to;
    };
    const std::size_t second = tier_end(0), rest = second < ext.size() ? tier_end(second) : ext.size();
    if (second >= ext.size()) return false;
    auto hull = [&](std::size_t from, std::size_t to) {
      Extent h = ext[from];
      for (std::size_t p = from + 1; p < to; ++p)
        for (std::size_t a = 0; a < 2; ++a) {
          h[a][0] = std::min(h[a][0], ext[p][a][0]);
          h[a][1] = std::max(h[a][1], ext[p][a][1]);
        }
      return h;
    };
    // inner stands within outer, and strictly inside within's bounds somewhere.
    auto inset = [](const Extent& inner, const Extent& outer, const std::array<Rank, 3>& lo,
                    const std::array<Rank, 3>& hi) {
      bool strictly = false;
      for (std::size_t a = 0; a < 2; ++a) {
        if (inner[a][0] < outer[a][0] || inner[a][1] > outer[a][1]) return false;
        strictly = strictly || inner[a][0] > lo[a] || inner[a][1] < hi[a];
      }
      return strictly;
    };
    const Extent& second_ext = ext[second];
    const std::array<Rank, 3> second_lo{second_ext[0][0], second_ext[1][0], 0},
        second_hi{second_ext[0][1], second_ext[1][1], 0};
    // Inside a stack found narrowing (the rest of one: peel_first), the
    // last two tiers narrow only once and are still tiers: the top tier of
    // a pagoda nests like every other.
    const bool narrows_again =
        rest < ext.size() ? inset(hull(rest, ext.size()), second_ext, second_lo, second_hi) : w.peel_first;
    if (!narrows_again || !inset(hull(second, ext.size()), ext[0], w.lo, w.hi)) return false;
    std::vector<bool> joins(pieces_.size(), false);
    for (std::size_t p = second + 1; p < pieces_.size(); ++p) joins[p] = true;
    compound_.assign(pieces_.size(), kNone);
    join_pieces(joins);
    // The rest is peeled first (Peel::Upper), not cut again as a run.
    compound_.assign(pieces_.size(), kNone);
    return true;
  }

  // The axes a piece of a cut along a tries: not a again (it was swept),
  // the other horizontal axis before z. Plots are laid out before they are
  // built up: a block with one tall tower is cut into its rows of
  // buildings, not into a slab of all its low buildings under the tower's
  // upper storeys.
  static std::array<int, 3> axes_after(int a) {
    if (a == 0) return {1, 2, 0};
    if (a == 1) return {0, 2, 1};
    return {0, 1, 2};
  }

  // One sweep along axis a over the container's bounds (9.1.3, boxesToOp):
  // finds the pieces a cut along a would make (pieces_, and which piece each
  // box falls in), or returns false when no cut along a divides it.
  bool find_pieces(const Work& w, int a) {
    const auto ax = static_cast<std::size_t>(a);
    // The counter of open boxes: a piece starts at a min bound when nothing
    // is open and ends where the counter next returns to zero; each box
    // belongs to the piece its bounds fall in (addToChild). Without
    // branches: the counter is zero only before a min bound, and a box's
    // two bounds name the same piece.
    const std::uint32_t begin = w.begin, end = w.end;  // locals: the stores below may not alias them
    const Event* events = events_[ax].data();
    std::uint32_t* span_of = span_of_.data();
    std::uint32_t* starts = starts_.data();  // room for every event, allocated once
    std::uint32_t span_count = 0, unmatched = 0;
    for (std::uint32_t i = begin; i < end; ++i) {
      const Event e = events[i];
      starts[span_count] = i;
      span_count += unmatched == 0 ? 1u : 0u;
      unmatched += 1u - 2u * (e & 1u);  // wraps to -1 and back: unsigned arithmetic
      span_of[e >> 1] = span_count - 1;
    }
    starts[span_count] = end;

    // Each piece's ranks are its first and last bounds' (the events are in
    // rank order, and a piece ends on a max bound). Its coordinates there:
    // the smallest min bound at its first rank, the largest max bound at
    // its last (and its first bound's, for a piece of zero length).
    spans_.resize(span_count);
    const std::vector<double>& rank_value = rank_value_[ax];
    for (std::size_t s = 0; s < span_count; ++s) {
      const std::uint32_t from = starts[s], to = starts[s + 1];
      Span& span = spans_[s];
      span.lo = rank_of(ax, events[from]);
      span.hi = rank_of(ax, events[to - 1]);
      span.count = (to - from) / 2;
      span.lo_val = rank_value[span.lo];
      if (std::isnan(span.lo_val)) {
        span.lo_val = value_of(ax, events[from]);
        for (std::uint32_t i = from + 1; i < to && rank_of(ax, events[i]) == span.lo; ++i)
          if ((events[i] & 1u) == 0) span.lo_val = std::min(span.lo_val, value_of(ax, events[i]));
      }
      span.hi_val = rank_value[span.hi];
      if (std::isnan(span.hi_val)) {
        span.hi_val = span.hi == span.lo ? value_of(ax, events[from]) : -std::numeric_limits<double>::infinity();
        for (std::uint32_t i = to; i > from && rank_of(ax, events[i - 1]) == span.hi; --i)
          if ((events[i - 1] & 1u) != 0) span.hi_val = std::max(span.hi_val, value_of(ax, events[i - 1]));
      }
    }

    // A piece of zero length (flat boxes only) joins the piece before it,
    // or the one after it when it comes first.
    pieces_.clear();
    target_.resize(spans_.size());
    for (std::size_t s = 0; s < spans_.size(); ++s) {
      const Span& span = spans_[s];
      if (!pieces_.empty() && (span.lo == span.hi || pieces_.back().lo == pieces_.back().hi)) {
        pieces_.back().absorb(span);
      } else {
        pieces_.push_back(span);
      }
      target_[s] = static_cast<std::uint32_t>(pieces_.size() - 1);
    }
    if (pieces_.size() == 1 &&
        ((pieces_[0].lo == w.lo[ax] && pieces_[0].hi == w.hi[ax]) || pieces_[0].lo == pieces_[0].hi)) {
      return false;
    }
    group_touching_pieces();
    group_set_back_pieces(w, a);
    return true;
  }

  // Empty space is what separates buildings; parts that touch make one
  // thing. Where a sweep finds both gaps and pieces that touch (a column
  // of a city: blocks of touching rows of buildings between streets), it
  // cuts at the gaps only, and each run of touching pieces is one piece,
  // cut again later (along the other axes first, then this one). So a
  // block is always a block, whether or not its strips of buildings
  // happen to line up into rows across it.
  void group_touching_pieces() {
    compound_.assign(pieces_.size(), kNone);
    bool gap = false, touch = false;
    for (std::size_t i = 0; i + 1 < pieces_.size(); ++i) (pieces_[i].hi == pieces_[i + 1].lo ? touch : gap) = true;
    if (!gap || !touch) return;
    std::vector<std::uint32_t> into(pieces_.size());
    std::size_t kept = 0;
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
      if (i > 0 && pieces_[kept - 1].hi == pieces_[i].lo) {
        pieces_[kept - 1].absorb(pieces_[i]);
        compound_[kept - 1] = kBuildings;
      } else {
        pieces_[kept] = pieces_[i];
        compound_[kept] = kNone;
        ++kept;
      }
      into[i] = static_cast<std::uint32_t>(kept - 1);
    }
    pieces_.resize(kept);
    compound_.resize(kept);
    for (std::uint32_t& t : target_) t = into[t];
  }

  // Pieces set back together: a run of neighbouring pieces along a
  // horizontal axis whose parts all start (or all end) at one place along
  // the other horizontal axis, inside the container, where their
  // neighbours reach further (a house behind its front yard between two
  // wings right across the plot). The run is one piece, cut again later,
  // along the other axis first: its yard is one empty part, not a strip
  // beside each of its bays.
  void group_set_back_pieces(const Work& w, int a) {
    if (a == 2 || pieces_.size() < 3) return;
    const auto b = static_cast<std::size_t>(1 - a);
    const std::size_t n = pieces_.size();
    std::vector<Rank> lo(n, std::numeric_limits<Rank>::max()), hi(n, 0);
    const Event* events = events_[static_cast<std::size_t>(a)].data();
    for (std::uint32_t i = w.begin; i < w.end; ++i) {
      const Event e = events[i];
      if ((e & 1u) != 0) continue;
      const std::uint32_t box = e >> 1;
      const std::uint32_t p = target_[span_of_[box]];
      lo[p] = std::min(lo[p], lo_[b][box]);
      hi[p] = std::max(hi[p], hi_[b][box]);
    }
    auto set_back = [&](std::size_t p) { return lo[p] > w.lo[b] || hi[p] < w.hi[b]; };
    // A piece joins the run before it when set back alike and touching it.
    std::vector<bool> joins(n, false);
    std::size_t kept = n;
    for (std::size_t i = 1; i < n; ++i) {
      joins[i] = set_back(i) && lo[i] == lo[i - 1] && hi[i] == hi[i - 1] && pieces_[i - 1].hi == pieces_[i].lo;
      kept -= joins[i] ? 1 : 0;
    }
    // Nothing joined, or everything (a peel of the whole container, which
    // uniform_peel takes where it is the only cut).
    if (kept == n || kept == 1) return;
    join_pieces(joins);
  }

  // Joins each piece whose joins[i] is set into the one before it: one
  // piece, cut again later (compound_), along the other axes first.
  void join_pieces(const std::vector<bool>& joins) {
    const std::size_t n = pieces_.size();
    std::vector<std::uint32_t> into(n);
    std::size_t kept = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (joins[i]) {
        pieces_[kept - 1].absorb(pieces_[i]);
        compound_[kept - 1] = kRun;
      } else {
        pieces_[kept] = pieces_[i];
        compound_[kept] = compound_[i];
        ++kept;
      }
      into[i] = static_cast<std::uint32_t>(kept - 1);
    }
    pieces_.resize(kept);
    compound_.resize(kept);
    for (std::uint32_t& t : target_) t = into[t];
  }

  // Which pieces of a cut peel their empty space first (Work::peel_first).
  enum class Peel { None, Upper, KeepPeeling };

  // Cuts the container into the pieces find_pieces(w, a) found last.
  void cut_along(const Work& w, int a, Peel peel = Peel::None) {
    const auto ax = static_cast<std::size_t>(a);
    const std::uint32_t begin = w.begin, end = w.end;
    const std::uint32_t* span_of = span_of_.data();

    // Pieces meeting at a rank share one cut, at the smallest of their
    // coordinates there; pieces at the container's ends keep its bounds.
    for (std::size_t i = 0; i + 1 < pieces_.size(); ++i) {
      if (pieces_[i].hi == pieces_[i + 1].lo) {
        pieces_[i].hi_val = pieces_[i + 1].lo_val = std::min(pieces_[i].hi_val, pieces_[i + 1].lo_val);
      }
    }
    if (pieces_.front().lo == w.lo[ax]) pieces_.front().lo_val = w.lo_val[ax];
    if (pieces_.back().hi == w.hi[ax]) pieces_.back().hi_val = w.hi_val[ax];

    // Each piece's segment: along a the events already come piece by piece
    // (a piece ends where the counter returns to zero); the other axes'
    // events are regrouped, stably, so each segment stays sorted.
    offsets_.resize(pieces_.size() + 1);
    offsets_[0] = w.begin;
    for (std::size_t p = 0; p < pieces_.size(); ++p) offsets_[p + 1] = offsets_[p] + 2 * pieces_[p].count;
    // Both axes in one loop: two independent chains of counter updates.
    const std::uint32_t* target = target_.data();
    const std::size_t o1 = (ax + 1) % 3, o2 = (ax + 2) % 3;
    Event* from1 = events_[o1].data();
    Event* from2 = events_[o2].data();
    Event* to1 = scratch_.data();
    Event* to2 = scratch2_.data();
    next_.assign(offsets_.begin(), offsets_.end() - 1);
    next2_.assign(offsets_.begin(), offsets_.end() - 1);
    std::uint32_t* next1 = next_.data();
    std::uint32_t* next2 = next2_.data();
    if (pieces_.size() == spans_.size()) {  // no piece joined another: span = piece
      for (std::uint32_t i = begin; i < end; ++i) {
        const Event e1 = from1[i];
        const Event e2 = from2[i];
        to1[next1[span_of[e1 >> 1]]++] = e1;
        to2[next2[span_of[e2 >> 1]]++] = e2;
      }
    } else {
      for (std::uint32_t i = begin; i < end; ++i) {
        const Event e1 = from1[i];
        const Event e2 = from2[i];
        to1[next1[target[span_of[e1 >> 1]]]++] = e1;
        to2[next2[target[span_of[e2 >> 1]]]++] = e2;
      }
    }
    std::memcpy(from1 + begin, to1 + begin, sizeof(Event) * (end - begin));
    std::memcpy(from2 + begin, to2 + begin, sizeof(Event) * (end - begin));

    // The node: pieces in order, with empty space before, between and
    // after them (toOp).
    SplitTree& node = *w.node;
    set_extent(node, w.lo_val, w.hi_val);
    node.kind = SplitTree::Kind::Split;
    node.axis = a;
    std::size_t children = pieces_.size();
    Rank previous = w.lo[ax];
    for (const Span& p : pieces_) {
      if (p.lo > previous) ++children;
      previous = p.hi;
    }
    if (previous < w.hi[ax]) ++children;
    node.children.resize(children);

    std::size_t at = 0;
    previous = w.lo[ax];
    double previous_val = w.lo_val[ax];
    auto gap = [&](double from_val, double to_val) {
      std::array<double, 3> lo = w.lo_val, hi = w.hi_val;
      lo[ax] = from_val;
      hi[ax] = to_val;
      set_extent(node.children[at++], lo, hi);  // Kind::Empty
    };
    const std::size_t first_work = stack_.size();
    for (std::size_t p = 0; p < pieces_.size(); ++p) {
      const Span& piece = pieces_[p];
      if (piece.lo > previous) gap(previous_val, piece.lo_val);
      Work child = w;
      child.node = &node.children[at++];
      child.begin = offsets_[p];
      child.end = offsets_[p + 1];
      child.lo[ax] = piece.lo;
      child.hi[ax] = piece.hi;
      child.lo_val[ax] = piece.lo_val;
      child.hi_val[ax] = piece.hi_val;
      child.axes = axes_after(a);
      child.tries = compound_[p] != kNone ? 3 : 2;  // a run of pieces is cut along a again, last
      // Touching buildings are cut into buildings before storeys: two
      // lodges side by side are two lodges, not a band of their walls
      // under a band of their roofs (whose party wall then lines up only
      // by chance, in each band on its own).
      if (compound_[p] == kBuildings && a != 2) child.axes = {1 - a, a, 2};
      child.peel_first = peel == Peel::KeepPeeling || (peel == Peel::Upper && p + 1 == pieces_.size());
      stack_.push_back(child);
      previous = piece.hi;
      previous_val = piece.hi_val;
    }
    if (previous < w.hi[ax]) gap(previous_val, w.hi_val[ax]);
    // First piece on top: depth first, in order.
    std::reverse(stack_.begin() + static_cast<std::ptrdiff_t>(first_work), stack_.end());
  }

  // No straight cut divides the container: its boxes, in index order.
  // Is the box flat on some axis, at the container's end along it (on one
  // of its faces)?
  bool on_face(const Work& w, std::uint32_t box) const {
    for (std::size_t a = 0; a < 3; ++a)
      if (lo_[a][box] == hi_[a][box] && (lo_[a][box] == w.lo[a] || lo_[a][box] == w.hi[a])) return true;
    return false;
  }

  // The container's boxes, by index.
  std::vector<std::uint32_t> boxes_in(const Work& w) const {
    std::vector<std::uint32_t> group;
    for (std::uint32_t i = w.begin; i < w.end; ++i) {
      const std::uint32_t e = events_[0][i];
      if ((e & 1u) == 0) group.push_back(e >> 1);
    }
    std::sort(group.begin(), group.end());
    return group;
  }

  // Is the container a mass model's faces (comp_faces.hpp)? Then it is
  // written so. Tried only where it could be: a container thick on every
  // axis whose boxes all lie flat on its faces (a facade's container is
  // flat itself, and a building's first solid part ends the look).
  bool faces_of_mass(const Work& w) {
    if (!any_flat_) return false;
    for (std::size_t a = 0; a < 3; ++a)
      if (w.lo[a] == w.hi[a]) return false;
    if (w.end - w.begin < 4) return false;
    // Every box flat on one of the container's faces, by rank, before
    // anything is gathered: most containers fail at their first box.
    for (std::uint32_t i = w.begin; i < w.end; ++i) {
      const Event e = events_[0][i];
      if ((e & 1u) == 0 && !on_face(w, e >> 1)) return false;
    }
    SplitTree& node = *w.node;
    set_extent(node, w.lo_val, w.hi_val);
    const auto faces = comp_faces(boxes_, boxes_in(w), node.min, node.max, tolerance_);
    if (!faces) return false;
    comp(node, *faces);
    return true;
  }

  void unsplittable(const Work& w) {
    const std::vector<std::uint32_t> group = boxes_in(w);
    SplitTree& node = *w.node;
    set_extent(node, w.lo_val, w.hi_val);
    node.kind = SplitTree::Kind::Unsplittable;
    node.children.resize(group.size());
    for (std::size_t i = 0; i < group.size(); ++i) {
      SplitTree& leaf = node.children[i];
      leaf.min = boxes_[group[i]].min;
      leaf.max = boxes_[group[i]].max;
      leaf.kind = SplitTree::Kind::Leaf;
      leaf.box = group[i];
    }
    if (group.size() >= 2) groups_.push_back(std::move(group));
  }

  // A mass model's faces (comp_faces.hpp): each face's parts split in its
  // own frame, as a facade on its own would be, their leaves naming the
  // parts by their index here.
  void comp(SplitTree& node, const std::vector<FaceParts>& faces) const {
    node.kind = SplitTree::Kind::Comp;
    for (const FaceParts& f : faces) {
      SplitTree face = split_boxes(f.local, BoxSplitOptions{tolerance_}, source_);
      renumber(face, f.boxes);
      face.min = glm::dvec3(0.0);
      face.max = f.size;
      node.children.push_back(std::move(face));
      node.faces.push_back(f.face);
    }
  }

  // Without recursion: a face's tree may be as deep as a building's.
  static void renumber(SplitTree& t, const std::vector<std::uint32_t>& index) {
    std::vector<SplitTree*> stack{&t};
    while (!stack.empty()) {
      SplitTree* n = stack.back();
      stack.pop_back();
      if (n->kind == SplitTree::Kind::Leaf) n->box = index[n->box];
      for (SplitTree& c : n->children) stack.push_back(&c);
    }
  }

  // Overlapping boxes share an unsplittable container; look for them there.
  void check_overlaps() const {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for (const auto& group : groups_) overlaps_in(group, pairs);
    if (pairs.empty()) return;
    const std::size_t count = pairs.size();
    const auto first = *std::min_element(pairs.begin(), pairs.end());
    const LabelledBox& a = boxes_[first.first];
    const LabelledBox& b = boxes_[first.second];
    std::string message = describe_overlap(a, b);
    if (count > 1) message += "; " + std::to_string(count - 1) + " more pair" + (count > 2 ? "s" : "") + " overlap";
    fail_at(a, message,
            loose_pieces_hint(a, b).value_or("inference needs non-overlapping parts; separate or merge these objects"));
  }

  // The insides of boxes along an axis as half-open integer intervals:
  // a solid box [lo, hi] becomes [4 lo + 1, 4 hi - 1), a flat one at r
  // [4 r - 1, 4 r + 1). Two intervals intersect exactly when two solid
  // boxes share more than a face, a flat box lies strictly inside a solid
  // one, or two flat boxes lie at the same rank.
  std::array<std::int64_t, 2> inside(std::uint32_t b, std::size_t a) const {
    const auto l = static_cast<std::int64_t>(lo_[a][b]);
    const auto h = static_cast<std::int64_t>(hi_[a][b]);
    if (l == h) return {4 * l - 1, 4 * l + 1};
    return {4 * l + 1, 4 * h - 1};
  }

  // Sweep and prune along x among a group's boxes.
  void overlaps_in(std::vector<std::uint32_t> group, std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs) const {
    std::sort(group.begin(), group.end(), [&](std::uint32_t p, std::uint32_t q) {
      const auto ip = inside(p, 0), iq = inside(q, 0);
      return ip[0] != iq[0] ? ip[0] < iq[0] : p < q;
    });
    std::vector<std::uint32_t> open;
    for (std::uint32_t b : group) {
      const std::int64_t start = inside(b, 0)[0];
      std::erase_if(open, [&](std::uint32_t o) { return inside(o, 0)[1] <= start; });
      for (std::uint32_t o : open) {
        bool meet = true;
        for (std::size_t a = 1; a < 3 && meet; ++a) {
          const auto ib = inside(b, a), io = inside(o, a);
          meet = std::max(ib[0], io[0]) < std::min(ib[1], io[1]);
        }
        if (!meet) continue;
        pairs.emplace_back(std::min(b, o), std::max(b, o));
      }
      open.push_back(b);
    }
  }

  [[noreturn]] void fail_at(const LabelledBox& box, const std::string& message, const std::string& hint) const {
    fail(ErrorKind::Input, source_, {box.line, box.line != 0 ? 1u : 0u}, message, hint);
  }

  static void set_extent(SplitTree& t, const std::array<double, 3>& lo, const std::array<double, 3>& hi) {
    t.min = glm::dvec3(lo[0], lo[1], lo[2]);
    t.max = glm::dvec3(hi[0], hi[1], hi[2]);
  }

  const std::vector<LabelledBox>& boxes_;
  const std::string& source_;
  double tolerance_;  // metres: what snapping joins
  bool any_flat_ = false;  // some box is flat on some axis: a mass's faces are possible
  std::array<std::vector<Rank>, 3> lo_, hi_;  // per axis, per box: ranks of its bounds
  std::array<Rank, 3> ranks_{};               // per axis: how many ranks
  std::array<double, 3> root_lo_{}, root_hi_{};  // the bounds of all boxes
  std::array<std::vector<Event>, 3> events_;  // per axis: each container's segment in sweep order
  std::array<std::vector<double>, 3> rank_value_;  // per axis, per rank: its one coordinate, or NaN
  std::vector<Event> scratch_, scratch2_;     // regrouping buffers, as long as an axis's events
  std::vector<std::uint32_t> span_of_;        // per box: its piece in the current sweep
  std::vector<double> fill_;                  // storeys_first's piece fills (reused)
  std::vector<std::uint64_t> faces_;          // cuts_line_up_by_chance's (piece, rank) pairs (reused)
  std::vector<std::array<std::vector<std::pair<Rank, Rank>>, 2>> cut_faces_;  // cuts_along_faces's (reused)
  std::vector<bool> across_;  // faces_right_across's answer (reused)
  std::vector<Rank> cut_ranks_;  // storeys_first: the ranks of the cuts along a horizontal axis it weighs, ascending
  bool alike_pieces_ = false;    // storeys_first: whether those cuts make pieces of one length
  std::vector<double> pieces_fill_;  // storeys_first: the fills of its sweep's pieces along a horizontal axis
  std::vector<Work> stack_;                   // containers still to cut
  std::vector<std::vector<std::uint32_t>> groups_;  // unsplittable containers' boxes
  std::vector<std::pair<std::uint32_t, std::uint32_t>>* overlaps_ = nullptr;  // collect_overlaps
  // The current sweep's pieces (reused: nothing is allocated per container).
  std::vector<Span> spans_, pieces_;
  // Per piece: kNone, or a run of pieces joined to be cut again later:
  // kRun (along the other axes first, then this one), kBuildings (touching
  // buildings, group_touching_pieces: the other horizontal axis, then this
  // one, then z).
  enum Compound : std::uint8_t { kNone, kRun, kBuildings };
  std::vector<Compound> compound_;
  std::vector<std::uint32_t> starts_, target_, offsets_, next_, next2_;
};

void count(const SplitTree& t, std::size_t depth, SplitTreeStats& s) {
  s.depth = std::max(s.depth, depth);
  switch (t.kind) {
    case SplitTree::Kind::Leaf: ++s.leaves; break;
    case SplitTree::Kind::Empty: ++s.empties; break;
    case SplitTree::Kind::Split: ++s.splits; break;
    case SplitTree::Kind::Unsplittable: ++s.unsplittable; break;
    case SplitTree::Kind::Comp: ++s.splits; break;
  }
  for (const SplitTree& c : t.children) count(c, depth + 1, s);
}

}  // namespace

SplitTree split_boxes(const std::vector<LabelledBox>& boxes, const BoxSplitOptions& options,
                      const std::string& source, std::vector<std::pair<std::uint32_t, std::uint32_t>>* overlaps) {
  if (overlaps) overlaps->clear();
  if (boxes.empty()) return {};
  if (boxes.size() >= (std::size_t{1} << 29)) {
    fail(ErrorKind::Limit, source, {}, "too many parts to split (" + std::to_string(boxes.size()) + ")",
         "split the example into smaller buildings");
  }
  Splitter splitter(boxes, std::max(0.0, options.tolerance), source);
  splitter.collect_overlaps(overlaps);
  return splitter.run();
}

std::string describe_overlap(const LabelledBox& a, const LabelledBox& b) {
  std::string by;
  for (int i = 0; i < 3; ++i) {
    const double o = std::max(0.0, std::min(a.max[i], b.max[i]) - std::max(a.min[i], b.min[i]));
    by += (i == 0 ? "" : " x ") + amount(o);
  }
  return "objects " + describe_object(a) + " and " + describe_object(b) + " overlap by " + by + " (along x, y, z)";
}

std::optional<std::string> loose_pieces_hint(const LabelledBox& a, const LabelledBox& b) {
  for (const LabelledBox* box : {&a, &b})
    if (box->loose_pieces > 1)
      return describe_object(*box) + " is " + std::to_string(box->loose_pieces) +
             " loose pieces in one object: make each its own object (Blender: Edit Mode, Mesh > Separate > "
             "By Loose Parts), then export again";
  return std::nullopt;
}

SplitTreeStats split_tree_stats(const SplitTree& tree) {
  SplitTreeStats s;
  count(tree, 1, s);
  return s;
}

}  // namespace vern
