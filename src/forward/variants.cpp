#include "forward/variants.hpp"

#include <cmath>
#include <cstdio>

#include "forward/program.hpp"
#include "graph/parallel_for.hpp"

namespace vern {

std::string variant_name(std::uint32_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "variant_%03u", index);
  return name;
}

std::vector<Derivation> derive_variants(const Grammar& grammar, const VariantOptions& options) {
  const std::uint32_t n = options.count;
  std::vector<Derivation> out(n);
  // Compiled once, read by every thread.
  const Program program = compile(grammar);
  parallel_for(
      n, options.threads,
      [&](std::size_t i) {
        DeriveOptions o = options.derive;
        o.seed = options.derive.seed + i;
        out[i] = derive(program, o);
      },
      [&](std::size_t finished) {
        if (options.progress) options.progress(static_cast<std::uint32_t>(finished), n);
      });
  return out;
}

Scene lay_out(std::vector<Derivation> derivations, double spacing) {
  Scene scene;
  if (derivations.empty()) return scene;
  scene.labels = derivations.front().labels;
  const auto n = static_cast<std::uint32_t>(derivations.size());
  const auto columns = static_cast<std::uint32_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  // Each column is as wide as its widest scope and each row as deep as its
  // deepest, so variants of different sizes never overlap.
  std::vector<double> width(columns, 0.0), depth((n + columns - 1) / columns, 0.0);
  for (std::uint32_t i = 0; i < n; ++i) {
    width[i % columns] = std::max(width[i % columns], derivations[i].start.size.x);
    depth[i / columns] = std::max(depth[i / columns], derivations[i].start.size.y);
  }
  std::vector<double> x0(columns, 0.0), y0(depth.size(), 0.0);
  for (std::size_t c = 1; c < columns; ++c) x0[c] = x0[c - 1] + width[c - 1] + spacing;
  for (std::size_t r = 1; r < depth.size(); ++r) y0[r] = y0[r - 1] + depth[r - 1] + spacing;
  for (std::uint32_t i = 0; i < n; ++i) {
    Variant v;
    v.name = variant_name(i);
    v.offset = glm::dvec3(x0[i % columns], y0[i / columns], 0.0);
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
