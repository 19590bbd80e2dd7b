// The hash functions outputs depend on, in one place: changing any of them
// changes what Vernacular writes (a seed's buildings, a label's colour,
// which values inference lines up), so each is fixed, written out here,
// and never std::hash (which may differ between standard libraries).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace vern {

// SplitMix64's finaliser: a bijective, well-mixed 64-bit hash. Random
// draws are keyed with it (forward/random_stream.hpp): a seed's buildings
// depend on every bit of it.
constexpr std::uint64_t mix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Mixes v into seed (boost-style, 64-bit): every structural hash of the
// operation graph (graph/structural.hpp), so the order inference meets
// equal parts in.
inline std::size_t hash_combine(std::size_t seed, std::size_t v) {
  return seed ^ (v + 0x9e3779b97f4a7c15ULL + (seed << 12) + (seed >> 4));
}

// FNV-1a, 32-bit: a label's colour in written files (io/palette.cpp), the
// same across runs and builds.
constexpr std::uint32_t fnv1a(std::string_view s) {
  std::uint32_t h = 2166136261u;
  for (char c : s) {
    h ^= static_cast<unsigned char>(c);
    h *= 16777619u;
  }
  return h;
}

// One step of a path through a graph: the parent's hash and the step's
// own number (inverse/check/check.hpp, derivation_path: where values seen at
// one place in every example are lined up).
constexpr std::uint64_t path_hash(std::uint64_t parent, std::uint64_t step) {
  std::uint64_t h = parent * 0x9e3779b97f4a7c15ULL + step;
  h ^= h >> 31;
  h *= 0xbf58476d1ce4e5b9ULL;
  return h ^ (h >> 29);
}

}  // namespace vern
