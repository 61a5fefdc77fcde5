// How stable the stability verdicts are against the choice of seeds
// (studies/stability/SeedBootstrap.hpp), on synthetic grids whose seed votes are known.
// Expected shares from the binomial law of the resampled seeds: with seeds (C, C, L) at one
// point, a resample of 3 seeds has a majority of L with probability
// P(at least 2 of 3 draws are L) = 3 (1/3)^2 (2/3) + (1/3)^3 = 7/27.
#include <gtest/gtest.h>

#include <cmath>

#include "studies/stability/SeedBootstrap.hpp"

namespace granwave {
namespace {

const std::vector<double> kF{10, 30}, kGamma{2, 3, 4, 5, 6};
const std::string C = "crystal", L = "liquid-like";

LayerPatterns seed(const std::string& state) {
  LayerPatterns p;
  p.available = true;
  p.state = p.within_cycle_state = state;
  p.period = 1;
  return p;
}

// Three seeds everywhere; the paper's diagram of states (StabilityFeaturesTest), and at
// `split` (dry, 10 Hz, Gamma = 6) the seeds (C, C, L) instead of (C, C, C).
SeedPatterns seeds(bool split) {
  const std::vector<std::string> row[2] = {{C, L, L, L, C}, {C, C, C, C, C}};
  SeedPatterns s;
  for (int law = 0; law < 2; ++law)
    for (std::size_t i = 0; i < kF.size(); ++i)
      for (std::size_t j = 0; j < kGamma.size(); ++j) {
        const std::string& st = row[i][j];
        std::vector<LayerPatterns> p{seed(st), seed(st), seed(st)};
        if (split && law == 0 && i == 0 && j == 4) p[2] = seed(L);
        s.patterns[law].push_back(p);
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

TEST(SeedBootstrap, UnanimousSeedsGiveEveryVerdictInEveryResample) {
  const SeedBootstrap b = bootstrapOverSeeds(frame(), seeds(false), 50);
  EXPECT_EQ(b.resamples, 50);
  ASSERT_FALSE(b.verdict_agreement.empty());
  for (const auto& [key, share] : b.verdict_agreement) EXPECT_DOUBLE_EQ(share, 1.0) << key;
}

TEST(SeedBootstrap, ASplitPointChangesItsVerdictInTheBinomialShareOfResamples) {
  constexpr int kResamples = 2000;
  const SeedBootstrap b = bootstrapOverSeeds(frame(), seeds(true), kResamples);
  const double p = 7.0 / 27.0;  // resamples with a liquid-like majority at the split point
  const double tol = 4 * std::sqrt(p * (1 - p) / kResamples);  // 4 sigma of the share
  EXPECT_NEAR(b.verdict_agreement.at("dry_solid_again"), 1 - p, tol);
  EXPECT_NEAR(b.verdict_agreement.at("dry_solid_again_within_cycle"), 1 - p, tol);
  EXPECT_DOUBLE_EQ(b.verdict_agreement.at("wet_solid_again"), 1.0);
}

}  // namespace
}  // namespace granwave
