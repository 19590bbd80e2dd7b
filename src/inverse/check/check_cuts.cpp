#include "inverse/check/check_cuts.hpp"

#include <algorithm>
#include <cmath>

#include "inverse/check/check_text.hpp"

namespace vern::check_detail {

namespace {
constexpr std::uint32_t kNoSegment = ~std::uint32_t{0};

struct Face {
  double t;
  int tag;  // -1: the scope's start, -2: its end, else 2 * k + (max face)
};

// make_cuts' working lists, kept from call to call on each thread: most
// calls cut one or two boxes, and allocating eight lists each time cost
// more than the cutting.
struct CutsScratch {
  std::vector<Face> faces;
  std::vector<double> lo, hi, positions;
  std::vector<int> cover;
  std::vector<char> flat_at;
  std::vector<std::uint32_t> seg_of;
  std::vector<std::size_t> next;
};
}  // namespace

std::optional<AxisMap> axis_map(const Scope& s, Axis a) {
  const glm::dvec3 f = s.frame[static_cast<int>(a)];
  for (int w = 0; w < 3; ++w) {
    const bool unit =
        std::abs(std::abs(f[w]) - 1.0) < 1e-9 && std::abs(f[(w + 1) % 3]) < 1e-9 && std::abs(f[(w + 2) % 3]) < 1e-9;
    if (unit) return AxisMap{w, f[w] > 0 ? 1.0 : -1.0, s.origin[w]};
  }
  return std::nullopt;
}

Cuts make_cuts(const std::vector<LabelledBox>& boxes, const BoxList& inside, const AxisMap& am, double length,
               double tol, double cut_tol) {
  Cuts c;
  make_cuts(boxes, inside, am, length, tol, cut_tol, c);
  return c;
}

void make_cuts(const std::vector<LabelledBox>& boxes, const BoxList& inside, const AxisMap& am, double length,
               double tol, double cut_tol, Cuts& c) {
  c.at.clear();
  c.in_order.clear();
  c.prefix.clear();
  c.outside.clear();
  thread_local CutsScratch scratch;
  // Every face and both ends, snapped: a run of positions within the
  // tolerance becomes one, the scope's end if the run holds one, else
  // its smallest.
  std::vector<Face>& faces = scratch.faces;
  faces.resize(2 * inside.size() + 2);
  faces[0] = {0.0, -1};
  faces[1] = {length, -2};
  for (std::size_t k = 0; k < inside.size(); ++k) {
    const LabelledBox& b = boxes[inside[k]];
    double t0 = am.local(b.min[am.world]), t1 = am.local(b.max[am.world]);
    if (t0 > t1) std::swap(t0, t1);
    faces[2 * k + 2] = {t0, static_cast<int>(2 * k)};
    faces[2 * k + 3] = {t1, static_cast<int>(2 * k + 1)};
  }
  // Most calls cut a box or two (a bay's window): sorted in place. Faces
  // at one position may come in any order; they become one cut.
  const auto earlier = [](const Face& a, const Face& b) { return a.t < b.t; };
  if (faces.size() <= 16) {
    for (std::size_t i = 1; i < faces.size(); ++i)
      for (std::size_t j = i; j > 0 && earlier(faces[j], faces[j - 1]); --j) std::swap(faces[j], faces[j - 1]);
  } else {
    std::sort(faces.begin(), faces.end(), earlier);
  }
  std::vector<double>& lo = scratch.lo;
  std::vector<double>& hi = scratch.hi;
  std::vector<double>& positions = scratch.positions;
  lo.assign(inside.size(), 0.0);
  hi.assign(inside.size(), 0.0);
  positions.clear();
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i;
    double rep = faces[i].t;
    bool has_start = false, has_end = false;
    // Faces within the cut tolerance are one; within the tolerance of a
    // scope's end, they are that end (a box may reach past a scope the
    // grammar placed by so much).
    const auto near = [&](double a, double b) { return std::abs(a - b) <= tol; };
    const bool at_start = cut_tol < tol && near(faces[i].t, 0.0), at_end = cut_tol < tol && near(faces[i].t, length);
    while (j < faces.size() &&
           (faces[j].t - faces[i].t <= cut_tol || (at_start && near(faces[j].t, 0.0)) ||
            (at_end && near(faces[j].t, length)))) {
      has_start = has_start || faces[j].tag == -1;
      has_end = has_end || faces[j].tag == -2;
      ++j;
    }
    if (has_start)
      rep = 0.0;
    else if (has_end)
      rep = length;
    for (std::size_t k = i; k < j; ++k) {
      if (faces[k].tag < 0) continue;
      const auto box = static_cast<std::size_t>(faces[k].tag / 2);
      (faces[k].tag % 2 ? hi : lo)[box] = rep;
    }
    positions.push_back(rep);
    i = j;
  }
  std::sort(positions.begin(), positions.end());
  positions.erase(std::unique(positions.begin(), positions.end()), positions.end());
  // Positions strictly inside a box are crossed: no boundary there.
  std::vector<int>& cover = scratch.cover;
  std::vector<char>& flat_at = scratch.flat_at;
  cover.assign(positions.size() + 1, 0);
  flat_at.assign(positions.size(), 0);
  auto index_of = [&](double v) {
    return static_cast<std::size_t>(std::lower_bound(positions.begin(), positions.end(), v) - positions.begin());
  };
  for (std::size_t k = 0; k < inside.size(); ++k) {
    if (lo[k] < -tol || hi[k] > length + tol) {
      c.outside.push_back(inside[k]);
      continue;
    }
    const std::size_t a = index_of(lo[k]), b = index_of(hi[k]);
    if (a == b) {
      flat_at[a] = 1;
      continue;
    }
    cover[a + 1] += 1;
    cover[b] -= 1;
  }
  int running = 0;
  for (std::size_t k = 0; k < positions.size(); ++k) {
    running += cover[k];
    if (running > 0 || positions[k] < 0 || positions[k] > length) continue;
    c.at.push_back(positions[k]);
    if (flat_at[k]) c.at.push_back(positions[k]);
  }
  const std::size_t segments = c.at.empty() ? 0 : c.at.size() - 1;
  // Each box's segment, then the boxes ordered by segment (in their order
  // within one).
  std::vector<std::uint32_t>& seg_of = scratch.seg_of;
  seg_of.assign(inside.size(), kNoSegment);
  c.prefix.assign(segments + 1, 0);
  for (std::size_t k = 0; k < inside.size(); ++k) {
    if (lo[k] < -tol || hi[k] > length + tol) continue;
    if (segments == 0) {
      c.outside.push_back(inside[k]);
      continue;
    }
    std::size_t seg;
    const auto first = std::lower_bound(c.at.begin(), c.at.end(), lo[k]);
    if (lo[k] == hi[k] && first != c.at.end() && *first == lo[k]) {
      seg = static_cast<std::size_t>(first - c.at.begin());  // the zero-length segment at a flat box's cut
    } else {
      const auto after = std::upper_bound(c.at.begin(), c.at.end(), lo[k]);
      seg = after == c.at.begin() ? 0 : static_cast<std::size_t>(after - c.at.begin()) - 1;
    }
    seg = std::min(seg, segments - 1);
    seg_of[k] = static_cast<std::uint32_t>(seg);
    ++c.prefix[seg + 1];
  }
  for (std::size_t k = 0; k < segments; ++k) c.prefix[k + 1] += c.prefix[k];
  c.in_order.resize(c.prefix[segments]);
  std::vector<std::size_t>& next = scratch.next;
  next.assign(c.prefix.begin(), c.prefix.end() - 1);
  for (std::size_t k = 0; k < inside.size(); ++k)
    if (seg_of[k] != kNoSegment) c.in_order[next[seg_of[k]]++] = inside[k];
}

