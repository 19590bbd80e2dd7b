// Inference as one call: labelled examples in, a readable grammar and the
// primitive meshes it needs out (thesis chapters 9-11).
//
//   examples -> ordered-box split per example (box_split, split_graph)
//            -> one interned graph, merged (merge)
//            -> numbers a person would write (tidy_numbers)
//            -> named rules (rule_naming)
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "forward/primitive_library.hpp"
#include "graph/grammar.hpp"
#include "inverse/load/example.hpp"
#include "inverse/merge/twin_rules.hpp"
#include "inverse/sizes/joint_sizes.hpp"

namespace vern {

struct InferOptions {
  // Coordinates closer than this (metres) are the same coordinate; 0 means
  // 1e-6 of the largest example's extent or coordinate (see default_tolerance).
  // Given (> 0), it is the examples' noise level: each example's
  // coordinates are snapped to one within it first (snapped_coordinates.hpp),
  // as check snaps them.
  double tolerance = 0;
  std::string start = "building";
  // `--distributions uniform`: varying sizes as rand(min, max), the
  // thesis's ranges, instead of fitted distributions.
  bool uniform_distributions = false;
  // Sizes that vary together drawn once (joint_sizes.hpp); false: each
  // size drawn on its own (`--sizes independent`).
  bool joint_sizes = true;
  // Twin subgraphs (equal but for numbers or axes) as one rule with
  // parameters (twin_rules.hpp); false: each copy written out
  // (`--twins apart`).
  bool twin_rules = true;
  // The meshes parts are compared with to find turned ones (--primitives);
  // null: the built-in primitives. A label's first part's own mesh stands
  // in where the library's is not one of its turns.
  const PrimitiveLibrary* primitives = nullptr;
  // Labels bottom to top (--stack): of two overlapping parts, the later
  // label is painted over the earlier and the earlier keeps what is
  // visible of it (layered_parts.hpp). Parts inside others need no order.
  std::vector<std::string> stack;
  // Threads that split examples (0: one per core); the result is the same.
  unsigned threads = 0;
  // Called as examples are split: (done, total), one call at a time.
  std::function<void(std::size_t, std::size_t)> progress;
};

struct Inference {
  Grammar grammar;               // rules, start rule, @scope (not @primitives)
  PrimitiveLibrary primitives;   // each label's canonical mesh, in the unit box (orientation.hpp)
  double tolerance = 0;          // the tolerance used
  JointSizes joint;              // sizes drawn once for several parts (joint_sizes.hpp)
  TwinRules twins;               // copies written as calls of one parameterised rule (twin_rules.hpp)
  std::size_t unturned_parts = 0;  // parts whose mesh is no turn of their label's: written unturned
  // "file:line:1: warning: ...\n  hint: ...", one per group of parts that no
  // straight cut separates (placed with S(...), split_graph.hpp), in
  // example order.
  std::vector<std::string> warnings;
};

// Throws vern::Error (Input) for examples that cannot be represented
// (overlapping parts, parts that neither straight cuts nor placements
// separate), naming the file and the objects.
Inference infer(const std::vector<Example>& examples, const InferOptions& options);

}  // namespace vern
