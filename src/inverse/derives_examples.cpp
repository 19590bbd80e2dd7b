#include "inverse/derives_examples.hpp"

#include <algorithm>

#include "graph/error.hpp"
#include "graph/parallel_for.hpp"
#include "inverse/derived_example.hpp"

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

bool derives_examples(const Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options,
                      std::vector<CheckResult>& results) {
  std::vector<Example> placed;
  for (const Example& e : examples) placed.push_back(at_origin(e));
  CheckOptions check;
  check.tolerance = options.tolerance;
  check.witness = false;
  return derives_examples(g, placed, check, options.threads, results);
}

}  // namespace vern
