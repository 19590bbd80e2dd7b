// Pictures of several buildings for one page: derived where they are
// drawn, all at one scale.
//
// A page shows examples beside new buildings, or a grammar's buildings
// beside those of the grammar learnt from them; at one scale a larger
// building looks larger, which is half of what a style is. Triangles are
// made one picture at a time, on the picture's thread, so a page of large
// buildings holds one building's triangles per thread.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "forward/derive.hpp"
#include "forward/scope.hpp"
#include "graph/grammar.hpp"
#include "report/html_report.hpp"
#include "report/raster.hpp"

namespace vern {

struct Drawing {
  std::string caption;
  Bounds bounds;  // world space: what the common scale must fit
  std::function<std::vector<RasterTriangle>()> triangles;
};

// Each drawing's picture, in order, at the one scale at which the largest
// fits (or at view.scale when set). Drawn on `threads` threads; the same
// pictures on any number.
std::vector<ReportPicture> draw_at_one_scale(const std::vector<Drawing>& drawings, RasterView view, unsigned threads);

// Buildings of `grammar` for seeds first .. first + count - 1, in order,
// derived on `threads` threads. One that stops at a limit is absent, and
// `notes` gets a line saying which seed and why; any other error of
// derive() is thrown.
std::vector<std::optional<Derivation>> derive_for_pictures(const Grammar& grammar, std::uint64_t first,
                                                           std::uint32_t count, unsigned threads,
                                                           std::vector<std::string>& notes);

// The world bounds of a building's terminals (its start scope when it has
// none).
Bounds building_bounds(const Derivation& building);

// A picture of these triangles with its caption.
ReportPicture picture_of(std::string caption, const std::vector<RasterTriangle>& triangles, const RasterView& view);

}  // namespace vern
