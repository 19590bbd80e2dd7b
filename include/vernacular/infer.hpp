// Inference: example buildings in, a grammar of their style out.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "vernacular/grammar.hpp"
#include "vernacular/io.hpp"

namespace vernacular {

struct InferOptions {
  // Coordinates closer than this (metres) are one; 0: the examples' own
  // float precision. Given, it is their noise level: coordinates are
  // snapped to it first.
  double tolerance = 0;
  std::string start = "building";  // the start rule's label
  // Varying sizes as rand(min, max) over the values seen, instead of the
  // best fitting distribution.
  bool uniform_distributions = false;
  // Sizes the examples vary together drawn once (slower: every example is
  // checked); false: each size drawn on its own.
  bool joint_sizes = true;
  // Parts built alike but for some numbers as one rule with parameters.
  bool twin_rules = true;
  // Labels bottom to top: of two overlapping parts, the later is painted
  // over the earlier, which keeps what is visible of it. Parts inside
  // others need no order.
  std::vector<std::string> stack;
  unsigned threads = 0;  // 0: one per core; the result is the same
};

struct InferResult {
  // Derives every example and buildings in their style. It holds its
  // parts' meshes (each label's, from the examples): write_buildings uses
  // them, save() writes them beside the grammar.
  Grammar grammar;
  double tolerance = 0;               // the tolerance used, in metres
  std::vector<std::string> warnings;  // what the user should know about the result
  std::size_t examples = 0;

  // Writes the grammar to `file` and the parts' meshes beside it
  // (STYLE.prims.obj and .mtl), which the grammar names, so that the
  // grammar alone regenerates the buildings; all three replaced together.
  // Throws Failure (Io; Usage unless `file` ends in .grm).
  void save(const std::filesystem::path& file) const;
};

// Infers a grammar from examples (at least one). Throws Failure: Usage
// for no examples or a start label that cannot be a rule's, Input for
// examples no straight cut and no stack order can take apart, Limit where
// a limit is reached.
InferResult infer(const std::vector<Example>& examples, const InferOptions& options = {});

}  // namespace vernacular
