#include "eval/layout_statistics.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>

namespace vern {

double wasserstein1(std::vector<double> a, std::vector<double> b) {
  if (a.empty() && b.empty()) return 0;
  auto mean_magnitude = [](const std::vector<double>& v) {
    double s = 0;
    for (const double x : v) s += std::abs(x);
    return s / static_cast<double>(v.size());
  };
  if (a.empty()) return mean_magnitude(b);
  if (b.empty()) return mean_magnitude(a);
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  // Integrate |F_a - F_b| over the merged breakpoints.
  const double wa = 1.0 / static_cast<double>(a.size()), wb = 1.0 / static_cast<double>(b.size());
  std::size_t i = 0, j = 0;
  double fa = 0, fb = 0, x = std::min(a[0], b[0]), total = 0;
  while (i < a.size() || j < b.size()) {
    const double next = j == b.size() || (i < a.size() && a[i] <= b[j]) ? a[i] : b[j];
    total += std::abs(fa - fb) * (next - x);
    x = next;
    while (i < a.size() && a[i] == x) fa += wa, ++i;
    while (j < b.size() && b[j] == x) fb += wb, ++j;
  }
  return total;
}

namespace {

// Per label name: part counts per building, and part sizes per axis.
struct Summary {
  std::map<std::string, std::vector<double>> counts;
  std::map<std::string, std::array<std::vector<double>, 3>> sizes;
  std::array<std::vector<double>, 3> plot;
};

Summary summarise(const std::vector<Derivation>& sample) {
  Summary s;
  // Every label of every building gets a count, zero included, so a label
  // that appears in some buildings is compared over all of them.
  std::vector<std::string> names;
  for (const Derivation& d : sample) {
    for (const Terminal& t : d.terminals) names.push_back(d.labels[t.label]);
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  for (const std::string& name : names) s.counts[name];
  for (const Derivation& d : sample) {
    std::map<std::string, double> count;
    for (const Terminal& t : d.terminals) {
      const std::string& name = d.labels[t.label];
      count[name] += 1;
      const Bounds b = world_bounds(t.scope);
      for (int a = 0; a < 3; ++a) s.sizes[name][static_cast<std::size_t>(a)].push_back(b.max[a] - b.min[a]);
    }
    for (const std::string& name : names) s.counts[name].push_back(count[name]);
    for (int a = 0; a < 3; ++a) s.plot[static_cast<std::size_t>(a)].push_back(d.start.size[a]);
  }
  return s;
}

// W1 relative to the reference's mean magnitude; 1 when only one side has
// values, 0 when neither does.
double relative_distance(const std::vector<double>& reference, const std::vector<double>& candidate) {
  if (reference.empty() || candidate.empty()) return reference.empty() && candidate.empty() ? 0.0 : 1.0;
  double mean = 0;
  for (const double x : reference) mean += std::abs(x);
  mean /= static_cast<double>(reference.size());
  const double w = wasserstein1(reference, candidate);
  if (mean <= 0) return w > 0 ? 1.0 : 0.0;
  return w / mean;
}

template <class Map, class Each>
void for_each_label(const Map& a, const Map& b, Each each) {
  std::vector<std::string> names;
  for (const auto& [name, _] : a) names.push_back(name);
  for (const auto& [name, _] : b) names.push_back(name);
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  for (const std::string& name : names) {
    const auto x = a.find(name), y = b.find(name);
    each(x == a.end() ? nullptr : &x->second, y == b.end() ? nullptr : &y->second);
  }
}

}  // namespace

StyleDistance style_distance(const std::vector<Derivation>& reference, const std::vector<Derivation>& candidate) {
  const Summary r = summarise(reference), c = summarise(candidate);
  StyleDistance d;
  std::size_t n = 0;
  for_each_label(r.counts, c.counts, [&](const std::vector<double>* x, const std::vector<double>* y) {
    d.structure += x && y ? relative_distance(*x, *y) : 1.0;
    ++n;
  });
  d.structure = n ? d.structure / static_cast<double>(n) : 0.0;

  n = 0;
  for_each_label(r.sizes, c.sizes, [&](const std::array<std::vector<double>, 3>* x,
                                        const std::array<std::vector<double>, 3>* y) {
    for (std::size_t a = 0; a < 3; ++a) d.sizes += x && y ? relative_distance((*x)[a], (*y)[a]) : 1.0;
    n += 3;
  });
  for (std::size_t a = 0; a < 3; ++a) d.sizes += relative_distance(r.plot[a], c.plot[a]);
  n += 3;
  d.sizes /= static_cast<double>(n);
  return d;
}

bool same_layout(const Derivation& a, const Derivation& b, double tolerance) {
  if (a.terminals.size() != b.terminals.size()) return false;
  // b's parts by cell of their low x corner; a part of a looks in its own
  // cell and the two beside it, so a bound within tolerance of a cell edge
  // is still found.
  const double cell = 4 * tolerance;
  struct Part {
    const std::string* label;
    Bounds bounds;
    bool used = false;
  };
  std::vector<Part> parts;
  std::multimap<long long, std::size_t> by_cell;
  for (const Terminal& t : b.terminals) {
    parts.push_back({&b.labels[t.label], world_bounds(t.scope)});
    by_cell.emplace(std::llround(std::floor(parts.back().bounds.min.x / cell)), parts.size() - 1);
  }
  auto close = [&](const Bounds& x, const Bounds& y) {
    for (int i = 0; i < 3; ++i) {
      if (std::abs(x.min[i] - y.min[i]) > tolerance || std::abs(x.max[i] - y.max[i]) > tolerance) return false;
    }
    return true;
  };
  for (const Terminal& t : a.terminals) {
    const Bounds bounds = world_bounds(t.scope);
    const long long home = std::llround(std::floor(bounds.min.x / cell));
    bool found = false;
    for (long long c = home - 1; c <= home + 1 && !found; ++c) {
      const auto [first, last] = by_cell.equal_range(c);
      for (auto it = first; it != last && !found; ++it) {
        Part& p = parts[it->second];
        if (!p.used && *p.label == a.labels[t.label] && close(p.bounds, bounds)) found = p.used = true;
      }
    }
    if (!found) return false;
  }
  return true;
}

}  // namespace vern
