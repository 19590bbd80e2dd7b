#include "report/raster.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vern {

namespace {

constexpr std::uint32_t kSky = std::numeric_limits<std::uint32_t>::max();

// The viewer's frame: right and up span the picture, toward points at the
// viewer (depth grows toward it).
struct Camera {
  glm::dvec3 right, up, toward;
  glm::dvec2 project(const glm::dvec3& p) const { return {glm::dot(p, right), glm::dot(p, up)}; }
  double depth(const glm::dvec3& p) const { return glm::dot(p, toward); }
};

Camera camera_for(const glm::dvec3& eye) {
  Camera c;
  c.toward = glm::normalize(eye);
  const glm::dvec3 z(0.0, 0.0, 1.0);
  glm::dvec3 right = glm::cross(z, c.toward);
  // Seen from straight above, "right" is x.
  c.right = glm::length(right) < 1e-9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::normalize(right);
  c.up = glm::cross(c.toward, c.right);
  return c;
}

// Light from above, a little from the front and the left: roofs brightest,
// fronts lighter than sides, so a box reads as a box.
const glm::dvec3 kLight = glm::normalize(glm::dvec3(-0.2, -0.5, 1.0));

double edge(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// The margin left all round a picture, in its pixels.
double margin_of(int width, int height) { return 0.06 * std::min(width, height); }

}  // namespace

glm::dvec2 projected_size(const glm::dvec3& min, const glm::dvec3& max, const glm::dvec3& eye) {
  const Camera cam = camera_for(eye);
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec2 q = cam.project(
        glm::dvec3(corner & 1 ? max.x : min.x, corner & 2 ? max.y : min.y, corner & 4 ? max.z : min.z));
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  return hi - lo;
}

double common_scale(std::span<const glm::dvec2> sizes, const RasterView& view) {
  const double margin = margin_of(view.width, view.height);
  double scale = std::numeric_limits<double>::infinity();
  for (const glm::dvec2& size : sizes) {
    if (size.x > 0) scale = std::min(scale, (view.width - 2 * margin) / size.x);
    if (size.y > 0) scale = std::min(scale, (view.height - 2 * margin) / size.y);
  }
  return std::isfinite(scale) ? scale : 1.0;
}

RgbImage rasterize(std::span<const RasterTriangle> triangles, const RasterView& view) {
  const int ss = std::max(1, view.supersampling);
  const int width = std::max(1, view.width), height = std::max(1, view.height);
  const int sw = width * ss, sh = height * ss;
  const Camera cam = camera_for(view.eye);

  // Fit the projected bounds into the picture, a margin all round.
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const RasterTriangle& t : triangles)
    for (const glm::dvec3* p : {&t.a, &t.b, &t.c}) {
      const glm::dvec2 q = cam.project(*p);
      lo = glm::min(lo, q);
      hi = glm::max(hi, q);
    }
  const glm::dvec2 extent = hi - lo;
  double scale = view.scale > 0 ? view.scale * ss : 1.0;
  if (!(view.scale > 0) && (extent.x > 0 || extent.y > 0)) {
    const glm::dvec2 sizes[] = {extent};
    RasterView samples = view;
    samples.width = sw;
    samples.height = sh;
    scale = common_scale(sizes, samples);
  }
  glm::dvec2 centre = triangles.empty() ? glm::dvec2(0.0) : (lo + hi) * 0.5;
  // At a scale given, buildings stand on the picture's margin, as in a row
  // of pictures of one street; fitted, each is centred.
  if (view.scale > 0 && !triangles.empty()) centre.y = lo.y + (sh * 0.5 - margin_of(sw, sh)) / scale;
  auto to_samples = [&](const glm::dvec3& p) {
    const glm::dvec2 q = (cam.project(p) - centre) * scale;
    return glm::dvec2(sw * 0.5 + q.x, sh * 0.5 - q.y);
  };

