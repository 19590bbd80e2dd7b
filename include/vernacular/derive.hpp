// Deriving buildings from a grammar.
//
// derive() is a pure function of (grammar, options): the same grammar, plot
// and seed give the same parts, bit for bit, on any machine and thread.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vernacular/grammar.hpp"

namespace vernacular {

using Vec3 = std::array<double, 3>;

// One terminal of a building: a labelled box (a primitive's mesh fills it).
struct Part {
  std::string label;  // the primitive: "window", "wall", ...
  Vec3 origin{};      // the box's corner, in metres (z up)
  // The box's own axes in world space, unit length: x, y and z of the
  // part's frame (a part turned by R(z, 90) has axes[0] = {0, 1, 0}).
  std::array<Vec3, 3> axes{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
  Vec3 size{};        // the box's extent along each of its axes
  // An explicit colour (the grammar's colour(...)), else absent.
  std::optional<std::array<float, 3>> colour;
  friend bool operator==(const Part&, const Part&) = default;
};

struct Building {
  Vec3 plot{};               // the start scope's size: the plot the building stands on, at the origin
  std::vector<Part> parts;   // in derivation order
  std::vector<std::string> warnings;  // what the derivation wants said (a label no rule or mesh knows)
  friend bool operator==(const Building&, const Building&) = default;
};

struct DeriveOptions {
  std::uint64_t seed = 1;
  // The plot's size; absent: the grammar's @scope (drawn with the seed),
  // else 10 x 10 x 10 m.
  std::optional<Vec3> plot;
  // Limits on runaway grammars: nested rule calls, parts, operations run.
  std::uint32_t max_depth = 1000;
  std::uint64_t max_parts = 1'000'000;
  std::uint64_t max_operations = 200'000'000;
  // A label none of whose rules applies is an error (Input), not nothing.
  bool strict = false;
};

// Derives one building. Throws Failure: Input where the grammar cannot be
// evaluated (a type, a division by zero, a negative size; located at the
// grammar's line and column, with the rule chain), Limit where a limit is
// reached.
Building derive(const Grammar& grammar, const DeriveOptions& options = {});

// `count` buildings, the i-th derived with seed options.seed + i, on
// `threads` threads (0: one per core); the same result whatever the
// thread count. Throws as derive() does, for the lowest failing seed.
std::vector<Building> derive_many(const Grammar& grammar, std::uint32_t count, const DeriveOptions& options = {},
                                  unsigned threads = 0);

// Spreading a run over machines, as `generate --shard K/N` does: of a
// run of `total` buildings (the i-th with seed + i), shard k of n
// (1 <= k <= n) is the buildings [first, first + count); the n shards are
// disjoint, in order, cover the run and differ in size by one at most.
// derive_many(grammar, s.count, {seed + s.first, ...}) derives shard k's
// buildings, equal to those of the whole run. Throws Failure (Usage)
// unless 1 <= k <= n.
struct Slice {
  std::uint32_t first = 0;
  std::uint32_t count = 0;
  friend bool operator==(const Slice&, const Slice&) = default;
};
Slice shard(std::uint32_t total, std::uint32_t k, std::uint32_t n);

}  // namespace vernacular
