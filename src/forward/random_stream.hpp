// Path-keyed random numbers.
//
// A draw depends on the seed and on the path from the start rule to the
// node that draws, never on evaluation order (docs/grammar.md, "Derivation and randomness"). Each node
// invocation owns a 64-bit key: the start key comes from the seed, a child's
// key mixes its parent's key with the child's slot (split part, repeat tile,
// chosen option, face). Draws within one node are numbered. So editing one
// branch of a grammar never reshuffles another, and threads cannot change
// results.
#pragma once

#include <cstdint>

#include "base/hashing.hpp"

namespace vern {

// One mix per step: parent keys are themselves mixed, so offsetting them by
// an odd multiple of the slot gives independent-looking children.
constexpr std::uint64_t child_key(std::uint64_t parent, std::uint64_t slot) {
  return mix64(parent + (slot + 1) * 0xd1b54a32d192ed03ULL);
}

// The key of derivation `seed`'s start node; constants and @scope use
// their own branches of it.
constexpr std::uint64_t seed_key(std::uint64_t seed) { return mix64(seed ^ 0x5eed5eed5eed5eedULL); }

class RandomStream {
 public:
  explicit RandomStream(std::uint64_t key) : key_(key) {}

  // Uniform in [0, 1): 53 random bits.
  double uniform() {
    return static_cast<double>(mix64(key_ + (++count_) * 0xaef17502108ef2d9ULL) >> 11) * 0x1.0p-53;
  }

  // Uniform in [a, b].
  double uniform(double a, double b) { return a + (b - a) * uniform(); }

  // Standard normal, by inverting the normal CDF at one uniform draw (one
  // draw per value keeps the numbering simple).
  double normal();

  // Normal(mu, sigma) truncated to [lo, hi], by inverse CDF within the
  // interval's probability mass: exact, and one draw whatever the bounds.
  double truncated_normal(double mu, double sigma, double lo, double hi);

 private:
  std::uint64_t key_;
  std::uint64_t count_ = 0;
};

// The standard normal CDF and its inverse (p in (0, 1)).
double normal_cdf(double x);
double inverse_normal_cdf(double p);

}  // namespace vern
