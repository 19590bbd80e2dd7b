#include "report/drawings.hpp"

#include <algorithm>

#include "base/error.hpp"
#include "base/parallel_for.hpp"
#include "report/png.hpp"

namespace vern {

ReportPicture picture_of(std::string caption, const std::vector<RasterTriangle>& triangles, const RasterView& view) {
  ReportPicture p;
  p.caption = std::move(caption);
  const RgbImage image = rasterize(triangles, view);
  p.png = png_bytes(image);
  p.width = image.width;
  p.height = image.height;
  return p;
}

std::vector<ReportPicture> draw_at_one_scale(const std::vector<Drawing>& drawings, RasterView view, unsigned threads) {
  if (!(view.scale > 0)) {
    std::vector<glm::dvec2> sizes;
    for (const Drawing& d : drawings) sizes.push_back(projected_size(d.bounds.min, d.bounds.max, view.eye));
    view.scale = common_scale(sizes, view);
  }
  std::vector<ReportPicture> pictures(drawings.size());
  parallel_for(drawings.size(), std::max(1u, threads), [&](std::size_t i) {
    pictures[i] = picture_of(drawings[i].caption, drawings[i].triangles(), view);
  });
  return pictures;
}

std::vector<std::optional<Derivation>> derive_for_pictures(const Grammar& grammar, std::uint64_t first,
                                                           std::uint32_t count, unsigned threads,
                                                           std::vector<std::string>& notes) {
  std::vector<std::optional<Derivation>> derived(count);
  std::vector<std::string> stopped(count);
  parallel_for(count, std::max(1u, threads), [&](std::size_t i) {
    DeriveOptions options;
    options.seed = first + i;
    try {
      derived[i] = derive(grammar, options);
    } catch (const Error& e) {
      if (e.kind() != ErrorKind::Limit) throw;
      stopped[i] = "seed " + std::to_string(options.seed) + " is not shown: " + e.what();
    }
  });
  for (const std::string& s : stopped)
    if (!s.empty()) notes.push_back(s);
  return derived;
}

Bounds building_bounds(const Derivation& building) {
  if (building.terminals.empty()) return world_bounds(building.start);
  Bounds all = world_bounds(building.terminals.front().scope);
  for (const Terminal& t : building.terminals) {
    const Bounds b = world_bounds(t.scope);
    all.min = glm::min(all.min, b.min);
    all.max = glm::max(all.max, b.max);
  }
  return all;
}

}  // namespace vern
