#include "forward/plain_number.hpp"

namespace vern {

namespace {

constexpr std::uint64_t kExactWhole = std::uint64_t{1} << 53;

// The powers of ten a double holds exactly.
constexpr double kPowersOfTen[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                   1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
constexpr int kMaxFraction = 22;

bool is_digit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

const char* scan_plain_decimal(const char* p, const char* end, double& value) {
  const bool negative = p != end && *p == '-';
  if (negative) ++p;
  if (p == end || !is_digit(*p)) return nullptr;
  std::uint64_t whole = 0;
  int fraction = 0;
  for (; p != end && is_digit(*p); ++p) {
    whole = whole * 10 + static_cast<std::uint64_t>(*p - '0');
    if (whole > kExactWhole) return nullptr;
  }
  if (p != end && *p == '.') {
    ++p;
    if (p == end || !is_digit(*p)) return nullptr;
    for (; p != end && is_digit(*p); ++p) {
      whole = whole * 10 + static_cast<std::uint64_t>(*p - '0');
      if (whole > kExactWhole || ++fraction > kMaxFraction) return nullptr;
    }
  }
  const double magnitude = static_cast<double>(whole) / kPowersOfTen[fraction];
  value = negative ? -magnitude : magnitude;
  return p;
}

const char* scan_plain_index(const char* p, const char* end, std::uint32_t& value) {
  const char* const first = p;
  std::uint32_t v = 0;
  for (; p != end && is_digit(*p); ++p) {
    if (p - first == 9) return nullptr;
    v = v * 10 + static_cast<std::uint32_t>(*p - '0');
  }
  if (p == first) return nullptr;
  value = v;
  return p;
}

}  // namespace vern
