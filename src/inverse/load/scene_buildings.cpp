#include "inverse/load/scene_buildings.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <utility>

namespace vern {
namespace {

struct Bounds {
  glm::dvec3 min{std::numeric_limits<double>::max()};
  glm::dvec3 max{std::numeric_limits<double>::lowest()};
  void add(const glm::dvec3& lo, const glm::dvec3& hi) {
    min = glm::min(min, lo);
    max = glm::max(max, hi);
  }
};

// The groups of a file's parts, numbered densely in order of their first
// part, with their bounds; each part its own group (`by_part`) reads its
// box in place (a million parts: no copy of their bounds).
class Groups {
 public:
  Groups(const Example& file, bool by_part) : boxes_(file.boxes) {
    if (by_part) return;
    of_part_.resize(boxes_.size());
    std::unordered_map<std::uint32_t, std::uint32_t> dense;
    for (std::size_t b = 0; b < boxes_.size(); ++b) {
      const auto next = static_cast<std::uint32_t>(bounds_.size());
      const std::uint32_t g = dense.emplace(boxes_[b].group, next).first->second;
      if (g == next) bounds_.emplace_back();
      of_part_[b] = g;
      bounds_[g].add(boxes_[b].min, boxes_[b].max);
    }
  }
  std::size_t size() const { return of_part_.empty() ? boxes_.size() : bounds_.size(); }
  std::uint32_t of_part(std::size_t b) const { return of_part_.empty() ? static_cast<std::uint32_t>(b) : of_part_[b]; }
  const glm::dvec3& min(std::uint32_t g) const { return of_part_.empty() ? boxes_[g].min : bounds_[g].min; }
  const glm::dvec3& max(std::uint32_t g) const { return of_part_.empty() ? boxes_[g].max : bounds_[g].max; }

