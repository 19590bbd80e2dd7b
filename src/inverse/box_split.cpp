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
// What this file adds to the thesis:
//   - Snapping: per axis, the sorted coordinates fall into runs whose
//     neighbours lie within the tolerance; each run is one rank. Every
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
//   - Termination: a container that no sweep along any of the three axes
//     divides is final (Kind::Unsplittable), so a pinwheel neither loops nor
//     crashes.
//   - Overlaps are found where they must show up: two boxes whose insides
//     intersect can never be cut apart, so they end in the same
//     unsplittable container. Only those containers are searched (sweep
//     and prune on x), so a valid example pays nothing for the check.
#include "inverse/box_split.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <limits>

#include "graph/error.hpp"

namespace vern {

namespace {

using Rank = std::uint32_t;
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

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

// A bound in an axis's sweep order, carrying what the sweep reads so that
// the sweep streams through memory instead of chasing boxes.
struct Event {
  std::uint32_t box_close = 0;  // box << 1 | (1 for a max bound)
  Rank rank = 0;
  double value = 0;  // the coordinate
};

enum class State : std::uint8_t { Active, Leaf, Split, Unsplittable };

struct Container {
  std::array<Rank, 3> lo{}, hi{};
  std::array<double, 3> lo_val{}, hi_val{};  // the extent's coordinates
  State state = State::Active;
  int axis = -1;
  std::uint8_t fails = 0;                // consecutive sweeps that did not divide it
  std::vector<std::uint32_t> boxes;      // while Active, and when final: its boxes
  std::vector<std::uint32_t> children;   // Split: child containers in order
  // The current sweep's state.
  std::uint32_t pass = kNone;
  std::uint32_t unmatched = 0;
  std::vector<Span> spans;
};

std::string amount(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

class Splitter {
 public:
  Splitter(const std::vector<LabelledBox>& boxes, double tolerance, const std::string& source)
      : boxes_(boxes), source_(source), lo_(boxes.size()), hi_(boxes.size()), owner_(boxes.size(), 0),
        span_of_(boxes.size(), 0) {
    for (int a = 0; a < 3; ++a) rank_axis(a, tolerance);
  }

  SplitTree run() {
    // The root is the bounds of all boxes.
    Container root;
    for (std::size_t a = 0; a < 3; ++a) {
      root.lo[a] = 0;
      root.hi[a] = ranks_[a] - 1;
      root.lo_val[a] = std::numeric_limits<double>::infinity();
      root.hi_val[a] = -std::numeric_limits<double>::infinity();
      for (const LabelledBox& b : boxes_) {
        root.lo_val[a] = std::min(root.lo_val[a], b.min[static_cast<glm::length_t>(a)]);
        root.hi_val[a] = std::max(root.hi_val[a], b.max[static_cast<glm::length_t>(a)]);
      }
    }
    root.boxes.resize(boxes_.size());
    for (std::uint32_t b = 0; b < boxes_.size(); ++b) root.boxes[b] = b;
    containers_.push_back(std::move(root));
    active_ = 1;
    settle(0);

    // Each sweep divides or fails every active container, and a container
    // failing on all three axes is final, so this ends; the guard only
    // turns a broken invariant into an error instead of a hang.
    const std::uint64_t max_passes = 3 * (6 * static_cast<std::uint64_t>(boxes_.size()) + 4);
    for (std::uint32_t pass = 0; active_ > 0; ++pass) {
      if (pass > max_passes) {
        throw Error(ErrorKind::Internal, format_message(source_, {}, "box splitting did not finish (a bug)"));
      }
      sweep(static_cast<int>(pass % 3), pass);
    }
    check_overlaps();
    return build(0);
  }

 private:
  // Snaps and ranks the coordinates along axis a, and sorts the sweep events.
  void rank_axis(int a, double tolerance) {
    const auto ax = static_cast<std::size_t>(a);
    const std::size_t n = boxes_.size();
    std::vector<std::pair<double, std::uint32_t>> bounds;  // (coordinate, box << 1 | is_max)
    bounds.reserve(2 * n);
    for (std::uint32_t b = 0; b < n; ++b) {
      bounds.emplace_back(boxes_[b].min[a], b << 1);
      bounds.emplace_back(boxes_[b].max[a], (b << 1) | 1u);
    }
    std::sort(bounds.begin(), bounds.end());
    Rank ranks = 0;
    for (std::size_t i = 0; i < bounds.size(); ++i) {
      // A new rank starts where the gap to the previous coordinate exceeds
      // the tolerance: coordinates within tolerance of a neighbour share one.
      if (i == 0 || bounds[i].first - bounds[i - 1].first > tolerance) ++ranks;
      const Rank rank = ranks - 1;
      const std::uint32_t b = bounds[i].second >> 1;
      ((bounds[i].second & 1u) != 0 ? hi_[b] : lo_[b])[ax] = rank;
    }
    ranks_[ax] = ranks;

    std::vector<std::uint64_t> keys;
    keys.reserve(2 * n);
    for (std::uint32_t b = 0; b < n; ++b) {
      const bool flat = lo_[b][ax] == hi_[b][ax];
      keys.push_back(key(lo_[b][ax], flat ? kOpenFlat : kOpenSolid, b));
      keys.push_back(key(hi_[b][ax], flat ? kCloseFlat : kCloseSolid, b));
    }
    std::sort(keys.begin(), keys.end());
    std::vector<Event>& events = events_[ax];
    events.reserve(keys.size());
    for (std::uint64_t k : keys) {
      const std::uint64_t order = (k >> 32) & 3u;
      const bool close = order == kCloseSolid || order == kCloseFlat;
      const auto b = static_cast<std::uint32_t>(k & 0xffffffffu);
      events.push_back({(b << 1) | (close ? 1u : 0u), static_cast<Rank>(k >> 34),
                        close ? boxes_[b].max[a] : boxes_[b].min[a]});
    }
  }

  static std::uint64_t key(Rank rank, std::uint64_t order, std::uint32_t box) {
    return (static_cast<std::uint64_t>(rank) << 34) | (order << 32) | box;
  }

  // One sweep along axis a over every active container (9.1.3, boxesToOp).
  void sweep(int a, std::uint32_t pass) {
    const auto ax = static_cast<std::size_t>(a);
    touched_.clear();
    std::vector<Event>& events = events_[ax];
    std::size_t keep = 0;
    for (std::size_t i = 0; i < events.size(); ++i) {
      const Event e = events[i];
      const std::uint32_t b = e.box_close >> 1;
      Container& c = containers_[owner_[b]];
      if (c.state != State::Active) continue;  // final: its events are dropped for good
      events[keep++] = e;
      if (c.pass != pass) {
        c.pass = pass;
        c.unmatched = 0;
        c.spans.clear();
        touched_.push_back(owner_[b]);
      }
      if (c.lo[ax] == c.hi[ax]) continue;  // flat along a: nothing to cut
      if ((e.box_close & 1u) == 0) {
        // A min bound: a new piece starts when nothing is open.
        if (c.unmatched == 0) {
          c.spans.push_back({e.rank, e.rank, e.value, e.value, 0});
        } else if (e.rank == c.spans.back().lo) {
          c.spans.back().lo_val = std::min(c.spans.back().lo_val, e.value);
        }
        ++c.unmatched;
      } else {
        // A max bound (addToChild): the box joins the current piece, which
        // can be cut off once no box is open.
        --c.unmatched;
        Span& s = c.spans.back();
        if (e.rank > s.hi) {
          s.hi = e.rank;
          s.hi_val = e.value;
        } else if (e.rank == s.hi) {
          s.hi_val = std::max(s.hi_val, e.value);
        }
        ++s.count;
        span_of_[b] = static_cast<std::uint32_t>(c.spans.size() - 1);
      }
    }
    events.resize(keep);
    for (std::uint32_t c : touched_) finish(c, a);
  }

  // After a sweep: cut the container into its pieces, or count a failure.
  void finish(std::uint32_t id, int a) {
    const auto ax = static_cast<std::size_t>(a);
    Container& c = containers_[id];
    if (c.lo[ax] == c.hi[ax]) return no_cut(id);

    // A piece of zero length (flat boxes only) joins the piece before it,
    // or the one after it when it comes first.
    std::vector<Span> pieces;
    std::vector<std::uint32_t> target(c.spans.size());
    for (std::size_t s = 0; s < c.spans.size(); ++s) {
      const Span& span = c.spans[s];
      if (!pieces.empty() && (span.lo == span.hi || pieces.back().lo == pieces.back().hi)) {
        pieces.back().absorb(span);
      } else {
        pieces.push_back(span);
      }
      target[s] = static_cast<std::uint32_t>(pieces.size() - 1);
    }
    c.spans = {};
    if (pieces.size() == 1 &&
        ((pieces[0].lo == c.lo[ax] && pieces[0].hi == c.hi[ax]) || pieces[0].lo == pieces[0].hi)) {
      return no_cut(id);
    }

    c.state = State::Split;
    c.axis = a;
    // Pieces meeting at a rank share one cut, at the smallest of their
    // coordinates there; pieces at the container's ends keep its bounds.
    for (std::size_t i = 0; i + 1 < pieces.size(); ++i) {
      if (pieces[i].hi == pieces[i + 1].lo) {
        pieces[i].hi_val = pieces[i + 1].lo_val = std::min(pieces[i].hi_val, pieces[i + 1].lo_val);
      }
    }
    if (pieces.front().lo == c.lo[ax]) pieces.front().lo_val = c.lo_val[ax];
    if (pieces.back().hi == c.hi[ax]) pieces.back().hi_val = c.hi_val[ax];

    std::vector<std::uint32_t> boxes = std::move(c.boxes);
    const Container shape = extent_of(c);
    std::vector<std::uint32_t> ids;
    ids.reserve(pieces.size());
    for (const Span& p : pieces) {
      Container child = shape;
      child.lo[ax] = p.lo;
      child.hi[ax] = p.hi;
      child.lo_val[ax] = p.lo_val;
      child.hi_val[ax] = p.hi_val;
      child.fails = 1;  // a piece cannot be cut again along a: this sweep would have
      child.boxes.reserve(p.count);
      ids.push_back(static_cast<std::uint32_t>(containers_.size()));
      containers_.push_back(std::move(child));  // invalidates c
    }
    for (std::uint32_t b : boxes) {
      const std::uint32_t child = ids[target[span_of_[b]]];
      containers_[child].boxes.push_back(b);
      owner_[b] = child;
    }
    --active_;
    active_ += ids.size();
    for (std::uint32_t child : ids) settle(child);
    containers_[id].children = std::move(ids);
  }

  // Only a container's extent (ranks and coordinates).
  static Container extent_of(const Container& c) {
    Container e;
    e.lo = c.lo;
    e.hi = c.hi;
    e.lo_val = c.lo_val;
    e.hi_val = c.hi_val;
    return e;
  }

  // The sweep did not divide the container; after three in a row, no axis can.
  void no_cut(std::uint32_t id) {
    Container& c = containers_[id];
    if (++c.fails >= 3) {
      c.state = State::Unsplittable;
      --active_;
    }
  }

  // A container holding one box that fills it is a leaf (a PrimContainer).
  void settle(std::uint32_t id) {
    Container& c = containers_[id];
    if (c.boxes.size() == 1 && lo_[c.boxes[0]] == c.lo && hi_[c.boxes[0]] == c.hi) {
      c.state = State::Leaf;
      --active_;
    }
  }

  // Overlapping boxes share an unsplittable container; look for them there.
  void check_overlaps() const {
    std::size_t count = 0;
    std::pair<std::uint32_t, std::uint32_t> first{kNone, kNone};
    for (const Container& c : containers_) {
      if (c.state != State::Unsplittable || c.boxes.size() < 2) continue;
      overlaps_in(c.boxes, count, first);
    }
    if (count == 0) return;
    const LabelledBox& a = boxes_[first.first];
    const LabelledBox& b = boxes_[first.second];
    std::string by;
    for (int i = 0; i < 3; ++i) {
      const double o = std::max(0.0, std::min(a.max[i], b.max[i]) - std::max(a.min[i], b.min[i]));
      by += (i == 0 ? "" : " x ") + amount(o);
    }
    std::string message = "objects " + describe_object(a) + " and " + describe_object(b) + " overlap by " + by +
                          " (along x, y, z)";
    if (count > 1) message += "; " + std::to_string(count - 1) + " more pair" + (count > 2 ? "s" : "") + " overlap";
    fail_at(a, message, "inference needs non-overlapping parts; separate or merge these objects");
  }

  // The insides of boxes along an axis as half-open integer intervals:
  // a solid box [lo, hi] becomes [4 lo + 1, 4 hi - 1), a flat one at r
  // [4 r - 1, 4 r + 1). Two intervals intersect exactly when two solid
  // boxes share more than a face, a flat box lies strictly inside a solid
  // one, or two flat boxes lie at the same rank.
  std::array<std::int64_t, 2> inside(std::uint32_t b, std::size_t a) const {
    const auto l = static_cast<std::int64_t>(lo_[b][a]);
    const auto h = static_cast<std::int64_t>(hi_[b][a]);
    if (l == h) return {4 * l - 1, 4 * l + 1};
    return {4 * l + 1, 4 * h - 1};
  }

  // Sweep and prune along x among a group's boxes.
  void overlaps_in(std::vector<std::uint32_t> group, std::size_t& count,
                   std::pair<std::uint32_t, std::uint32_t>& first) const {
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
        ++count;
        const std::pair<std::uint32_t, std::uint32_t> pair{std::min(b, o), std::max(b, o)};
        if (pair < first) first = pair;
      }
      open.push_back(b);
    }
  }

