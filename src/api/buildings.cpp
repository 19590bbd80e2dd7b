#include "api/buildings.hpp"

#include <unordered_map>

namespace vernacular::detail {

namespace {

Vec3 vec(const glm::dvec3& v) { return {v.x, v.y, v.z}; }
glm::dvec3 vec(const Vec3& v) { return {v[0], v[1], v[2]}; }

}  // namespace

Building building_of(const vern::Derivation& derivation) {
  Building b;
  b.plot = vec(derivation.start.size);
  b.warnings = derivation.warnings;
  b.parts.reserve(derivation.terminals.size());
  for (const vern::Terminal& t : derivation.terminals) {
    Part p;
    p.label = derivation.labels.at(t.label);
    p.origin = vec(t.scope.origin);
    for (int a = 0; a < 3; ++a) p.axes[static_cast<std::size_t>(a)] = vec(t.scope.frame[a]);
    p.size = vec(t.scope.size);
    if (t.coloured) p.colour = std::array<float, 3>{t.colour.red, t.colour.green, t.colour.blue};
    b.parts.push_back(std::move(p));
  }
  return b;
}

std::vector<vern::Derivation> derivations_of(const std::vector<Building>& buildings) {
  // One label table for all: a scene's buildings share it (lay_out).
  std::vector<std::string> labels;
  std::unordered_map<std::string, vern::LabelId> ids;
  std::vector<vern::Derivation> out;
  out.reserve(buildings.size());
  for (const Building& b : buildings) {
    vern::Derivation d;
    d.start.size = vec(b.plot);
    for (const Part& p : b.parts) {
      const auto [it, added] = ids.try_emplace(p.label, static_cast<vern::LabelId>(labels.size()));
      if (added) labels.push_back(p.label);
      vern::Terminal t;
      t.label = it->second;
      t.scope.origin = vec(p.origin);
      for (int a = 0; a < 3; ++a) t.scope.frame[a] = vec(p.axes[static_cast<std::size_t>(a)]);
      t.scope.size = vec(p.size);
      if (p.colour) {
        t.coloured = true;
        t.colour = {(*p.colour)[0], (*p.colour)[1], (*p.colour)[2]};
      }
      d.terminals.push_back(t);
    }
    out.push_back(std::move(d));
  }
  for (vern::Derivation& d : out) d.labels = labels;
  return out;
}

}  // namespace vernacular::detail
