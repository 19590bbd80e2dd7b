#include "inverse/load/turned_examples.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "base/parallel_for.hpp"

namespace vern {

namespace {

// (x, y) turned counterclockwise q times.
glm::dvec3 turn(glm::dvec3 p, int q) {
  for (int i = 0; i < q; ++i) p = {-p.y, p.x, p.z};
  return p;
}

// A run of alike groups of pieces as one, the children of one split
// (`written`: where each is in `out`, from `first`, each followed by '|'):
// bays of a pier, a window and a pier, two or three of them, are one bay.
// Children that repeat the one before are already one; only where a group
// of two or more repeats is the text written again.
void fold_runs(std::string& out, std::size_t first, const std::vector<std::pair<std::size_t, std::size_t>>& written) {
  const auto same = [&](std::size_t a, std::size_t b) {
    return written[a].second == written[b].second &&
           out.compare(written[a].first, written[a].second, out, written[b].first, written[b].second) == 0;
  };
  const std::size_t n = written.size();
  bool any = false;
  for (std::size_t p = 2; 2 * p <= n && !any; ++p)
    for (std::size_t i = 0; i + 2 * p <= n && !any; ++i) {
      bool repeats = true;
      for (std::size_t k = 0; k < p && repeats; ++k) repeats = same(i + k, i + p + k);
      any = repeats;
    }
  if (!any) return;
  std::vector<std::string> children;
  for (const auto& [start, size] : written) children.push_back(out.substr(start, size));
  for (bool folded = true; folded;) {
    folded = false;
    for (std::size_t p = 1; 2 * p <= children.size() && !folded; ++p)
      for (std::size_t i = 0; i + 2 * p <= children.size() && !folded; ++i)
        if (std::equal(children.begin() + i, children.begin() + i + p, children.begin() + i + p)) {
          children.erase(children.begin() + i + p, children.begin() + i + 2 * p);
          folded = true;
        }
  }
  out.resize(first);
  for (const std::string& c : children) out += c + '|';
}

// What the splitting makes of an example, without sizes: axes, order,
// labels, and a run of alike pieces, or of alike groups of pieces, as one
// (rows of 3 and of 5 windows are one layout, and so are 2 and 4 bays).
void layout(const SplitTree& t, const std::vector<LabelledBox>& boxes, std::string& out) {
  switch (t.kind) {
    case SplitTree::Kind::Leaf: out += boxes[t.box].label; return;
    case SplitTree::Kind::Empty: out += '_'; return;
    case SplitTree::Kind::Unsplittable: {
      std::vector<std::string> labels;
      for (const SplitTree& c : t.children) labels.push_back(boxes[c.box].label);
      std::ranges::sort(labels);
      out += "U(";
      for (const std::string& l : labels) out += l + ",";
      out += ')';
      return;
    }
    case SplitTree::Kind::Comp:
      out += "C(";
      for (std::size_t i = 0; i < t.children.size(); ++i) {
        out += face_name(t.faces[i]);
        out += ':';
        layout(t.children[i], boxes, out);
        out += '|';
      }
      out += ')';
      return;
    case SplitTree::Kind::Split: break;
  }
  out += static_cast<char>('x' + t.axis);
  out += '(';
  const std::size_t first = out.size();
  // Each child is written in place and taken back when it repeats the one
  // before: no string per child (each level copied all below it).
  std::vector<std::pair<std::size_t, std::size_t>> written;  // (start, size) of each child kept
  std::size_t previous = std::string::npos, previous_size = 0;
  for (const SplitTree& c : t.children) {
    const std::size_t start = out.size();
    layout(c, boxes, out);
    const std::size_t size = out.size() - start;
    // (Before the first, the one before is empty.)
    if (size == previous_size && (previous == std::string::npos || out.compare(start, size, out, previous, size) == 0)) {
      out.resize(start);
      continue;
    }
    out += '|';
    written.emplace_back(start, size);
    previous = start;
    previous_size = size;
  }
  fold_runs(out, first, written);
  out += ')';
}

// The layout of an example's boxes turned q times (only the boxes: the
// layout reads nothing else).
std::string layout_of(const Example& e, int q, double tolerance) {
  std::vector<LabelledBox> boxes = e.boxes;
  for (LabelledBox& b : boxes) {
    const glm::dvec3 a = turn(b.min, q), c = turn(b.max, q);
    b.min = glm::min(a, c);
    b.max = glm::max(a, c);
  }
  const SplitTree tree = split_boxes(boxes, BoxSplitOptions{tolerance}, e.source);
  std::string out;
  layout(tree, boxes, out);
  return out;
}

}  // namespace

Example turned_example(const Example& example, int quarters) {
  quarters = ((quarters % 4) + 4) % 4;
  if (quarters == 0) return example;
  Example out = example;
  for (LabelledBox& b : out.boxes) {
    const glm::dvec3 a = turn(b.min, quarters), c = turn(b.max, quarters);
    b.min = glm::min(a, c);
    b.max = glm::max(a, c);
  }
  for (Mesh& m : out.meshes) {
    for (glm::dvec3& p : m.positions) p = turn(p, quarters);
    for (glm::dvec3& n : m.normals) n = turn(n, quarters);
  }
  if (example.positions.size() == example.boxes.size()) {
    PartPositions positions;
    std::vector<glm::dvec3> part;
    for (std::size_t i = 0; i < example.boxes.size(); ++i) {
      example.positions.get(i, example.boxes[i].min, example.boxes[i].max, part);
      for (glm::dvec3& p : part) p = turn(p, quarters);
      positions.add(part, out.boxes[i].min, out.boxes[i].max);
    }
    out.positions = std::move(positions);
  }
  update_bounds(out);
  return out;
}

std::vector<int> common_orientation(const std::vector<Example>& examples, const std::vector<SplitTree>& trees,
                                    double tolerance, unsigned threads) {
  const std::size_t n = examples.size();
  std::vector<int> quarters(n, 0);
  if (n < 2) return quarters;
  // Each example's layout turned 0..3 times.
  std::vector<std::array<std::string, 4>> layouts(n);
  for (std::size_t i = 0; i < n; ++i) layout(trees[i], examples[i].boxes, layouts[i][0]);
  // All alike as they are: nothing to turn.
  if (std::all_of(layouts.begin(), layouts.end(), [&](const auto& l) { return l[0] == layouts[0][0]; })) return quarters;
  // Quarter turns only: a building turned half round is also its mirror
  // image for every part symmetric front to back (a garage on the other
  // side), which is how a person reads it.
  parallel_for(n, threads, [&](std::size_t i) {
    for (const int q : {1, 3}) layouts[i][q] = layout_of(examples[i], q, tolerance);
  });
  // How many examples show each layout as they are, and turned.
  std::map<std::string, std::size_t> as_they_are, reachable;
  for (std::size_t i = 0; i < n; ++i) {
    ++as_they_are[layouts[i][0]];
    std::array<std::string, 3> seen{layouts[i][0], layouts[i][1], layouts[i][3]};
    std::ranges::sort(seen);
    for (std::size_t q = 0; q < seen.size(); ++q)
      if (q == 0 || seen[q] != seen[q - 1]) ++reachable[seen[q]];
  }
  // The common layout: the one most examples can show, then the one most
  // show as they are (one order every time: the map's).
  const std::string* common = nullptr;
  for (const auto& [key, count] : reachable) {
    if (as_they_are[key] == 0) continue;  // a layout no example shows as it is turns none
    if (!common || count > reachable[*common] ||
        (count == reachable[*common] && as_they_are[key] > as_they_are[*common]))
      common = &key;
  }
  if (!common || reachable[*common] < 2 || reachable[*common] == as_they_are[*common]) return quarters;
  for (std::size_t i = 0; i < n; ++i) {
    if (layouts[i][0] == *common) continue;
    for (const int q : {1, 3})
      if (layouts[i][q] == *common) {
        quarters[i] = q;
        break;
      }
  }
  return quarters;
}

}  // namespace vern