  [[noreturn]] void fail_at(const LabelledBox& box, const std::string& message, const std::string& hint) const {
    fail(ErrorKind::Input, source_, {box.line, box.line != 0 ? 1u : 0u}, message, hint);
  }

  SplitTree build(std::uint32_t id) const {
    const Container& c = containers_[id];
    SplitTree t = extent(c.lo_val, c.hi_val);
    switch (c.state) {
      case State::Leaf:
        t.kind = SplitTree::Kind::Leaf;
        t.box = c.boxes[0];
        break;
      case State::Unsplittable: {
        t.kind = SplitTree::Kind::Unsplittable;
        std::vector<std::uint32_t> boxes = c.boxes;
        std::sort(boxes.begin(), boxes.end());
        for (std::uint32_t b : boxes) {
          SplitTree leaf;
          leaf.min = boxes_[b].min;
          leaf.max = boxes_[b].max;
          leaf.kind = SplitTree::Kind::Leaf;
          leaf.box = b;
          t.children.push_back(std::move(leaf));
        }
        break;
      }
      case State::Split: {
        // Gaps before, between and after the pieces are empty space (toOp).
        t.kind = SplitTree::Kind::Split;
        t.axis = c.axis;
        const auto ax = static_cast<std::size_t>(c.axis);
        auto gap = [&](double from, double to) {
          std::array<double, 3> lo = c.lo_val, hi = c.hi_val;
          lo[ax] = from;
          hi[ax] = to;
          t.children.push_back(extent(lo, hi));  // Kind::Empty
        };
        Rank previous = c.lo[ax];
        double previous_val = c.lo_val[ax];
        for (std::uint32_t child : c.children) {
          const Container& k = containers_[child];
          if (k.lo[ax] > previous) gap(previous_val, k.lo_val[ax]);
          t.children.push_back(build(child));
          previous = k.hi[ax];
          previous_val = k.hi_val[ax];
        }
        if (previous < c.hi[ax]) gap(previous_val, c.hi_val[ax]);
        break;
      }
      case State::Active:
        throw Error(ErrorKind::Internal, format_message(source_, {}, "box splitting left a container unfinished (a bug)"));
    }
    return t;
  }

