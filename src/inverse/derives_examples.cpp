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

bool check_passes(const Grammar& g, const std::vector<Example>& examples, double tolerance, unsigned threads) {
  std::vector<char> derivable(examples.size(), 0);
  parallel_for(examples.size(), threads, [&](std::size_t i) {
    CheckOptions check;
    check.tolerance = example_tolerance(examples[i], tolerance);
    check.witness = false;
    const Example placed = at_origin(examples[i]);
    try {
      derivable[i] = check_example(g, placed.boxes, example_size(placed), check).derivable;
    } catch (const Error&) {
      derivable[i] = 0;  // too many steps: not derivable as far as we know
    }
  });
  return std::ranges::all_of(derivable, [](char d) { return d != 0; });
}

}  // namespace vern
