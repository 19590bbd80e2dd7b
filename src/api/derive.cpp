// derive and derive_many: the forward engine's derivations as Buildings.
#include "vernacular/derive.hpp"

#include "api/api_data.hpp"
#include "api/buildings.hpp"
#include "forward/derive.hpp"
#include "forward/shards.hpp"
#include "forward/variants.hpp"

namespace vernacular {

namespace {

vern::DeriveOptions internal_options(const DeriveOptions& options) {
  vern::DeriveOptions o;
  o.seed = options.seed;
  o.limits.max_depth = options.max_depth;
  o.limits.max_terminals = options.max_parts;
  o.limits.max_operations = options.max_operations;
  o.strict = options.strict;
  if (options.plot) o.size = glm::dvec3((*options.plot)[0], (*options.plot)[1], (*options.plot)[2]);
  return o;
}

}  // namespace

Building derive(const Grammar& grammar, const DeriveOptions& options) {
  return detail::guarded(
      [&] { return detail::building_of(vern::derive(grammar.data().grammar, internal_options(options))); });
}

std::vector<Building> derive_many(const Grammar& grammar, std::uint32_t count, const DeriveOptions& options,
                                  unsigned threads) {
  return detail::guarded([&] {
    vern::VariantOptions o;
    o.derive = internal_options(options);
    o.count = count;
    o.threads = threads;
    std::vector<Building> out;
    out.reserve(count);
    for (vern::Derivation& d : vern::derive_variants(grammar.data().grammar, o)) out.push_back(detail::building_of(d));
    return out;
  });
}

Slice shard(std::uint32_t total, std::uint32_t k, std::uint32_t n) {
  return detail::guarded([&] {
    if (k < 1 || k > n)
      vern::fail(vern::ErrorKind::Usage, "", {}, "shard " + std::to_string(k) + " of " + std::to_string(n) + " is none",
                 "shards are numbered 1 to n");
    const vern::Slice s = vern::shard_slice(total, {k, n});
    return Slice{s.first, s.count};
  });
}

}  // namespace vernacular
