// Does inference learn the style, or only the examples? (issue 15)
//
// A source grammar derives N examples; a grammar is inferred from them.
//   precision: the share of the inferred grammar's variants that the source
//              grammar derives (check_example with the variant's plot):
//              variants the source could have made;
//   recall:    the share of fresh source samples (other seeds, other
//              plots) that the inferred grammar derives: the source's
//              buildings the inferred style admits.
// Precision is measured on the examples' own plots and on plots 1.5 times
// wider than theirs (a style that only fits the plots it saw is not the
// style). A plot is what inference sees: an example's extent. So the
// inferred grammar's variants are derived on example extents, and fresh
// source samples are checked on their own extents; a source grammar is only
// a fair judge when it derives its own samples on their extents
// (`self_recall`, which should be 1).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "graph/description_length.hpp"
#include "graph/grammar.hpp"

namespace vern {

struct PrecisionRecallOptions {
  std::uint32_t examples = 10;      // N: source samples with seeds 1..N
  std::uint32_t samples = 40;       // variants judged for precision; fresh source samples for recall
  double wider = 1.5;               // the unseen plots: example extents this many times wider along x
  unsigned threads = 0;             // 0: one per core; the results are the same
  std::uint64_t max_check_steps = 2'000'000;  // per check; beyond it the building counts as not derived
};

// A count out of a total, and the first failure for the notes.
struct Share {
  std::uint32_t hits = 0, total = 0;
  std::uint32_t undecided = 0;  // checks that hit the step limit or could not decide (counted as misses)
  std::string first_miss;       // "seed 1004: <check's mismatch>"
  double value() const { return total == 0 ? 0.0 : static_cast<double>(hits) / total; }
};

struct PrecisionRecall {
  std::uint32_t examples = 0;
  std::uint32_t reproduced = 0;      // examples the inferred grammar derives (must be all)
  std::string first_unreproduced;
  DescriptionLength inferred;
  std::size_t inferred_lines = 0;
  std::string inferred_text;
  Share precision;        // inferred variants on the examples' plots, derived by the source
  Share precision_wider;  // inferred variants on plots `wider` times as wide
  Share recall;           // fresh source samples derived by the inferred grammar
  std::uint32_t invalid = 0;  // inferred variants (both plot sets) with overlapping or outside parts
  std::string first_invalid;
};

// Throws vern::Error when the source cannot derive or inference rejects the
// examples.
PrecisionRecall precision_recall(const Grammar& source, const PrecisionRecallOptions& options);

// Fresh source samples (seeds from 5001) that the source itself derives on
// their extents: whether `source` can judge precision and recall at all.
Share self_recall(const Grammar& source, const PrecisionRecallOptions& options);

}  // namespace vern