std::shared_ptr<const Cuts> CutsCache::of(const BoxList& inside, const AxisMap& am, double length) {
  for (const Entry& c : entries_)
    if (c.world == am.world && c.sign == am.sign && c.origin == am.origin && c.length == length && c.boxes == inside)
      return c.cuts;
  Entry* slot = nullptr;
  if (entries_.size() < 8) {
    slot = &entries_.emplace_back();
  } else {
    slot = &entries_[next_++ % entries_.size()];
  }
  Entry& e = *slot;
  // A split still matching may hold the old cuts: then they stay its own.
  if (!e.cuts || e.cuts.use_count() > 1) e.cuts = std::make_shared<Cuts>();
  make_cuts(boxes_, inside, am, length, tol_, cut_tol_, *e.cuts);
  e.boxes.assign(inside.begin(), inside.end());
  e.world = am.world;
  e.sign = am.sign;
  e.origin = am.origin;
  e.length = length;
  return e.cuts;
}

std::string cuts_text(const Cuts& c, const AxisMap& am) {
  std::vector<double> w;
  for (double t : c.at) w.push_back(am.world_of(t));
  std::sort(w.begin(), w.end());
  w.erase(std::unique(w.begin(), w.end()), w.end());
  std::string t = std::string(1, "xyz"[am.world]) + " = ";
  for (std::size_t k = 0; k < w.size() && k < 12; ++k) t += (k ? ", " : "") + num(w[k]);
  if (w.size() > 12) t += ", ... (" + std::to_string(w.size()) + " cuts)";
  return t;
}

}  // namespace vern::check_detail
