// Many buildings from one grammar: parallel derivation and layout.
//
// Variant i is derived with seed (seed + i), so `--seed 14 -n 1` gives
// exactly variant 7 of `--seed 7`, and the results are the same whatever
// the thread count: each variant is a pure function of its seed.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "forward/derive.hpp"

namespace vern {

struct VariantOptions {
  DeriveOptions derive;       // derive.seed is the first variant's seed
  std::uint32_t count = 1;
  unsigned threads = 1;       // 0: one per core
  // Called from the deriving threads as variants finish (done, total); may
  // be empty. Used for progress lines.
  std::function<void(std::uint32_t, std::uint32_t)> progress;
};

// Derives every variant. If any derivation fails, the error of the lowest
// failing variant index is thrown (so the message does not depend on which
// thread finished first), after all threads have stopped.
std::vector<Derivation> derive_variants(const Grammar& grammar, const VariantOptions& options);

// The same, up to `batch` variants at a time (fewer when they are large:
// a batch holds some 64 MB of terminals, one variant per thread at least),
// each given to take(index, ...) in index order once its batch is done, so
// that only one batch is held (generate -n 5000 writes as it derives). The error thrown is the one
// derive_variants throws; the variants before it have been taken.
void derive_variants_in_order(const Grammar& grammar, const VariantOptions& options, std::uint32_t batch,
                              const std::function<void(std::uint32_t, Derivation&&)>& take);

// Each variant's start-scope size, as its derivation will have it, without
// deriving. Throws the error derive_variants would throw when one of them
// cannot be drawn.
std::vector<glm::dvec3> start_sizes(const Grammar& grammar, const VariantOptions& options);

// Where lay_out places variants of these start sizes.
std::vector<glm::dvec3> layout_offsets(const std::vector<glm::dvec3>& sizes, double spacing);

// Places derivations on a grid seen from above (columns along x, rows along
// y, about square), each variant's start scope separated by `spacing`
// metres, named variant_000, variant_001, ...
Scene lay_out(std::vector<Derivation> derivations, double spacing);

// One variant alone at the origin (for one-file-per-variant output).
Scene single(Derivation derivation, std::uint32_t index);

// "variant_007": the name of variant i.
std::string variant_name(std::uint32_t index);

}  // namespace vern
