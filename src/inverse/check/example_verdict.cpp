#include "inverse/check/example_verdict.hpp"

#include <cstdio>

#include "base/error.hpp"
#include "base/number_format.hpp"
#include "base/out_of_memory.hpp"
#include "inverse/load/layered_parts.hpp"
#include "inverse/load/snapped_coordinates.hpp"

namespace vern {

namespace {

// The verdict on `taken`: the example as read or snapped.
CheckResult verdict(const Grammar& grammar, const Example& loaded, const Example& taken,
                    const std::vector<std::string>& stack, const std::optional<glm::dvec3>& scope,
                    const CheckOptions& options) {
  const std::string& file = loaded.source;
  // Snapped (snapped_coordinates.hpp), coordinates apart are places
  // apart, cut within float noise; sizes fit within the noise level.
  const bool snap = taken.snapped > 0;
  const Example example = visible_parts(taken, Layering{stack, default_tolerance(loaded)});
  std::vector<LabelledBox> boxes = example.boxes;
  for (auto& b : boxes) {
    b.min -= example.min;
    b.max -= example.min;
  }
  // As read, within its float noise (from where the file put it, before
  // it was moved to the origin), as infer took it without a level.
  CheckOptions own = options;
  own.tolerance = snap ? options.tolerance : default_tolerance(loaded);
  if (snap) own.cut_tolerance = default_tolerance(loaded);
  try {
    return naming_out_of_memory(file, "while checking this example", "check it alone, or lower --max-steps", [&] {
      return check_example(grammar, boxes, scope.value_or(example_size(example)), own);
    });
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::Limit && e.kind() != ErrorKind::Input) throw;
    throw Error(e.kind(), naming_input(e.what(), file));
  }
}

}  // namespace

CheckResult example_verdict(const Grammar& grammar, const Example& loaded, const std::vector<std::string>& stack,
                            const std::optional<glm::dvec3>& scope, const CheckOptions& options) {
  // Given a noise level, the example is taken as infer takes it, snapped;
  // a grammar infer made from it as read (where the snapped coordinates
  // gave none) derives it as read.
  const std::optional<Example> snapped =
      options.tolerance > 0 ? std::optional<Example>(snapped_coordinates(loaded, options.tolerance)) : std::nullopt;
  CheckResult r = verdict(grammar, loaded, snapped ? *snapped : loaded, stack, scope, options);
  const bool derived_snapped = snapped && r.derivable;
  if (snapped && !r.derivable) {
    CheckResult as_read = verdict(grammar, loaded, loaded, stack, scope, options);
    if (as_read.derivable) r = std::move(as_read);
  }
  if (derived_snapped) {
    const double moved = largest_move(loaded, *snapped);
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", moved);
    if (moved > 0)
      r.witness.insert(r.witness.begin(), "coordinates moved by up to " + std::string(text) +
                                              " m onto places within the noise level " +
                                              format_number(options.tolerance) + " m");
  }
  return r;
}

}  // namespace vern
