// Pictures of buildings: triangles drawn into an image, seen from above
// one front corner.
//
// Reports are mailed and opened anywhere (report/html_report.hpp), so a
// building is drawn here, as pixels, not left to a viewer. A z-buffer
// decides what is seen, exactly, whatever the order of the triangles (a
// painter's sort of faces gets interlocking boxes wrong); parallel
// projection keeps a facade's rows and columns straight. The picture is a
// pure function of its triangles and view: same input, same pixels.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace vern {

struct RasterTriangle {
  glm::dvec3 a{0.0}, b{0.0}, c{0.0};  // world space, z up
  glm::dvec3 colour{0.8};             // components in [0, 1]
  // Parts are outlined where one meets another or the sky: the part
  // (terminal, example part) the triangle belongs to.
  std::uint32_t part = 0;
};

struct RasterView {
  int width = 360, height = 270;  // pixels of the picture
  // Where the viewer stands, as a direction from the building: the front
  // (the side facing -y, where facades face) seen a little from its left
  // and from above.
  glm::dvec3 eye{-0.45, -1.0, 0.55};
  int supersampling = 3;  // samples per pixel along each axis (edges without jaggies)
  // Pixels per metre; 0: whatever fills the picture. Pictures drawn at one
  // scale show which building is the larger.
  double scale = 0;
};

struct RgbImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // rows top to bottom, 3 bytes a pixel
  friend bool operator==(const RgbImage&, const RgbImage&) = default;
};

// The triangles drawn in parallel projection along -view.eye, centred,
// scaled to fill the picture with a margin (or at view.scale), lit from
// above and in front, each part outlined. A white picture for no
// triangles. Triangles of zero area (seen edge on) draw nothing of their
// own.
RgbImage rasterize(std::span<const RasterTriangle> triangles, const RasterView& view = {});

// The width and height, in metres, that the box from `min` to `max` covers
// in a picture seen from `eye`.
glm::dvec2 projected_size(const glm::dvec3& min, const glm::dvec3& max, const glm::dvec3& eye);

// The largest scale (pixels per metre) at which every one of these sizes
// fits a picture of `view`'s size with rasterize's margin.
double common_scale(std::span<const glm::dvec2> sizes, const RasterView& view);

}  // namespace vern
