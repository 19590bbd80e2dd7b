#include "eval/evaluation.hpp"

#include <algorithm>

#include "forward/layout_faults.hpp"
#include "forward/variants.hpp"
#include "graph/writer.hpp"
#include "inverse/check/check.hpp"
#include "inverse/infer.hpp"
#include "inverse/load/derived_example.hpp"

namespace vern {

namespace {

std::vector<Derivation> sample(const Grammar& g, std::uint64_t seed, std::uint32_t count, unsigned threads) {
  VariantOptions o;
  o.derive.seed = seed;
  o.count = count;
  o.threads = threads;
  return derive_variants(g, o);
}

// Novelty: a variant whose parts all lie within 1e-5 of the largest
// example's size of an example's is that example: ten times the examples'
// own tolerance, far above the rounding of inferred numbers (a quarter of
// it), far below any difference a person would see.
double sameness_tolerance(const std::vector<Example>& examples) {
  double largest = 0;
  for (const Example& e : examples) {
    const glm::dvec3 s = example_size(e);
    largest = std::max({largest, s.x, s.y, s.z});
  }
  return std::max(1e-12, 1e-5 * largest);
}

}  // namespace

Evaluation evaluate_inference(const Grammar& source, const EvaluationOptions& options) {
  Evaluation e;
  e.source = description_length(source);
  e.examples = options.examples;
  e.variants = options.variants;

  const std::vector<Derivation> derived = sample(source, 1, options.examples, options.threads);
  std::vector<Example> examples;
  for (std::size_t i = 0; i < derived.size(); ++i) {
    examples.push_back(example_from_derivation(derived[i], "example_" + std::to_string(i + 1)));
  }
  InferOptions infer_options;
  infer_options.uniform_distributions = options.uniform_distributions;
  const Inference learnt = infer(examples, infer_options);
  e.inferred = description_length(learnt.grammar);
  e.inferred_text = write_grammar(learnt.grammar);
  e.inferred_lines = static_cast<std::size_t>(std::count(e.inferred_text.begin(), e.inferred_text.end(), '\n'));

  for (const Example& example : examples) {
    const Example placed = at_origin(example);
    const CheckResult r = check_example(learnt.grammar, placed.boxes, example_size(placed));
    if (r.derivable) {
      ++e.reproduced;
    } else if (e.first_unreproduced.empty()) {
      e.first_unreproduced = example.source + ": " + r.mismatch;
    }
  }

  const std::vector<Derivation> variants = sample(learnt.grammar, 1001, options.variants, options.threads);
  const std::vector<Derivation> reference = sample(source, 1001, options.variants, options.threads);
  const std::vector<Derivation> more = sample(source, 2001, options.variants, options.threads);

  for (const Derivation& d : variants) {
    const LayoutFaults f = find_faults(d);
    if (f.valid()) {
      ++e.valid;
    } else if (e.first_fault.empty()) {
      e.first_fault = f.first;
    }
  }
  for (const Derivation& d : reference) e.source_valid += find_faults(d).valid() ? 1 : 0;

  // Examples as the learnt grammar places them: at the origin.
  const double tolerance = sameness_tolerance(examples);
  std::vector<Derivation> placed = derived;
  for (std::size_t i = 0; i < placed.size(); ++i) {
    for (Terminal& t : placed[i].terminals) t.scope.origin -= examples[i].min;
  }
  for (const Derivation& d : variants) {
    const bool copy = std::any_of(placed.begin(), placed.end(),
                                  [&](const Derivation& x) { return same_layout(d, x, tolerance); });
    e.novel += copy ? 0 : 1;
  }
  e.source_varies = std::any_of(reference.begin() + 1, reference.end(), [&](const Derivation& d) {
    return !same_layout(d, reference.front(), tolerance);
  });

  e.distance = style_distance(reference, variants);
  e.noise = style_distance(reference, more);
  return e;
}

}  // namespace vern
