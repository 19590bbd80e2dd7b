// A repeat's drawn tile size read from the tiles it gave, and a count that
// is a line of a size written as a person writes it.
#include "inverse/sizes/tile_draws.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "graph/grammar.hpp"
#include "graph/writer.hpp"

namespace vern {
namespace {

// Runs of a repeat(z, s), s drawn from [2.8, 3.6], on lengths of 8 to 16 m.
std::vector<TileRun> storeys(std::size_t count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> size(2.8, 3.6), length(8, 16);
  std::vector<TileRun> runs;
  for (std::size_t k = 0; k < count; ++k) {
    const double s = size(rng), l = length(rng), n = std::max(1.0, std::ceil(l / s));
    runs.push_back({l / n, n});
  }
  return runs;
}

std::vector<Observation> lengths_of(const std::vector<TileRun>& runs) {
  std::vector<Observation> out;
  for (const TileRun& r : runs) out.push_back({r.length, 1});
  return out;
}

TEST(TileDraws, TheDrawSpansTheSizesThatGaveTheTilesNotTheTiles) {
  const std::vector<TileRun> runs = storeys(30, 7);
  double shortest = 10;
  for (const TileRun& r : runs) shortest = std::min(shortest, r.length);
  ASSERT_LT(shortest, 2.7);  // tiles shorter than any size drawn
  const Distribution d = tile_size_distribution(runs, lengths_of(runs), {}, 1e-6);
  ASSERT_EQ(d.kind, DistributionKind::Uniform);
  EXPECT_GE(d.lo, 2.7);
  EXPECT_LE(d.hi, 3.7);
  EXPECT_GT(d.hi - d.lo, 0.5);
  // Every building's count is one the range gives: some size in it makes
  // exactly that many tiles.
  for (const TileRun& r : runs) {
    const double from = std::max(d.lo, r.length), to = std::min(d.hi, r.length * r.count / (r.count - 1));
    EXPECT_LT(from, to) << r.length << " x " << r.count;
  }
}

TEST(TileDraws, ARunOfOneTileLeavesTheLengthsToBeFitted) {
  std::vector<TileRun> runs = storeys(10, 3);
  runs.push_back({3.1, 1});
  const Distribution d = tile_size_distribution(runs, lengths_of(runs), {}, 1e-6);
  const Distribution fitted = fit_distribution(lengths_of(runs), {});
  EXPECT_EQ(d.kind, fitted.kind);
  EXPECT_EQ(d.lo, fitted.lo);
  EXPECT_EQ(d.hi, fitted.hi);
}

TEST(TileDraws, ACountOverAShortDivisorIsWrittenAsADivision) {
  Grammar g;
  Linear before, after;
  before.add(0, 1 / 4.4);
  after.c0 = 5;
  after.add(0, -1 / 4.4);
  EXPECT_EQ(write_expression(g, count_line_expr(before), {"s1"}), "s1 / 4.4");
  EXPECT_EQ(write_expression(g, count_line_expr(after), {"s1"}), "5 - s1 / 4.4");
  Linear odd;  // no short divisor: as linear_expr writes it
  odd.add(0, 0.3);
  EXPECT_EQ(write_expression(g, count_line_expr(odd), {"s1"}), "0.3 * s1");
}

}  // namespace
}  // namespace vern
