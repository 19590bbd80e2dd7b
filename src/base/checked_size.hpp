// Sizes computed from numbers a file gives (counts, offsets, strides).
//
// A hostile file picks them so that a product or sum wraps round past 2^64
// into a small value that passes a range check (a glTF accessor of 2^62+24
// elements of 12 bytes "ends" at byte 276). Arithmetic on such numbers is
// done here, where it says when the true result does not fit.
#pragma once

#include <cstddef>
#include <optional>

namespace vern {

// a + b, or nothing when the sum does not fit in std::size_t.
inline std::optional<std::size_t> checked_add(std::size_t a, std::size_t b) {
  std::size_t sum = 0;
  if (__builtin_add_overflow(a, b, &sum)) return std::nullopt;
  return sum;
}

// a * b, or nothing when the product does not fit in std::size_t.
inline std::optional<std::size_t> checked_mul(std::size_t a, std::size_t b) {
  std::size_t product = 0;
  if (__builtin_mul_overflow(a, b, &product)) return std::nullopt;
  return product;
}

}  // namespace vern