  static SplitTree extent(const std::array<double, 3>& lo, const std::array<double, 3>& hi) {
    SplitTree t;
    t.min = glm::dvec3(lo[0], lo[1], lo[2]);
    t.max = glm::dvec3(hi[0], hi[1], hi[2]);
    return t;
  }

  const std::vector<LabelledBox>& boxes_;
  const std::string& source_;
  std::vector<std::array<Rank, 3>> lo_, hi_;       // per box: ranks of its bounds
  std::array<Rank, 3> ranks_{};                    // per axis: how many ranks
  std::array<std::vector<Event>, 3> events_;       // per axis, in sweep order
  std::vector<std::uint32_t> owner_;    // per box: its smallest container
  std::vector<std::uint32_t> span_of_;  // per box: its piece in the current sweep
  std::vector<Container> containers_;
  std::vector<std::uint32_t> touched_;
  std::size_t active_ = 0;
};

void count(const SplitTree& t, std::size_t depth, SplitTreeStats& s) {
  s.depth = std::max(s.depth, depth);
  switch (t.kind) {
    case SplitTree::Kind::Leaf: ++s.leaves; break;
    case SplitTree::Kind::Empty: ++s.empties; break;
    case SplitTree::Kind::Split: ++s.splits; break;
    case SplitTree::Kind::Unsplittable: ++s.unsplittable; break;
  }
  for (const SplitTree& c : t.children) count(c, depth + 1, s);
}

}  // namespace

SplitTree split_boxes(const std::vector<LabelledBox>& boxes, const BoxSplitOptions& options,
                      const std::string& source) {
  if (boxes.empty()) return {};
  if (boxes.size() >= (std::size_t{1} << 29)) {
    fail(ErrorKind::Limit, source, {}, "too many parts to split (" + std::to_string(boxes.size()) + ")",
         "split the example into smaller buildings");
  }
  for (const LabelledBox& b : boxes) {
    for (int a = 0; a < 3; ++a) {
      if (!(b.min[a] <= b.max[a])) {  // also catches NaN
        fail(ErrorKind::Input, source, {b.line, b.line != 0 ? 1u : 0u},
             "object " + describe_object(b) + " has a box whose minimum exceeds its maximum (or is not a number)",
             "give each part real geometry");
      }
    }
  }
  return Splitter(boxes, std::max(0.0, options.tolerance), source).run();
}

SplitTreeStats split_tree_stats(const SplitTree& tree) {
  SplitTreeStats s;
  count(tree, 1, s);
  return s;
}

}  // namespace vern
