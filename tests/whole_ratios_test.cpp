// whole_ratios: small whole multiples of a unit, found for splits whose
// relative sizes have them, and the same answer as trying every k.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "inverse/sizes/tidy_numbers.hpp"

namespace vern {
namespace {

// Every k from 1 to max_whole, each size checked: the definition.
std::optional<std::vector<double>> every_k(const std::vector<double>& sizes, int max_whole) {
  double smallest = 0;
  for (double s : sizes) {
    if (!(s > 0)) return std::nullopt;
    smallest = smallest == 0 ? s : std::min(smallest, s);
  }
  for (int k = 1; k <= max_whole; ++k) {
    const double unit = smallest / k;
    std::vector<double> out;
    bool ok = true;
    for (double s : sizes) {
      const double n = std::round(s / unit);
      ok = ok && n >= 1 && n <= max_whole && std::abs(s / unit - n) <= 1e-9 * n;
      out.push_back(n);
    }
    if (ok) return out;
  }
  return std::nullopt;
}

TEST(WholeRatios, FindsSmallWholeMultiples) {
  EXPECT_EQ(whole_ratios({2.0, 4.0, 6.0}), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(whole_ratios({1.5, 1.0}), (std::vector<double>{3, 2}));
  EXPECT_EQ(whole_ratios({1.0, 61.0}), std::nullopt);
  EXPECT_EQ(whole_ratios({1.0, -1.0}), std::nullopt);
}

TEST(WholeRatios, WithinATolerancePerCutAsAModellingToolWritesThem) {
  // Six decimals, as Blender writes OBJ: 2 : 1 within 1e-5 m of every cut.
  EXPECT_EQ(whole_ratios({6.666667, 3.333333}, 1e-5), (std::vector<double>{2, 1}));
  EXPECT_EQ(whole_ratios({6.666667, 3.333333}), std::nullopt);  // to 1e-9 relative they are not
  EXPECT_EQ(whole_ratios({4.666667, 2.333333, 7.000001}, 1e-5), (std::vector<double>{2, 1, 3}));
  // The fewest units that fit: 1 : 1, not 60 : 60.
  EXPECT_EQ(whole_ratios({3.0000004, 2.9999996}, 1e-5), (std::vector<double>{1, 1}));
  // 2 : 1 of 3.00004 m puts the cut at 2.0000267, 1.3e-5 from 2.00004:
  // beyond a tolerance of 1e-5 (and 2.00002 : 1, 6.7e-6 off, is within).
  EXPECT_EQ(whole_ratios({2.00004, 1.0}, 1e-5), std::nullopt);
  EXPECT_EQ(whole_ratios({2.00002, 1.0}, 1e-5), (std::vector<double>{2, 1}));
}

TEST(WholeRatios, AgreesWithTryingEveryK) {
  std::mt19937_64 rng(3);
  for (int i = 0; i < 20000; ++i) {
    const std::size_t n = 1 + rng() % 6;
    const double unit = 0.001 * static_cast<double>(1 + rng() % 5000);
    std::vector<double> sizes;
    for (std::size_t j = 0; j < n; ++j) {
      // Whole multiples, some beyond 60, some with noise, some random.
      const auto kind = rng() % 4;
      const double whole = static_cast<double>(1 + rng() % 80);
      if (kind == 0) sizes.push_back(unit * whole);
      else if (kind == 1) sizes.push_back(unit * whole * (1 + 1e-12 * static_cast<double>(rng() % 100)));
      else if (kind == 2) sizes.push_back(unit * static_cast<double>(1 + rng() % 12) / 7);
      else sizes.push_back(0.001 * static_cast<double>(1 + rng() % 9000));
    }
    EXPECT_EQ(whole_ratios(sizes), every_k(sizes, 60)) << i;
  }
}

}  // namespace
}  // namespace vern