  const std::size_t samples = static_cast<std::size_t>(sw) * static_cast<std::size_t>(sh);
  std::vector<double> depth(samples, -std::numeric_limits<double>::infinity());
  std::vector<std::uint32_t> seen(samples, kSky);  // triangle index at each sample
  std::vector<glm::dvec3> shade(triangles.size());
  // Faces of one part are told apart by their plane's direction, so a box's
  // edges are drawn but not the diagonal between a quad's two triangles.
  std::vector<std::uint64_t> face(triangles.size());

  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const RasterTriangle& t = triangles[i];
    glm::dvec3 n = glm::cross(t.b - t.a, t.c - t.a);
    const double area = glm::length(n);
    if (!(area > 0)) continue;
    n /= area;
    if (glm::dot(n, cam.toward) < 0) n = -n;  // both sides of a face are seen alike
    const double light = 0.35 + 0.65 * std::max(0.0, glm::dot(n, kLight));
    shade[i] = glm::clamp(t.colour, 0.0, 1.0) * light;
    const auto q = [](double v) { return static_cast<std::uint64_t>(std::lround(v * 32.0) + 64) & 0xff; };
    face[i] = (static_cast<std::uint64_t>(t.part) << 24) | (q(n.x) << 16) | (q(n.y) << 8) | q(n.z);

    const glm::dvec2 a = to_samples(t.a), b = to_samples(t.b), c = to_samples(t.c);
    const double da = cam.depth(t.a), db = cam.depth(t.b), dc = cam.depth(t.c);
    const double whole = edge(a, b, c);
    if (!(std::abs(whole) > 1e-12)) continue;  // edge on
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x, b.x, c.x}))));
    const int x1 = std::min(sw - 1, static_cast<int>(std::ceil(std::max({a.x, b.x, c.x}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y, b.y, c.y}))));
    const int y1 = std::min(sh - 1, static_cast<int>(std::ceil(std::max({a.y, b.y, c.y}))));
    // Edge functions stepped along rows (a large facade covers a hundred
    // thousand samples, and buildings behind it as many again): weights
    // are the edge values over the whole area, made positive inside.
    const double inv = 1.0 / whole;
    const glm::dvec2 start(x0 + 0.5, y0 + 0.5);
    const double wa0 = edge(b, c, start) * inv, wb0 = edge(c, a, start) * inv, wc0 = edge(a, b, start) * inv;
    // d(edge(u, v, p))/dx = -(v.y - u.y), d/dy = v.x - u.x.
    const double ax = -(c.y - b.y) * inv, ay = (c.x - b.x) * inv;
    const double bx = -(a.y - c.y) * inv, by = (a.x - c.x) * inv;
    const double cx = -(b.y - a.y) * inv, cy = (b.x - a.x) * inv;
    for (int y = y0; y <= y1; ++y) {
      const int dy = y - y0;
      double wa = wa0 + ay * dy, wb = wb0 + by * dy, wc = wc0 + cy * dy;
      std::size_t at = static_cast<std::size_t>(y) * sw + x0;
      for (int x = x0; x <= x1; ++x, ++at, wa += ax, wb += bx, wc += cx) {
        if (wa < 0 || wb < 0 || wc < 0) continue;
        const double d = wa * da + wb * db + wc * dc;
        // Nearer wins; on a tie the earlier triangle keeps the sample.
        if (d > depth[at]) {
          depth[at] = d;
          seen[at] = static_cast<std::uint32_t>(i);
        }
      }
    }
  }

  // A sample is on an outline when a neighbour shows another face or sky.
  auto key = [&](std::size_t at) { return seen[at] == kSky ? ~std::uint64_t{0} : face[seen[at]]; };
  RgbImage image;
  image.width = width;
  image.height = height;
  image.rgb.assign(static_cast<std::size_t>(width) * height * 3, 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      glm::dvec3 sum(0.0);
      for (int sy = y * ss; sy < (y + 1) * ss; ++sy)
        for (int sx = x * ss; sx < (x + 1) * ss; ++sx) {
          const std::size_t at = static_cast<std::size_t>(sy) * sw + sx;
          if (seen[at] == kSky) {
            sum += glm::dvec3(1.0);
            continue;
          }
          const std::uint64_t k = key(at);
          const bool outline = (sx > 0 && key(at - 1) != k) || (sx + 1 < sw && key(at + 1) != k) ||
                               (sy > 0 && key(at - sw) != k) || (sy + 1 < sh && key(at + sw) != k);
          sum += outline ? shade[seen[at]] * 0.45 : shade[seen[at]];
        }
      const glm::dvec3 colour = sum / static_cast<double>(ss * ss);
      for (int k = 0; k < 3; ++k)
        image.rgb[(static_cast<std::size_t>(y) * width + x) * 3 + k] =
            static_cast<std::uint8_t>(std::lround(std::clamp(colour[k], 0.0, 1.0) * 255.0));
    }
  return image;
}

}  // namespace vern
