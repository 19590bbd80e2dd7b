#include "report/style_report.hpp"

#include <algorithm>
#include <optional>

#include "base/error.hpp"
#include "base/parallel_for.hpp"
#include "forward/derive.hpp"
#include "forward/scope.hpp"
#include "report/building_triangles.hpp"
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

std::string example_caption(const std::string& source) {
  // The file's name ends at " (building" when a scene was divided.
  const std::size_t building = source.find(" (building ");
  const std::size_t slash = source.find_last_of('/', building == std::string::npos ? std::string::npos : building);
  return slash == std::string::npos ? source : source.substr(slash + 1);
}

std::optional<glm::dvec3> elevation_eye(const std::vector<Example>& examples) {
  if (examples.empty()) return std::nullopt;
  // Thin along one horizontal axis, next to the larger of the other two:
  // a facade, seen best as an elevation, from straight in front.
  for (int thin : {1, 0}) {
    const bool flat = std::all_of(examples.begin(), examples.end(), [&](const Example& e) {
      const glm::dvec3 size = e.max - e.min;
      return size[thin] <= 0.05 * std::max(size[1 - thin], size.z);
    });
    if (flat) return thin == 1 ? glm::dvec3(0.0, -1.0, 0.0) : glm::dvec3(-1.0, 0.0, 0.0);
  }
  return std::nullopt;
}

Report style_report(const StyleReportInput& input) {
  if (!input.grammar || !input.primitives || !input.examples)
    throw Error(ErrorKind::Internal, "style_report: the grammar, its meshes and the examples are all needed");
  const std::vector<Example>& examples = *input.examples;
  const std::size_t shown = std::min(examples.size(), input.max_examples);

  // The new buildings first, each on a thread of its own: all pictures are
  // drawn at one scale, which needs every building's size.
  std::vector<std::optional<Derivation>> derived(input.new_buildings);
  std::vector<std::string> stopped(input.new_buildings);
  parallel_for(input.new_buildings, std::max(1u, input.threads), [&](std::size_t i) {
    DeriveOptions options;
    options.seed = input.first_seed + i;
    try {
      derived[i] = derive(*input.grammar, options);
    } catch (const Error& e) {
      if (e.kind() != ErrorKind::Limit) throw;
      stopped[i] = "seed " + std::to_string(options.seed) + " is not shown: " + e.what();
    }
  });
  // Every picture at one scale: the largest building fills its picture.
  std::vector<Bounds> bounds;
  for (std::size_t i = 0; i < shown; ++i) bounds.push_back({examples[i].min, examples[i].max});
  for (const std::optional<Derivation>& d : derived) {
    if (!d || d->terminals.empty()) continue;
    Bounds all = world_bounds(d->terminals.front().scope);
    for (const Terminal& t : d->terminals) {
      const Bounds b = world_bounds(t.scope);
      all.min = glm::min(all.min, b.min);
      all.max = glm::max(all.max, b.max);
    }
    bounds.push_back(all);
  }
  RasterView view = input.view;
  if (const std::optional<glm::dvec3> front = elevation_eye(examples)) view.eye = *front;
  std::vector<glm::dvec2> sizes;
  for (const Bounds& b : bounds) sizes.push_back(projected_size(b.min, b.max, view.eye));
  if (!(view.scale > 0)) view.scale = common_scale(sizes, view);

  std::vector<std::optional<ReportPicture>> pictures(shown + input.new_buildings);
  parallel_for(pictures.size(), std::max(1u, input.threads), [&](std::size_t task) {
    if (task < shown) {
      Layering layering = input.layering;
      layering.tolerance = example_tolerance(examples[task], input.layering.tolerance);
      pictures[task] = picture_of(example_caption(examples[task].source),
                                  example_triangles(visible_parts(examples[task], layering)), view);
    } else if (const std::optional<Derivation>& d = derived[task - shown]) {
      pictures[task] = picture_of("seed " + std::to_string(input.first_seed + (task - shown)),
                                  derived_triangles(*d, *input.primitives), view);
    }
  });

  ReportGallery examples_gallery;
  examples_gallery.title = shown == examples.size()
                               ? "Examples (" + std::to_string(examples.size()) + ")"
                               : "Examples (the first " + std::to_string(shown) + " of " +
                                     std::to_string(examples.size()) + ")";
  for (std::size_t i = 0; i < shown; ++i) examples_gallery.pictures.push_back(std::move(*pictures[i]));
  ReportGallery new_gallery;
  new_gallery.title = "New buildings of the grammar (seeds " + std::to_string(input.first_seed) + " to " +
                      std::to_string(input.first_seed + input.new_buildings - 1) + ")";
  ReportSection section;
  section.figures = input.figures;
  section.notes = input.notes;
  for (std::size_t i = 0; i < input.new_buildings; ++i) {
    if (pictures[shown + i]) new_gallery.pictures.push_back(std::move(*pictures[shown + i]));
    if (!stopped[i].empty()) section.notes.push_back(stopped[i]);
  }
  section.galleries.push_back(std::move(examples_gallery));
  if (input.new_buildings > 0) section.galleries.push_back(std::move(new_gallery));
  section.grammar_name = input.title;
  section.grammar_text = input.grammar_text;

  Report report;
  report.title = input.title;
  report.intro = "A grammar inferred from " + std::to_string(examples.size()) + " example" +
                 (examples.size() == 1 ? "" : "s") +
                 ", and buildings it derives that no example shows. Regenerate more with: generate " + input.title +
                 " -n 10 -o out/";
  report.sections.push_back(std::move(section));
  return report;
}

}  // namespace vern
