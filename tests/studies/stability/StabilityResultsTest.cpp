// The tiny stability study (tests/studies/data/tiny-stability.toml): f = 30 and 40 Hz,
// Gamma = 3, 6 (A = 0.41 d and 0.23 d at Gamma 3, 0.83 d and 0.47 d at Gamma 6).
//
// A plate that moves less than half a particle diameter (amplitude A = Gamma g / (2 pi f)^2)
// cannot move a layer's particles past their neighbours: the layer stays caged, crystal or
// amorphous, never liquid-like (the paper's argument for the crystals at high f, Huang,
// Sec. III: the amplitude falls as f^-2 and becomes small against d). Checked at every grid
// point with A < d/2, dry and wet, on the most frequent verdict of the seeds.
// The dry-wet difference counts per frequency are counts of Gamma points: between 0 and the
// number of Gamma values, on the grid and over the seed resamples (median inside its 95 %
// interval); a difference in any symbol counts each point once, so the count of "any" lies
// between the largest and the sum of the counts by symbol, and equals the stored count.
// Seeds are added (max_seeds = 3, seed_step = 1) only while a feature is undecided and only at
// points whose seeds disagree.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "scene/SceneParser.hpp"
#include "tests/studies/contract/TinyStudy.hpp"

namespace {

constexpr char kKind[] = "stability";
using StabilityResults = granwave::testing::TinyStudyTest<kKind>;
const std::string kRoot = "/results/stability";
constexpr double kLiquidLike = 2;  // /results/stability/<law>/state code

TEST_F(StabilityResults, LayersOnAPlateMovingLessThanHalfADiameterStayCaged) {
  const auto f = study().series(kRoot + "/frequencies");
  const auto gammas = study().series(kRoot + "/gammas");
  const granwave::Scene scene =
      granwave::parseSceneFile(std::string(GRANWAVE_SOURCE_DIR) + "/scenes/paper-dry.toml");
  const double d = scene.particles.diameter;
  int checked = 0;
  for (const char* law : {"dry", "wet"}) {
    const auto state = study().series(kRoot + "/" + law + "/state");
    for (std::size_t k = 0; k < state.size(); ++k) {
      const std::size_t i = k / gammas.size(), j = k % gammas.size();
      const double omega = 2 * std::numbers::pi * f[i];
      const double amplitude = gammas[j] * scene.run.gravity / (omega * omega);
      if (amplitude >= d / 2 || !std::isfinite(state[k])) continue;
      ++checked;
      EXPECT_NE(state[k], kLiquidLike) << law << " at f = " << f[i] << " Hz, Gamma = " << gammas[j];
    }
  }
  EXPECT_GE(checked, 4) << "too few points with A < d/2 classified";
}

TEST_F(StabilityResults, DifferenceCountsByCategoryAreCountsOfGammaPointsWithIntervals) {
  const double gammas = static_cast<double>(study().series(kRoot + "/gammas").size());
  const std::string g = kRoot + "/difference_bootstrap/";
  for (const char* key : {"state", "state_within_cycle", "waves", "kinks", "any"}) {
    const auto grid = study().series(g + key + "/grid");
    const auto median = study().series(g + key + "/median");
    const auto low = study().series(g + key + "/low95"), high = study().series(g + key + "/high95");
    ASSERT_EQ(grid.size(), 2u) << key;
    for (std::size_t i = 0; i < grid.size(); ++i) {
      EXPECT_GE(grid[i], 0) << key;
      EXPECT_LE(grid[i], gammas) << key;
      EXPECT_LE(low[i], median[i]) << key;
      EXPECT_LE(median[i], high[i]) << key;
      EXPECT_GE(low[i], 0) << key;
      EXPECT_LE(high[i], gammas) << key;
    }
  }
  const auto any = study().series(g + "any/grid");
  const auto state = study().series(g + "state/grid"), waves = study().series(g + "waves/grid");
  const auto kinks = study().series(g + "kinks/grid");
  EXPECT_EQ(any, study().series(kRoot + "/differences_per_frequency"));
  for (std::size_t i = 0; i < any.size(); ++i) {
    EXPECT_GE(any[i], std::max({state[i], waves[i], kinks[i]}));
    EXPECT_LE(any[i], state[i] + waves[i] + kinks[i]);
  }
}

TEST_F(StabilityResults, SeedsAreAddedWhereTheSeedsDisagreeWhileAFeatureIsUndecided) {
  const auto seeds = study().series(kRoot + "/seeds_per_point");
  const auto dry = study().series(kRoot + "/dry/seeds_agree");
  const auto wet = study().series(kRoot + "/wet/seeds_agree");
  ASSERT_EQ(seeds.size(), dry.size());
  bool added = false, split_left_at_two = false;
  for (std::size_t p = 0; p < seeds.size(); ++p) {
    EXPECT_TRUE(seeds[p] == 2 || seeds[p] == 3) << "point " << p << ": " << seeds[p] << " seeds";
    added = added || seeds[p] == 3;
    split_left_at_two = split_left_at_two || (seeds[p] == 2 && !(dry[p] && wet[p]));
  }
  // A round adds a seed at every point whose seeds disagree, so a split point left at two
  // seeds means no round ran, which needs every feature decided (at least 90 % of resamples).
  if (split_left_at_two) {
    EXPECT_FALSE(added);
    EXPECT_EQ(study().value(kRoot + "/seed_bootstrap", "undecided"), 0);
  }
}

}  // namespace
