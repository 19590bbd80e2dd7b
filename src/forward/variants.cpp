#include "forward/variants.hpp"

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <thread>

#include "base/error.hpp"
#include "base/parallel_for.hpp"
#include "forward/program.hpp"

namespace vern {

std::string variant_name(std::uint32_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "variant_%03u", index);
  return name;
}

namespace {

// Variants first .. first + out.size() - 1, in parallel; throws the error of
// the lowest failing one once all have stopped.
void derive_range(const Program& program, const VariantOptions& options, std::uint32_t first,
                  std::vector<Derivation>& out) {
  parallel_for(
      out.size(), options.threads,
      [&](std::size_t i) {
        DeriveOptions o = options.derive;
        o.seed = options.derive.seed + first + i;
        out[i] = derive(program, o);
      },
      [&](std::size_t finished) {
        if (options.progress) options.progress(static_cast<std::uint32_t>(first + finished), options.count);
      });
}

}  // namespace

std::vector<Derivation> derive_variants(const Grammar& grammar, const VariantOptions& options) {
  std::vector<Derivation> out(options.count);
  // Compiled once, read by every thread.
  derive_range(compile(grammar), options, 0, out);
  return out;
}

void derive_variants_in_order(const Grammar& grammar, const VariantOptions& options, std::uint32_t batch,
                              const std::function<void(std::uint32_t, Derivation&&)>& take) {
  const Program program = compile(grammar);
  const std::uint32_t threads =
      std::max(1u, options.threads != 0 ? options.threads : std::thread::hardware_concurrency());
  batch = std::max(batch, threads);
  // Large buildings come fewer at a time: a batch holds about this many
  // bytes of terminals (but one building per thread at least).
  constexpr double kBatchBytes = 64.0 * (1 << 20);
  std::uint32_t next = batch;
  std::vector<Derivation> held;
  for (std::uint32_t first = 0; first < options.count;) {
    held.assign(std::min(next, options.count - first), Derivation{});
    derive_range(program, options, first, held);
    std::size_t terminals = 0;
    for (std::uint32_t i = 0; i < held.size(); ++i) {
      terminals += held[i].terminals.size();
      take(first + i, std::move(held[i]));
      held[i] = Derivation{};  // its terminals go now, not with the batch
    }
    const double per_variant = static_cast<double>(terminals) * sizeof(Terminal) / static_cast<double>(held.size());
    next = static_cast<std::uint32_t>(std::clamp(kBatchBytes / std::max(per_variant, 1.0), double(threads), double(batch)));
    first += static_cast<std::uint32_t>(held.size());
  }
}

std::vector<glm::dvec3> start_sizes(const Grammar& grammar, const VariantOptions& options) {
  const Program program = compile(grammar);
  std::vector<glm::dvec3> sizes(options.count);
  for (std::uint32_t i = 0; i < options.count; ++i) {
    DeriveOptions o = options.derive;
    o.seed = options.derive.seed + i;
    try {
      sizes[i] = derive_start_size(program, o);
    } catch (const Error&) {
      // A variant before this one may fail first, and its error is the
      // one derive_variants reports: derive them (holding none) to find it.
      VariantOptions before = options;
      before.count = i;
      before.progress = nullptr;
      derive_variants_in_order(grammar, before, 64, [](std::uint32_t, Derivation&&) {});
      throw;
    }
  }
  return sizes;
}

std::vector<glm::dvec3> layout_offsets(const std::vector<glm::dvec3>& sizes, double spacing) {
  const auto n = static_cast<std::uint32_t>(sizes.size());
  if (n == 0) return {};
  const auto columns = static_cast<std::uint32_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  // Each column is as wide as its widest scope and each row as deep as its
  // deepest, so variants of different sizes never overlap.
  std::vector<double> width(columns, 0.0), depth((n + columns - 1) / columns, 0.0);
  for (std::uint32_t i = 0; i < n; ++i) {
    width[i % columns] = std::max(width[i % columns], sizes[i].x);
    depth[i / columns] = std::max(depth[i / columns], sizes[i].y);
  }
  std::vector<double> x0(columns, 0.0), y0(depth.size(), 0.0);
  for (std::size_t c = 1; c < columns; ++c) x0[c] = x0[c - 1] + width[c - 1] + spacing;
  for (std::size_t r = 1; r < depth.size(); ++r) y0[r] = y0[r - 1] + depth[r - 1] + spacing;
  std::vector<glm::dvec3> offsets(n);
  for (std::uint32_t i = 0; i < n; ++i) offsets[i] = glm::dvec3(x0[i % columns], y0[i / columns], 0.0);
  return offsets;
}

Scene lay_out(std::vector<Derivation> derivations, double spacing) {
  Scene scene;
  if (derivations.empty()) return scene;
  scene.labels = derivations.front().labels;
  std::vector<glm::dvec3> sizes;
  for (const Derivation& d : derivations) sizes.push_back(d.start.size);
  const std::vector<glm::dvec3> offsets = layout_offsets(sizes, spacing);
  for (std::uint32_t i = 0; i < derivations.size(); ++i) {
    Variant v;
    v.name = variant_name(i);
    v.offset = offsets[i];
    v.terminals = std::move(derivations[i].terminals);
    scene.variants.push_back(std::move(v));
  }
  return scene;
}

Scene single(Derivation derivation, std::uint32_t index) {
  Scene scene;
  scene.labels = std::move(derivation.labels);
  Variant v;
  v.name = variant_name(index);
  v.terminals = std::move(derivation.terminals);
  scene.variants.push_back(std::move(v));
  return scene;
}

}  // namespace vern
