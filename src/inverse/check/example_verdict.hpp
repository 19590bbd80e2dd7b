// The verdict on one example as a file gave it: does the grammar derive
// it, taken as infer takes examples?
//
// check_example() matches boxes already at the origin. An example as read
// is first taken as infer takes it: parts set into parts, or painted over
// one another (`stack`, bottom to top), each keep what is visible of them
// (layered_parts.hpp); given a noise level (options.tolerance), its
// coordinates are snapped to it (snapped_coordinates.hpp), and where the
// snapped example does not derive, the example as read is tried (a
// grammar infer made from it as read, the snapped coordinates giving
// none). `check` and the library's check() give the same verdicts.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "inverse/check/check.hpp"
#include "inverse/load/example.hpp"

namespace vern {

// On a plot of `scope` (default: the example's own extent), its lowest
// corner at the example's. Derivable after snapping, the witness starts
// with how far coordinates moved. Throws as check_example() does; Limit
// and Input errors name the example's file.
CheckResult example_verdict(const Grammar& grammar, const Example& loaded, const std::vector<std::string>& stack,
                            const std::optional<glm::dvec3>& scope, const CheckOptions& options);

}  // namespace vern
