#include "inverse/check/derives_examples.hpp"

#include <algorithm>

#include "base/error.hpp"
#include "base/parallel_for.hpp"
#include "inverse/load/derived_example.hpp"

namespace vern {

namespace {

// One example at its origin; an example that needs more steps than the
// check allows, or that the grammar cannot derive whatever it draws, is
// not derivable as far as a step knows, unless `limits_throw`: then the
// limit is the answer, the example named. A bug (Internal) is never an
// answer: it goes on to the user.
// Checked in a learned order, an example that fails is asked again in the
// written one, so the answer is never "no" where the written order says "yes".
CheckResult check_placed(const Grammar& g, const Example& placed, const CheckOptions& check,
                         bool limits_throw = false) {
  auto once = [&](CheckOptions options) {
    // Snapped coordinates apart are places apart (Example::snapped).
    if (placed.snapped > 0 && options.cut_tolerance <= 0) options.cut_tolerance = default_tolerance(placed);
    try {
      return check_example(g, placed.boxes, example_size(placed), options);
    } catch (const Error& e) {
      if (e.kind() == ErrorKind::Internal) throw;
      if (limits_throw && e.kind() == ErrorKind::Limit) throw Error(e.kind(), naming_input(e.what(), placed.source));
      return CheckResult{};
    }
  };
  CheckResult r = once(check);
  if (r.derivable || !check.learned_order) return r;
  CheckOptions written = check;
  written.learned_order = false;
  return once(written);
}

// The examples' indices, those with the most boxes first: checked in that
// order on two threads, the last to finish is a small one (the city's
// largest example takes half again as many steps as its smallest).
std::vector<std::size_t> largest_first(const std::vector<Example>& examples) {
  std::vector<std::size_t> order(examples.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return examples[a].boxes.size() > examples[b].boxes.size(); });
  return order;
}

}  // namespace

bool derives_examples(const Grammar& g, const std::vector<Example>& placed, const CheckOptions& check, unsigned threads,
                      std::vector<CheckResult>& results) {
  results.assign(placed.size(), {});
  const std::vector<std::size_t> order = largest_first(placed);
  parallel_for(placed.size(), threads, [&](std::size_t k) {
    const std::size_t i = order[k];
    results[i] = check_placed(g, placed[i], check);
  });
  return std::ranges::all_of(results, [](const CheckResult& r) { return r.derivable; });
}

bool derives_examples(const Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options,
                      std::vector<CheckResult>& results) {
  std::vector<Example> placed;
  for (const Example& e : examples) placed.push_back(boxes_at_origin(e));
  CheckOptions check;
  check.tolerance = options.tolerance;
  check.witness = false;
  return derives_examples(g, placed, check, options.threads, results);
}

bool witnesses_of(const Grammar& g, const std::vector<Example>& examples, const RewriteCheck& options, Witnesses& w) {
  if (!w.known) {
    w.derivable = derives_examples(g, examples, options, w.results);
    w.known = true;
  }
  return w.derivable;
}

std::optional<NotDerived> first_not_derived(const Grammar& g, const std::vector<Example>& examples, double tolerance,
                                            unsigned threads) {
  auto options = [&](const Example& e) {
    CheckOptions check;
    check.tolerance = example_tolerance(e, tolerance);
    check.witness = false;
    return check;
  };
  std::vector<char> derivable(examples.size(), 0);
  const std::vector<std::size_t> order = largest_first(examples);
  parallel_for(examples.size(), threads, [&](std::size_t k) {
    const std::size_t i = order[k];
    CheckOptions check = options(examples[i]);
    check.learned_order = true;  // only the answer is kept
    check.answer_only = true;
    derivable[i] = check_placed(g, boxes_at_origin(examples[i]), check, true).derivable;
  });
  const auto failed = std::ranges::find(derivable, 0);
  if (failed == derivable.end()) return std::nullopt;
  // Asked again, once, for the reason.
  const auto i = static_cast<std::size_t>(failed - derivable.begin());
  return NotDerived{i, check_placed(g, boxes_at_origin(examples[i]), options(examples[i])).mismatch};
}

}  // namespace vern
