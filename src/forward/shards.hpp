// Spreading one run's buildings over machines: `generate --shard K/N`.
//
// A run of `count` buildings (building i derived with seed + i) is cut
// into N slices of consecutive buildings, as equal as whole buildings
// allow; shard K (1..N) derives and writes slice K only, each building
// under its own index and, in a one-file layout, at its place in the
// whole run's layout. N shards run anywhere write together exactly the
// files, and the buildings, of the one run.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace vern {

struct Shard {
  std::uint32_t index = 1;  // K, 1-based
  std::uint32_t count = 1;  // N
};

// "K/N" with 1 <= K <= N; nullopt for anything else.
std::optional<Shard> parse_shard(std::string_view text);

struct Slice {
  std::uint32_t first = 0;  // the first building's index in the run
  std::uint32_t count = 0;  // how many
};

// Shard K's buildings of a run of `total`: [floor((K-1) total / N),
// floor(K total / N)). Slices are disjoint, in order, cover the run, and
// differ in size by one at most (some are empty when N > total).
Slice shard_slice(std::uint32_t total, Shard shard);

}  // namespace vern
