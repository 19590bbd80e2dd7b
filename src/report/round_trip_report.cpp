#include "report/round_trip_report.hpp"

#include <iterator>
#include <optional>

#include "base/error.hpp"
#include "report/building_triangles.hpp"
#include "report/drawings.hpp"

namespace vern {

ReportSection round_trip_section(const RoundTripInput& input) {
  if (!input.source || !input.learnt || !input.primitives)
    throw Error(ErrorKind::Internal, "round_trip_section: both grammars and the meshes are needed");
  ReportSection section;
  section.heading = input.name;
  section.figures = input.figures;
  section.notes = input.notes;
  const auto examples = derive_for_pictures(*input.source, input.example_seed, input.shown, input.threads, section.notes);
  const auto variants = derive_for_pictures(*input.learnt, input.variant_seed, input.shown, input.threads, section.notes);
  std::vector<Drawing> drawings;
  std::size_t drawn_examples = 0;
  for (const auto* set : {&examples, &variants}) {
    const std::uint64_t first = set == &examples ? input.example_seed : input.variant_seed;
    for (std::size_t i = 0; i < set->size(); ++i)
      if (const std::optional<Derivation>& d = (*set)[i]) {
        drawings.push_back({"seed " + std::to_string(first + i), building_bounds(*d),
                            [&input, &d] { return derived_triangles(*d, *input.primitives); }});
        if (set == &examples) ++drawn_examples;
      }
  }
  std::vector<ReportPicture> pictures = draw_at_one_scale(drawings, input.view, input.threads);
  const auto split = pictures.begin() + static_cast<std::ptrdiff_t>(drawn_examples);
  ReportGallery source;
  source.title = "Examples: the source grammar's buildings, seeds " + std::to_string(input.example_seed) + " to " +
                 std::to_string(input.example_seed + input.shown - 1);
  source.pictures.assign(std::make_move_iterator(pictures.begin()), std::make_move_iterator(split));
  ReportGallery learnt;
  learnt.title = "The learnt grammar's buildings, seeds " + std::to_string(input.variant_seed) + " to " +
                 std::to_string(input.variant_seed + input.shown - 1);
  learnt.pictures.assign(std::make_move_iterator(split), std::make_move_iterator(pictures.end()));
  section.galleries.push_back(std::move(source));
  section.galleries.push_back(std::move(learnt));
  section.grammar_name = "The learnt grammar";
  section.grammar_text = input.learnt_text;
  return section;
}

}  // namespace vern
