#include "inverse/load/layered_parts.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <queue>
#include <unordered_map>
#include <unordered_set>

#include "base/error.hpp"
#include "inverse/split/box_split.hpp"

namespace vern {

namespace {

struct Box {
  glm::dvec3 min{0.0}, max{0.0};
};

Box box_of(const LabelledBox& b) { return {b.min, b.max}; }

bool flat(const Box& b, int axis, double tol) { return b.max[axis] - b.min[axis] <= tol; }

// Does `outer` hold `inner`, within tol on every axis?
bool holds(const LabelledBox& outer, const LabelledBox& inner, double tol) {
  for (int a = 0; a < 3; ++a)
    if (inner.min[a] < outer.min[a] - tol || inner.max[a] > outer.max[a] + tol) return false;
  return true;
}

// What of `hole` lies inside `region`: on an axis where the region is flat
// the hole must reach its plane, on the others they must share more than
// the tolerance. nullopt when nothing does.
std::optional<Box> clipped(const Box& hole, const Box& region, double tol) {
  Box c;
  for (int a = 0; a < 3; ++a) {
    c.min[a] = std::max(hole.min[a], region.min[a]);
    c.max[a] = std::min(hole.max[a], region.max[a]);
    if (flat(region, a, tol)) {
      if (c.max[a] < c.min[a] - tol) return std::nullopt;
      c.min[a] = region.min[a];
      c.max[a] = region.max[a];
    } else if (c.max[a] - c.min[a] <= tol) {
      return std::nullopt;
    }
  }
  return c;
}

// Sorted values, each run within tol of the one before kept as its first.
std::vector<double> distinct(std::vector<double> v, double tol) {
  std::sort(v.begin(), v.end());
  std::vector<double> out;
  for (const double x : v)
    if (out.empty() || x > out.back() + tol) out.push_back(x);
  return out;
}

// Where no straight cut divides the region cleanly: the grid of the
// holes' bounds, each cell outside every hole kept, runs of them along x
// joined.
void tile_by_grid(const Box& region, const std::vector<Box>& holes, double tol, std::vector<Box>& out) {
  std::array<std::vector<double>, 3> lines;
  for (int a = 0; a < 3; ++a) {
    std::vector<double> v{region.min[a], region.max[a]};
    if (!flat(region, a, tol))
      for (const Box& h : holes)
        for (const double x : {h.min[a], h.max[a]})
          if (x > region.min[a] + tol && x < region.max[a] - tol) v.push_back(x);
    lines[a] = distinct(std::move(v), tol);
    lines[a].back() = region.max[a];
  }
  auto covered = [&](const glm::dvec3& centre) {
    return std::any_of(holes.begin(), holes.end(), [&](const Box& h) {
      for (int a = 0; a < 3; ++a)
        if (centre[a] < h.min[a] - tol || centre[a] > h.max[a] + tol) return false;
      return true;
    });
  };
  for (std::size_t k = 0; k + 1 < lines[2].size(); ++k)
    for (std::size_t j = 0; j + 1 < lines[1].size(); ++j) {
      std::optional<Box> run;
      for (std::size_t i = 0; i + 1 < lines[0].size(); ++i) {
        const Box cell{{lines[0][i], lines[1][j], lines[2][k]}, {lines[0][i + 1], lines[1][j + 1], lines[2][k + 1]}};
        if (covered((cell.min + cell.max) * 0.5)) {
          if (run) out.push_back(*run);
          run.reset();
        } else if (run) {
          run->max.x = cell.max.x;
        } else {
          run = cell;
        }
      }
      if (run) out.push_back(*run);
    }
}

// The positions along `axis` inside the region where the holes end and
// no hole crosses.
std::vector<double> clean_cuts(const Box& region, const std::vector<Box>& holes, int axis, double tol) {
  std::vector<double> cuts, clean;
  if (flat(region, axis, tol)) return clean;
  for (const Box& h : holes)
    for (const double x : {h.min[axis], h.max[axis]})
      if (x > region.min[axis] + tol && x < region.max[axis] - tol) cuts.push_back(x);
  for (const double c : distinct(std::move(cuts), tol))
    if (std::none_of(holes.begin(), holes.end(),
                     [&](const Box& h) { return h.min[axis] < c - tol && h.max[axis] > c + tol; }))
      clean.push_back(c);
  return clean;
}

// The region minus the holes (clipped to it, not overlapping each other),
// as boxes: cut on z, then along the horizontal axis with more places to
// cut (the row of windows, not the wall's depth behind them, whichever
// way the wall faces: a house and the same house turned a quarter keep
// pieces alike), then the other, at every position no hole crosses.
void tile(const Box& region, const std::vector<Box>& holes, double tol, std::vector<Box>& out) {
  if (holes.empty()) {
    out.push_back(region);
    return;
  }
  std::vector<double> along[3];
  for (int axis = 0; axis < 3; ++axis) along[axis] = clean_cuts(region, holes, axis, tol);
  const int first_horizontal = along[1].size() > along[0].size() ? 1 : 0;
  for (const int axis : {2, first_horizontal, 1 - first_horizontal}) {
    std::vector<double>& clean = along[axis];
    if (clean.empty()) continue;
    clean.push_back(region.max[axis]);
    double from = region.min[axis];
    for (const double to : clean) {
      Box band = region;
      band.min[axis] = from;
      band.max[axis] = to;
      std::vector<Box> inside;
      for (const Box& h : holes)
        if (auto c = clipped(h, band, tol)) inside.push_back(*c);
      tile(band, inside, tol, out);
      from = to;
    }
    return;
  }
  // No cut is clean: a hole covers the region, or the holes lie in a pinwheel.
  for (const Box& h : holes) {
    bool covers = true;
    for (int a = 0; a < 3 && covers; ++a) covers = h.min[a] <= region.min[a] + tol && h.max[a] >= region.max[a] - tol;
    if (covers) return;
  }
  tile_by_grid(region, holes, tol, out);
}

[[noreturn]] void fail_at(const Example& e, const LabelledBox& box, const std::string& message,
                          const std::string& hint) {
  fail(ErrorKind::Input, e.source, {box.line, box.line != 0 ? 1u : 0u}, message, hint);
}

}  // namespace

Example visible_parts(const Example& example, const std::vector<OverlapPair>& overlaps, const Layering& layering) {
  if (overlaps.empty()) return example;
  const double tol = layering.tolerance;
  const std::vector<LabelledBox>& boxes = example.boxes;
  const std::size_t n = boxes.size();
  std::unordered_map<std::string, int> rank;
  for (std::size_t i = 0; i < layering.stack.size(); ++i) rank.emplace(layering.stack[i], static_cast<int>(i));
  auto rank_of = [&](const LabelledBox& b) {
    const auto it = rank.find(b.label);
    return it == rank.end() ? -1 : it->second;
  };

  // Which of each pair is painted over the other.
  std::vector<std::vector<std::uint32_t>> above(n), below(n);
  std::size_t unordered = 0;
  std::optional<OverlapPair> first;
  for (const auto& [i, j] : overlaps) {
    const LabelledBox& a = boxes[i];
    const LabelledBox& b = boxes[j];
    const int ra = rank_of(a), rb = rank_of(b);
    std::uint32_t top = 0;
    if (ra >= 0 && rb >= 0 && ra != rb) {
      top = ra > rb ? i : j;
    } else {
      const bool b_in_a = holds(a, b, tol), a_in_b = holds(b, a, tol);
      if (b_in_a != a_in_b) {
        top = b_in_a ? j : i;
      } else if (ra >= 0 && ra == rb) {
        top = j;  // one listed label: painted in file order, as annotations are
      } else {
        ++unordered;
        if (!first) first = OverlapPair{i, j};
        continue;
      }
    }
    const std::uint32_t bottom = top == i ? j : i;
    above[bottom].push_back(top);
    below[top].push_back(bottom);
  }
  if (unordered > 0) {
    const LabelledBox& a = boxes[first->first];
    const LabelledBox& b = boxes[first->second];
    const bool same_box = holds(a, b, tol) && holds(b, a, tol);
    std::string message = describe_overlap(a, b) + (same_box ? ": they are one box" : ", and neither lies inside the other");
    if (unordered > 1)
      message += "; " + std::to_string(unordered - 1) + " more such pair" + (unordered > 2 ? "s" : "");
    const std::string hint =
        loose_pieces_hint(a, b) ? *loose_pieces_hint(a, b)
        : a.label == b.label
            ? "separate or merge these objects, or list their label in --stack: parts of one listed label are "
              "painted in file order, the later over the earlier"
            : "say which is painted over which, bottom to top: --stack " + a.label + "," + b.label +
                  " (or the reverse; list every label that overlaps another), or separate them";
    fail_at(example, a, message, hint);
  }

  // Top down: a part once every part painted over it is resolved (its
  // visible pieces are the holes in this one). Ties in file order.
  std::vector<std::size_t> waiting(n, 0);
  std::priority_queue<std::uint32_t, std::vector<std::uint32_t>, std::greater<>> ready;
  std::size_t involved = 0;
  for (std::uint32_t p = 0; p < n; ++p) {
    waiting[p] = above[p].size();
    if (above[p].empty() && below[p].empty()) continue;
    ++involved;
    if (waiting[p] == 0) ready.push(p);
  }
  std::vector<std::vector<Box>> pieces(n);
  std::vector<bool> changed(n, false);
  std::size_t done = 0;
  while (!ready.empty()) {
    const std::uint32_t p = ready.top();
    ready.pop();
    ++done;
    const Box own = box_of(boxes[p]);
    std::vector<Box> holes;
    for (const std::uint32_t t : above[p]) {
      const std::vector<Box>& over = changed[t] ? pieces[t] : std::vector<Box>{box_of(boxes[t])};
      for (const Box& h : over)
        if (auto c = clipped(h, own, tol)) holes.push_back(*c);
    }
    if (!holes.empty()) {
      changed[p] = true;
      tile(own, holes, tol, pieces[p]);
    }
    for (const std::uint32_t b : below[p])
      if (--waiting[b] == 0) ready.push(b);
  }
  if (done < involved) {
    std::vector<std::uint32_t> left;
    for (std::uint32_t p = 0; p < n && left.size() < 2; ++p)
      if (waiting[p] > 0) left.push_back(p);
    fail_at(example, boxes[left[0]],
            "objects " + describe_object(boxes[left[0]]) + " and " + describe_object(boxes[left[1]]) +
                " are among parts painted over one another in a circle (by the stack order and by lying inside "
                "one another)",
            "give a --stack order that lists their labels, so that it alone orders them");
  }

  // The example again, each changed part replaced by its pieces in place.
  Example out;
  out.source = example.source;
  out.meshes = example.meshes;
  out.snapped = example.snapped;
  out.file_tolerance = example.file_tolerance;
  const bool positions = example.positions.size() == n;
  std::unordered_map<std::string, std::uint32_t> mesh_of;
  for (const LabelledBox& b : boxes)
    if (b.mesh != Mesh::kNone) mesh_of.emplace(b.label, b.mesh);
  std::vector<glm::dvec3> at;
  for (std::uint32_t p = 0; p < n; ++p) {
    if (!changed[p]) {
      out.boxes.push_back(boxes[p]);
      if (positions) {
        example.positions.get(p, boxes[p].min, boxes[p].max, at);
        out.positions.add(at, boxes[p].min, boxes[p].max);
      }
      continue;
    }
    for (const Box& piece : pieces[p]) {
      LabelledBox b = boxes[p];
      b.min = piece.min;
      b.max = piece.max;
      b.loose_pieces = 1;
      out.boxes.push_back(b);
      if (positions) {
        at.clear();
        for (int c = 0; c < 8; ++c)
          at.emplace_back((c & 1) ? b.max.x : b.min.x, (c & 2) ? b.max.y : b.min.y, (c & 4) ? b.max.z : b.min.z);
        out.positions.add(at, b.min, b.max);
      }
    }
  }
  // Each label's mesh stays with its first part, which may now be another.
  std::unordered_set<std::string> seen;
  for (LabelledBox& b : out.boxes) {
    const auto it = mesh_of.find(b.label);
    b.mesh = it != mesh_of.end() && seen.insert(b.label).second ? it->second : Mesh::kNone;
  }
  update_bounds(out);
  return out;
}

Example visible_parts(const Example& example, const Layering& layering) {
  std::vector<OverlapPair> overlaps;
  split_boxes(example.boxes, BoxSplitOptions{layering.tolerance}, example.source, &overlaps);
  return visible_parts(example, overlaps, layering);
}

}  // namespace vern
