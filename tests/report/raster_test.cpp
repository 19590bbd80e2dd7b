// Pictures of buildings: what is drawn where, what hides what, outlines,
// and one scale for several pictures.
#include "report/raster.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace vern {
namespace {

// A box's twelve triangles, all in one colour, as one part.
std::vector<RasterTriangle> box(glm::dvec3 min, glm::dvec3 max, glm::dvec3 colour, std::uint32_t part) {
  auto at = [&](int c) { return glm::dvec3(c & 1 ? max.x : min.x, c & 2 ? max.y : min.y, c & 4 ? max.z : min.z); };
  static constexpr int kFaces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  std::vector<RasterTriangle> out;
  for (const auto& f : kFaces) {
    out.push_back({at(f[0]), at(f[1]), at(f[2]), colour, part});
    out.push_back({at(f[0]), at(f[2]), at(f[3]), colour, part});
  }
  return out;
}

glm::ivec3 pixel(const RgbImage& image, int x, int y) {
  const std::size_t at = (static_cast<std::size_t>(y) * image.width + x) * 3;
  return {image.rgb[at], image.rgb[at + 1], image.rgb[at + 2]};
}

const glm::ivec3 kWhite(255, 255, 255);

// Seen straight from the front (-y), z up: the picture's x is the world's
// x and its rows run down z.
RasterView front_view() {
  RasterView v;
  v.width = 100;
  v.height = 100;
  v.eye = {0.0, -1.0, 0.0};
  return v;
}

TEST(Raster, NoTrianglesIsAWhitePicture) {
  const RgbImage image = rasterize({}, front_view());
  ASSERT_EQ(image.rgb.size(), 100u * 100u * 3u);
  EXPECT_TRUE(std::all_of(image.rgb.begin(), image.rgb.end(), [](std::uint8_t b) { return b == 255; }));
}

TEST(Raster, ABoxFillsThePictureButItsMarginAndKeepsItsColour) {
  const auto tris = box({0, 0, 0}, {1, 1, 1}, {1.0, 0.0, 0.0}, 0);
  const RgbImage image = rasterize(tris, front_view());
  EXPECT_EQ(pixel(image, 1, 1), kWhite);
  EXPECT_EQ(pixel(image, 98, 98), kWhite);
  const glm::ivec3 centre = pixel(image, 50, 50);
  EXPECT_GT(centre.r, 60);  // red, darkened by the light on a face seen head on
  EXPECT_EQ(centre.g, 0);
  EXPECT_EQ(centre.b, 0);
  // The margin is 6 %: the box spans about 6 to 94.
  EXPECT_NE(pixel(image, 10, 50), kWhite);
  EXPECT_NE(pixel(image, 90, 50), kWhite);
}

TEST(Raster, TheNearerPartHidesTheOtherWhateverTheOrderDrawn) {
  // A red slab in front (y = 0 .. 0.1) of a larger blue one (y = 1 .. 1.1).
  const auto near = box({0.25, 0, 0.25}, {0.75, 0.1, 0.75}, {1, 0, 0}, 0);
  const auto far = box({0, 1, 0}, {1, 1.1, 1}, {0, 0, 1}, 1);
  std::vector<RasterTriangle> near_first = near, far_first = far;
  near_first.insert(near_first.end(), far.begin(), far.end());
  far_first.insert(far_first.end(), near.begin(), near.end());
  for (const auto& tris : {near_first, far_first}) {
    const RgbImage image = rasterize(tris, front_view());
    const glm::ivec3 middle = pixel(image, 50, 50), side = pixel(image, 15, 50);
    EXPECT_GT(middle.r, 0);
    EXPECT_EQ(middle.b, 0);
    EXPECT_EQ(side.r, 0);
    EXPECT_GT(side.b, 0);
  }
}

TEST(Raster, WherePartsMeetAnOutlineIsDrawnAndNotInsideAFace) {
  // Two grey boxes side by side, x 0..1 and 1..2: one face seen head on.
  auto tris = box({0, 0, 0}, {1, 1, 1}, {0.8, 0.8, 0.8}, 0);
  const auto right = box({1, 0, 0}, {2, 1, 1}, {0.8, 0.8, 0.8}, 1);
  tris.insert(tris.end(), right.begin(), right.end());
  RasterView view = front_view();
  view.width = 200;
  const RgbImage image = rasterize(tris, view);
  // Inside a face: the face's grey; where the two meet (x = 100): darker.
  // The diagonal between a face's two triangles is no outline.
  // The left face spans pixels 12 to 100 across and 94 up to 6; its
  // diagonal runs from (12, 94) to (100, 6).
  const glm::ivec3 inside = pixel(image, 35, 60), seam = pixel(image, 100, 50), diagonal = pixel(image, 56, 50);
  EXPECT_LT(seam.r, inside.r - 15);
  EXPECT_EQ(diagonal, inside);
}

TEST(Raster, AtOneScaleALargerBuildingIsDrawnLargerAndStandsOnTheMargin) {
  const auto small = box({0, 0, 0}, {1, 1, 1}, {0.5, 0.5, 0.5}, 0);
  const auto tall = box({0, 0, 0}, {1, 1, 3}, {0.5, 0.5, 0.5}, 0);
  RasterView view = front_view();
  const glm::dvec2 sizes[] = {projected_size({0, 0, 0}, {1, 1, 1}, view.eye), projected_size({0, 0, 0}, {1, 1, 3}, view.eye)};
  EXPECT_DOUBLE_EQ(sizes[1].y, 3.0);
  view.scale = common_scale(sizes, view);
  EXPECT_NEAR(view.scale, 88.0 / 3.0, 1e-9);  // the tall box fills the height but the margins
  auto rows_drawn = [](const RgbImage& image) {
    int top = image.height, bottom = -1;
    for (int y = 0; y < image.height; ++y)
      if (pixel(image, 50, y) != kWhite) top = std::min(top, y), bottom = std::max(bottom, y);
    return std::pair(top, bottom);
  };
  const auto [small_top, small_bottom] = rows_drawn(rasterize(small, view));
  const auto [tall_top, tall_bottom] = rows_drawn(rasterize(tall, view));
  EXPECT_NEAR(tall_bottom - tall_top, 3 * (small_bottom - small_top), 3);
  EXPECT_EQ(small_bottom, tall_bottom);  // both on the ground line
  // Fitted, each fills the picture.
  RasterView fitted = front_view();
  EXPECT_NEAR(rows_drawn(rasterize(small, fitted)).second - rows_drawn(rasterize(small, fitted)).first, 88, 2);
}

}  // namespace
}  // namespace vern
