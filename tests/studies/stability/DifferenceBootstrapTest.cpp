// The dry-wet difference counts per frequency over seed resamples
// (studies/stability/DifferenceBootstrap.hpp), on synthetic grids whose seed votes are known.
// Expected from the binomial law of the resampled seeds: a point with seeds (C, C, L) draws a
// majority of L with probability P(at least 2 of 3 draws are L) = 3 (1/3)^2 (2/3) + (1/3)^3 =
// 7/27 = 0.26, so a count that this point alone changes is its grid value in 20/27 of the
// resamples and one more (or less) in 7/27: median the grid value, 95 % interval spanning
// both, as 7/27 > 2.5 %.
#include <gtest/gtest.h>

#include "studies/stability/DifferenceBootstrap.hpp"

namespace granwave {
namespace {

const std::vector<double> kF{10, 30}, kGamma{2, 3, 4};
const std::string C = "crystal", L = "liquid-like";

LayerPatterns seed(const std::string& state, bool wave) {
  LayerPatterns p;
  p.available = true;
  p.state = p.within_cycle_state = state;
  p.surface_wave = wave;
  p.period = 1;
  return p;
}

// Three seeds at every point. Dry: liquid-like with surface waves at 10 Hz, Gamma = 3, 4;
// wet: liquid-like without waves there; both crystals elsewhere. `split_state`: the dry seeds
// at (10 Hz, Gamma = 2) are (C, C, L); `split_wave`: the wet seeds at (30 Hz, Gamma = 4) have
// a wave in one of three.
SeedPatterns seeds(bool split_state, bool split_wave) {
  SeedPatterns s;
  for (int law = 0; law < 2; ++law)
    for (std::size_t i = 0; i < kF.size(); ++i)
      for (std::size_t j = 0; j < kGamma.size(); ++j) {
        const bool fluid = i == 0 && j > 0;
        const LayerPatterns p = seed(fluid ? L : C, fluid && law == 0);
        std::vector<LayerPatterns> v{p, p, p};
        if (split_state && law == 0 && i == 0 && j == 0) v[2] = seed(L, false);
        if (split_wave && law == 1 && i == 1 && j == 2) v[0] = seed(C, true);
        s.patterns[law].push_back(v);
        s.finished[law].push_back({true, true, true});
        s.messages[law].push_back({"", "", ""});
      }
  return s;
}

StabilityGrid frame() {
  StabilityGrid g;
  g.frequencies = kF;
  g.gammas = kGamma;
  return g;
}

const DifferenceCounts& of(const std::vector<DifferenceCounts>& all, Difference d) {
  for (const DifferenceCounts& c : all)
    if (c.difference == d) return c;
  throw std::logic_error("no such difference");
}

TEST(DifferenceBootstrap, SeedsThatAllAgreeGiveZeroWidthIntervalsAtTheGridCounts) {
  const auto counts = bootstrapDifferenceCounts(frame(), seeds(false, false), 200);
  ASSERT_EQ(counts.size(), std::size(kDifferences));
  for (const DifferenceCounts& c : counts)
    for (std::size_t i = 0; i < kF.size(); ++i) {
      EXPECT_EQ(c.resampled[i].resamples, 200);
      EXPECT_EQ(c.resampled[i].low, c.grid[i]) << differenceKey(c.difference) << i;
      EXPECT_EQ(c.resampled[i].high, c.grid[i]) << differenceKey(c.difference) << i;
    }
  // Waves differ at 10 Hz, Gamma = 3 and 4; the states nowhere.
  EXPECT_EQ(of(counts, Difference::surface_waves).grid, (std::vector<double>{2, 0}));
  EXPECT_EQ(of(counts, Difference::state).grid, (std::vector<double>{0, 0}));
  EXPECT_EQ(of(counts, Difference::any).grid, (std::vector<double>{2, 0}));
}

TEST(DifferenceBootstrap, ASplitPointWidensOnlyItsFrequencyAndCategory) {
  const auto counts = bootstrapDifferenceCounts(frame(), seeds(true, true), 400);
  const PercentileInterval state10 = of(counts, Difference::state).resampled[0];
  EXPECT_EQ(of(counts, Difference::state).grid[0], 0);
  EXPECT_EQ(state10.median, 0);
  EXPECT_EQ(state10.low, 0);
  EXPECT_EQ(state10.high, 1);
  EXPECT_EQ(of(counts, Difference::state).resampled[1].high, 0);
  const PercentileInterval waves30 = of(counts, Difference::surface_waves).resampled[1];
  EXPECT_EQ(waves30.median, 0);
  EXPECT_EQ(waves30.high, 1);
  const PercentileInterval waves10 = of(counts, Difference::surface_waves).resampled[0];
  EXPECT_EQ(waves10.low, 2);
  EXPECT_EQ(waves10.high, 2);
  EXPECT_EQ(of(counts, Difference::kinks).resampled[0].high, 0);
  // Any symbol at 10 Hz: the two wave points always, the split state point in 7/27.
  EXPECT_EQ(of(counts, Difference::any).resampled[0].low, 2);
  EXPECT_EQ(of(counts, Difference::any).resampled[0].high, 3);
}

TEST(DifferenceBootstrap, TheSameInputGivesTheSameIntervals) {
  const auto a = bootstrapDifferenceCounts(frame(), seeds(true, true), 100);
  const auto b = bootstrapDifferenceCounts(frame(), seeds(true, true), 100);
  for (std::size_t d = 0; d < a.size(); ++d)
    for (std::size_t i = 0; i < kF.size(); ++i) {
      EXPECT_EQ(a[d].resampled[i].median, b[d].resampled[i].median);
      EXPECT_EQ(a[d].resampled[i].low, b[d].resampled[i].low);
      EXPECT_EQ(a[d].resampled[i].high, b[d].resampled[i].high);
    }
}

}  // namespace
}  // namespace granwave
