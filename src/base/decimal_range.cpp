#include "base/decimal_range.hpp"

#include <algorithm>
#include <cstdint>

namespace vern {

bool decimal_underflows(std::string_view text) {
  if (!text.empty() && (text[0] == '-' || text[0] == '+')) text.remove_prefix(1);
  const std::string_view mantissa = text.substr(0, text.find_first_of("eE"));
  const std::string_view exponent_text = text.substr(mantissa.size() + (mantissa.size() < text.size() ? 1 : 0));
  // The power of ten of the first digit that is not 0: the magnitude
  // before the exponent (digit k of the mantissa stands for 10^(whole - 1 - k)).
  const auto whole = static_cast<std::int64_t>(std::min(mantissa.find('.'), mantissa.size()));
  std::int64_t k = 0;
  bool found = false;
  for (const char c : mantissa) {
    if (c == '.') continue;
    if (c != '0') {
      found = true;
      break;
    }
    ++k;
  }
  if (!found) return false;  // zero: never out of range
  // The exponent, held within a range far beyond any double's.
  std::int64_t exponent = 0;
  bool negative = false;
  std::size_t at = 0;
  if (at < exponent_text.size() && (exponent_text[at] == '-' || exponent_text[at] == '+'))
    negative = exponent_text[at++] == '-';
  for (; at < exponent_text.size(); ++at)
    exponent = std::min<std::int64_t>(exponent * 10 + (exponent_text[at] - '0'), 1'000'000'000);
  return whole - 1 - k + (negative ? -exponent : exponent) < 0;
}

}  // namespace vern
