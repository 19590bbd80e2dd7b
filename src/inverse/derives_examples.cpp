#include "inverse/derives_examples.hpp"

#include <algorithm>

#include "graph/error.hpp"
#include "graph/parallel_for.hpp"

namespace vern {

bool derives_examples(const Grammar& g, const std::vector<Example>& placed, const CheckOptions& check, unsigned threads,
                      std::vector<CheckResult>& results) {
  results.assign(placed.size(), {});
  parallel_for(placed.size(), threads, [&](std::size_t i) {
    try {
      results[i] = check_example(g, placed[i].boxes, example_size(placed[i]), check);
    } catch (const Error&) {
      results[i] = {};  // too many steps: not derivable as far as a step knows
    }
  });
  return std::ranges::all_of(results, [](const CheckResult& r) { return r.derivable; });
}

}  // namespace vern
