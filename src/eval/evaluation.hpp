// Judging inference by round trips (issue 4, "Evaluation"): a grammar
// derives k examples; inference learns a grammar from them; the learnt
// grammar must reproduce every example and make new, valid buildings in the
// same style. One call measures all of it for one source grammar.
#pragma once

#include <cstdint>
#include <string>

#include "eval/layout_statistics.hpp"
#include "graph/description_length.hpp"
#include "graph/grammar.hpp"

namespace vern {

struct EvaluationOptions {
  std::uint32_t examples = 10;        // k: derived with seeds 1..k
  std::uint32_t variants = 100;       // n: derived with seeds 1001.. from both grammars
  unsigned threads = 0;               // 0: one per core
  bool uniform_distributions = false; // infer --distributions uniform
};

struct Evaluation {
  std::string inferred_text;          // the learnt grammar as infer writes it
  DescriptionLength source, inferred;
  std::size_t inferred_lines = 0;
  std::uint32_t examples = 0;
  std::uint32_t reproduced = 0;       // examples check accepts
  std::string first_unreproduced;     // check's mismatch for the first one it rejects
  std::uint32_t variants = 0;
  std::uint32_t valid = 0;            // learnt grammar's variants without faults (layout_faults.hpp)
  std::uint32_t source_valid = 0;     // the same for the source grammar's variants
  std::string first_fault;            // the first learnt variant's fault, for the notes
  std::uint32_t novel = 0;            // learnt variants equal to no example
  bool source_varies = false;         // the source's variants are not all one building
  StyleDistance distance;             // source variants vs learnt variants
  StyleDistance noise;                // source variants vs more source variants: the floor
};

// Throws vern::Error when the source grammar cannot derive, or inference
// rejects the examples (e.g. overlapping parts).
Evaluation evaluate_inference(const Grammar& source, const EvaluationOptions& options);

}  // namespace vern
