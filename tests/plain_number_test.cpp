// The OBJ reader's plain-number scanners: the same value as from_chars,
// bit for bit, wherever they accept; a refusal for anything else (the
// reader's general path then reads it).
#include "io/plain_number.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cstdint>
#include <random>
#include <string>

namespace vern {
namespace {

// True when scan_plain_decimal accepts the whole text; then it must agree
// with from_chars bit for bit.
bool agrees(const std::string& text) {
  double fast = 0.0;
  const char* end = scan_plain_decimal(text.data(), text.data() + text.size(), fast);
  if (end == nullptr) return false;
  EXPECT_EQ(end, text.data() + text.size()) << text;
  double slow = 0.0;
  std::from_chars(text.data(), text.data() + text.size(), slow);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(fast), std::bit_cast<std::uint64_t>(slow)) << text;
  return true;
}

TEST(PlainNumber, DecimalsReadAsFromCharsDoes) {
  for (const char* s : {"0", "-0", "1", "1.802", "-0.5", "0.1", "0.3", "123456.789", "999999999999999",
                        "0.00000000000001", "3.14159265358979", "-2.71828182845904", "007.50"})
    EXPECT_TRUE(agrees(s)) << s;
  // Random short decimals as the OBJ writer and the layouts write them.
  std::mt19937_64 rng(7);
  for (int i = 0; i < 200000; ++i) {
    std::string s = (rng() & 1) ? "-" : "";
    s += std::to_string(rng() % 1000000);
    const auto decimals = static_cast<int>(rng() % 10);  // 15 digits at most: below 2^53
    if (decimals > 0) {
      s += '.';
      for (int d = 0; d < decimals; ++d) s += static_cast<char>('0' + rng() % 10);
    }
    EXPECT_TRUE(agrees(s)) << s;
  }
}

TEST(PlainNumber, AnythingElseIsRefused) {
  for (const char* s : {"", "-", "+1", ".5", "5.", "1e3", "1E-2", "inf", "nan", "0x10", "9007199254740993",
                        "0.000000000000001", "-2.718281828459045", "--1", "-.5"}) {
    double v = 0.0;
    const std::string text = s;
    const char* end = scan_plain_decimal(text.data(), text.data() + text.size(), v);
    EXPECT_TRUE(end == nullptr || end != text.data() + text.size()) << s;
  }
}

TEST(PlainNumber, IndicesAreNineDigitsAtMost) {
  std::uint32_t v = 0;
  const std::string ok = "123456789", long_one = "1234567890", sign = "-1";
  EXPECT_EQ(scan_plain_index(ok.data(), ok.data() + ok.size(), v), ok.data() + ok.size());
  EXPECT_EQ(v, 123456789u);
  EXPECT_EQ(scan_plain_index(long_one.data(), long_one.data() + long_one.size(), v), nullptr);
  EXPECT_EQ(scan_plain_index(sign.data(), sign.data() + sign.size(), v), nullptr);
}

}  // namespace
}  // namespace vern