 private:
  const std::vector<LabelledBox>& boxes_;
  std::vector<std::uint32_t> of_part_;  // empty: each part its own group
  std::vector<Bounds> bounds_;
};

// The groups `start` gathered into pieces that gaps wider than
// `tolerance` separate along the first `axes` axes (x, y, z), each piece
// divided again until no gap runs through it (a row of houses, then a
// house behind another). Each division sorts its piece: O(n log n) per
// level.
std::vector<std::vector<std::uint32_t>> separated(const Groups& groups, std::vector<std::uint32_t> start,
                                                  double tolerance, int axes) {
  std::vector<std::vector<std::uint32_t>> out, work;
  work.push_back(std::move(start));
  // A piece's extents along one axis, sorted by where they start (kept
  // side by side: a million groups sort in a tenth of the time an index
  // sorted through the bounds takes).
  struct Extent {
    double lo, hi;
    std::uint32_t group;
  };
  std::vector<Extent> along;
  while (!work.empty()) {
    std::vector<std::uint32_t> piece = std::move(work.back());
    work.pop_back();
    bool divided = false;
    for (int axis = 0; axis < axes && !divided && piece.size() > 1; ++axis) {
      along.clear();
      for (const std::uint32_t g : piece) along.push_back({groups.min(g)[axis], groups.max(g)[axis], g});
      std::sort(along.begin(), along.end(),
                [](const Extent& a, const Extent& b) { return a.lo < b.lo || (a.lo == b.lo && a.group < b.group); });
      std::size_t first = 0;
      double reach = along[0].hi;
      for (std::size_t k = 1; k <= along.size(); ++k) {
        if (k < along.size() && along[k].lo <= reach + tolerance) {
          reach = std::max(reach, along[k].hi);
          continue;
        }
        if (k == along.size() && first == 0) break;  // no gap along this axis
        divided = true;
        std::vector<std::uint32_t>& part = work.emplace_back();
        for (std::size_t i = first; i < k; ++i) part.push_back(along[i].group);
        first = k;
        if (k < along.size()) reach = along[k].hi;
      }
    }
    if (!divided) out.push_back(std::move(piece));
  }
  return out;
}

// The parts `boxes` (file order) of `file` as an example of their own.
Example building_of(const Example& file, const std::vector<std::uint32_t>& boxes, std::string source,
                    const std::unordered_map<std::string, std::uint32_t>& mesh_of) {
  Example out;
  out.source = std::move(source);
  out.meshes = file.meshes;
  out.file_tolerance = default_tolerance(file);
  const bool positions = file.positions.size() == file.boxes.size();
  std::vector<glm::dvec3> at;
  std::unordered_map<std::string, bool> seen;
  for (const std::uint32_t b : boxes) {
    LabelledBox box = file.boxes[b];
    // Each label's first part in this building holds its canonical mesh.
    const auto mesh = mesh_of.find(box.label);
    box.mesh = seen.emplace(box.label, true).second && mesh != mesh_of.end() ? mesh->second : Mesh::kNone;
    if (positions) {
      file.positions.get(b, box.min, box.max, at);
      out.positions.add(at, box.min, box.max);
    }
    out.boxes.push_back(std::move(box));
  }
  update_bounds(out);
  return out;
}

// The pieces that stand apart (separated along x and y), when there are
// two or more and each is a building: it stands on the ground, and no
// empty space divides it along x, y or z (windows annotated without their
// wall, a column of them, are no building). Else none.
std::vector<std::vector<std::uint32_t>> standing_apart(const Example& file, const Groups& groups, double tolerance) {
  std::vector<std::uint32_t> all(groups.size());
  for (std::uint32_t g = 0; g < all.size(); ++g) all[g] = g;
  std::vector<std::vector<std::uint32_t>> pieces = separated(groups, std::move(all), tolerance, 2);
  const double ground = file.min.z + tolerance;
  const auto building = [&](const std::vector<std::uint32_t>& piece) {
    return std::any_of(piece.begin(), piece.end(), [&](std::uint32_t g) { return groups.min(g).z <= ground; }) &&
           separated(groups, piece, tolerance, 3).size() == 1;
  };
  if (pieces.size() < 2 || !std::all_of(pieces.begin(), pieces.end(), building)) pieces.clear();
  return pieces;
}

}  // namespace

SceneBuildings scene_buildings(Example file, BuildingsMode mode, double tolerance) {
  SceneBuildings out;
  if (mode == BuildingsMode::File || file.boxes.empty()) {
    out.buildings.push_back(std::move(file));
    return out;
  }
  const Groups groups(file, mode == BuildingsMode::Parts);
  std::vector<std::vector<std::uint32_t>> pieces;
  if (mode == BuildingsMode::Groups) {
    for (std::uint32_t g = 0; g < groups.size(); ++g) pieces.push_back({g});
  } else {
    pieces = standing_apart(file, groups, tolerance);
  }
  if (pieces.size() < 2) {
    // Buildings the file's groups hold together: said, not divided (a
    // city the grammar lays out as one building).
    if (mode == BuildingsMode::Apart && groups.size() < file.boxes.size()) {
      if (const auto parts = standing_apart(file, Groups(file, true), tolerance); !parts.empty()) {
        out.note = "note: " + file.source + " looks like " + std::to_string(parts.size()) +
                   " buildings standing apart, but its groups (top-level glTF nodes, OBJ `g` groups) hold them "
                   "together: read as one example\n  hint: --buildings parts reads each building as an example";
      }
    }
    out.buildings.push_back(std::move(file));
    return out;
  }
  // Each building's parts in file order; buildings in order of their first.
  std::vector<std::uint32_t> building_of_group(groups.size());
  for (std::uint32_t k = 0; k < pieces.size(); ++k)
    for (const std::uint32_t g : pieces[k]) building_of_group[g] = k;
  std::vector<std::vector<std::uint32_t>> parts(pieces.size());
  std::vector<std::uint32_t> order;
  for (std::uint32_t b = 0; b < file.boxes.size(); ++b) {
    const std::uint32_t k = building_of_group[groups.of_part(b)];
    if (parts[k].empty()) order.push_back(k);
    parts[k].push_back(b);
  }
  std::unordered_map<std::string, std::uint32_t> mesh_of;
  for (const LabelledBox& b : file.boxes)
    if (b.mesh != Mesh::kNone) mesh_of.emplace(b.label, b.mesh);
  const std::string count = std::to_string(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    out.buildings.push_back(building_of(
        file, parts[order[k]], file.source + " (building " + std::to_string(k + 1) + " of " + count + ")", mesh_of));
  }
  const std::string what = mode == BuildingsMode::Groups ? "groups (top-level glTF nodes, OBJ `g` groups)"
                                                         : "buildings standing apart";
  out.note = "note: " + file.source + " holds " + count + " " + what +
             ": each is an example of its own\n  hint: --buildings file reads the whole file as one example";
  return out;
}

}  // namespace vern
