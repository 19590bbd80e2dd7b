// Plain numbers read straight from text: the fast path of the OBJ reader.
//
// Almost every number in an exported OBJ is a short decimal ("1.802",
// "-0.5", "17"). These scanners read only that plain form, to exactly the
// value std::from_chars gives, and refuse anything else (exponents, a '+',
// ".5", long mantissas) by returning nullptr: the caller then takes its
// general path, which also owns every error message. Inline: a large file
// has tens of millions of numbers, and a call each cost a third of the time.
#pragma once

#include <cstdint>

namespace vern {

namespace plain_number_detail {

// The powers of ten a double holds exactly.
inline constexpr double kPowersOfTen[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                          1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
// Fifteen digits are below 2^53: a whole number a double holds exactly.
inline constexpr int kMaxDigits = 15;

inline bool is_digit(char c) { return static_cast<unsigned char>(c - '0') < 10; }

}  // namespace plain_number_detail

// -?[0-9]+(\.[0-9]+)? of at most 15 digits in all. Such a value is that
// whole number of digits divided by a power of ten, both exact doubles, so
// the one correctly rounded division is the correctly rounded value
// (Clinger's fast path): bit for bit what from_chars returns. Returns the
// end of the number, or nullptr when the text at p is not of this form.
inline const char* scan_plain_decimal(const char* p, const char* end, double& value) {
  using namespace plain_number_detail;
  const bool negative = p != end && *p == '-';
  if (negative) ++p;
  const char* const first = p;
  std::uint64_t whole = 0;
  for (; p != end && is_digit(*p); ++p) whole = whole * 10 + static_cast<std::uint64_t>(*p - '0');
  const auto int_digits = p - first;
  if (int_digits == 0) return nullptr;
  long fraction = 0;
  if (p != end && *p == '.') {
    const char* const point = ++p;
    for (; p != end && is_digit(*p); ++p) whole = whole * 10 + static_cast<std::uint64_t>(*p - '0');
    fraction = p - point;
    if (fraction == 0) return nullptr;
  }
  // Checked once at the end: more digits only wrapped `whole`, now ignored.
  if (int_digits + fraction > kMaxDigits) return nullptr;
  const double magnitude = static_cast<double>(whole) / kPowersOfTen[fraction];
  value = negative ? -magnitude : magnitude;
  return p;
}

// [0-9]+ of at most 9 digits (no sign): an OBJ index counted from 1.
// Returns the end of the digits, or nullptr.
inline const char* scan_plain_index(const char* p, const char* end, std::uint32_t& value) {
  using namespace plain_number_detail;
  const char* const first = p;
  std::uint32_t v = 0;
  for (; p != end && is_digit(*p); ++p) v = v * 10 + static_cast<std::uint32_t>(*p - '0');
  if (p == first || p - first > 9) return nullptr;
  value = v;
  return p;
}

}  // namespace vern
