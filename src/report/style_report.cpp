#include "report/style_report.hpp"

#include <algorithm>
#include <optional>
#include <utility>

#include "base/error.hpp"
#include "forward/derive.hpp"
#include "forward/scope.hpp"
#include "report/building_triangles.hpp"
#include "report/drawings.hpp"

namespace vern {

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

  ReportSection section;
  section.figures = input.figures;
  section.notes = input.notes;
  const std::vector<std::optional<Derivation>> derived =
      derive_for_pictures(*input.grammar, input.first_seed, input.new_buildings, input.threads, section.notes);
  std::vector<Drawing> drawings;
  for (std::size_t i = 0; i < shown; ++i) {
    const Example& example = examples[i];
    drawings.push_back({example_caption(example.source), {example.min, example.max}, [&input, &example] {
                          Layering layering = input.layering;
                          layering.tolerance = example_tolerance(example, input.layering.tolerance);
                          return example_triangles(visible_parts(example, layering));
                        }});
  }
  for (std::size_t i = 0; i < derived.size(); ++i)
    if (const std::optional<Derivation>& d = derived[i])
      drawings.push_back({"seed " + std::to_string(input.first_seed + i), building_bounds(*d),
                          [&input, &d] { return derived_triangles(*d, *input.primitives); }});
  RasterView view = input.view;
  if (const std::optional<glm::dvec3> front = elevation_eye(examples)) {
    view.eye = *front;
    // Elevations of facades taller than wide (most of a city's) get
    // pictures taller than wide, so the facade fills more of its picture.
    double tall = 0;
    for (const Example& e : examples) {
      const glm::dvec3 size = e.max - e.min;
      tall += size.z > std::max(size.x, size.y) ? 1 : 0;
    }
    if (tall * 2 > static_cast<double>(examples.size()) && view.width > view.height) std::swap(view.width, view.height);
  }
  std::vector<ReportPicture> pictures = draw_at_one_scale(drawings, view, input.threads);

  ReportGallery examples_gallery;
  examples_gallery.title = shown == examples.size()
                               ? "Examples (" + std::to_string(examples.size()) + ")"
                               : "Examples (the first " + std::to_string(shown) + " of " +
                                     std::to_string(examples.size()) + ")";
  examples_gallery.pictures.assign(std::make_move_iterator(pictures.begin()),
                                   std::make_move_iterator(pictures.begin() + static_cast<std::ptrdiff_t>(shown)));
  ReportGallery new_gallery;
  new_gallery.title = "New buildings of the grammar (seeds " + std::to_string(input.first_seed) + " to " +
                      std::to_string(input.first_seed + input.new_buildings - 1) + ")";
  new_gallery.pictures.assign(std::make_move_iterator(pictures.begin() + static_cast<std::ptrdiff_t>(shown)),
                              std::make_move_iterator(pictures.end()));
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
