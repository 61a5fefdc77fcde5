// When a point of the surface-waves study waves (its seeds' windows pooled) and where its onset
// lies: SurfaceWaveSummary::waves, summarise and waveOnset on made-up runs of known windows.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "studies/surface_waves/SurfaceWaveOnset.hpp"
#include "studies/surface_waves/SurfaceWavesAnalysis.hpp"

namespace granwave {
namespace {

// A finished run at Gamma `gamma` (seed `seed`) of `windows` spectrum windows, `wave_windows`
// of them with an f/2 wave, and a mean amplitude `amplitude_d` (d) over its windows with the
// standard error `error_d` over them. (A window with a wave has at least 0.5 d, so k waving
// windows of n make the mean at least k / n x 0.5 d.)
SurfaceWaveRun run(double gamma, int seed, int windows, int wave_windows, double amplitude_d,
                   double error_d = 0.3) {
  SurfaceWaveRun r;
  r.point.gamma = gamma;
  r.point.seed = seed;
  r.ok = r.spectrum = true;
  r.windows = windows;
  r.wave_windows = wave_windows;
  r.amplitude_d = {amplitude_d, error_d};
  r.wavelength_d = {40, 1};
  r.standing_mode = 3;
  return r;
}

// The runs' points combined over seeds 1 and 2, one summary per Gamma.
std::vector<SurfaceWaveSummary> summaries(const std::vector<SurfaceWaveRun>& runs) {
  std::vector<SurfaceWavePoint> points;
  for (const SurfaceWaveRun& r : runs) points.push_back(r.point);
  return summarise(runs, points, 1);
}

TEST(SurfaceWaveSummary, HalfOfThePooledWindowsCountedExactlyWithAWaveOfThresholdAmplitudeWaves) {
  // 6 of 6 and 0 of 6 windows: the per-run fractions, once summed as six sixths
  // (0.9999999999999999) and pooled as fraction x windows, gave 0.49999999999999994 of 12.
  const auto s = summaries({run(4, 1, 6, 6, 1.0), run(4, 2, 6, 0, 1.0)});
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].wave_windows, 6);
  EXPECT_EQ(s[0].windows, 12);
  EXPECT_EQ(s[0].wave_fraction, 0.5);
  EXPECT_TRUE(s[0].waves());
}

TEST(SurfaceWaveSummary, FewerThanHalfTheWindowsIsNotAWaveWhateverTheAmplitude) {
  const auto s = summaries({run(4, 1, 6, 3, 5.0), run(4, 2, 6, 2, 5.0)});
  ASSERT_EQ(s.size(), 1u);
  EXPECT_FALSE(s[0].waves());
}

TEST(SurfaceWaveOnset, FlatLayerBelowAndAWaveInEveryWindowAboveCrossAtTheBracketsMiddle) {
  // Shares 0 and 1: Gamma_c = 2.5, its error the binomial parts (0.5/12 x 1/2 each) and the
  // bracket's width / sqrt 12 in quadrature.
  const auto s = summaries({run(2, 1, 12, 0, 0.1), run(3, 1, 12, 12, 4.6)});
  const SurfaceWaveOnset o = waveOnset({2, 3}, 0, 10, 120, true, s);
  ASSERT_TRUE(o.gamma_c.valid()) << o.bound;
  EXPECT_DOUBLE_EQ(o.gamma_c.value, 2.5);
  const double binomial = 0.5 / 12 * 0.5;
  EXPECT_NEAR(o.gamma_c.error, std::sqrt(2 * binomial * binomial + 1.0 / 12), 1e-12);
}

TEST(SurfaceWaveOnset, OneSeedOfTwoWavingInEveryWindowPlacesTheOnsetAtThatGamma) {
  // The wet layer at 25 Hz: flat at Gamma 4; at Gamma 5 one seed holds a mode-1 wave in all 6
  // windows and the other none (a bistable point, share exactly 1/2). Gamma_c = 5, its error the
  // binomial part of the upper share, sqrt(0.25 / 12) / (1/2), and the bracket's width / sqrt 12
  // (the lower share is 0), in quadrature.
  const auto s = summaries(
      {run(4, 1, 6, 0, 0.1), run(4, 2, 6, 0, 0.1), run(5, 1, 6, 6, 1.2), run(5, 2, 6, 0, 0.1)});
  const SurfaceWaveOnset o = waveOnset({4, 5}, 0, 10, 120, true, s);
  ASSERT_TRUE(o.gamma_c.valid()) << o.bound;
  EXPECT_NEAR(o.gamma_c.value, 5.0, 1e-12);
  EXPECT_NEAR(o.gamma_c.error, std::hypot(std::sqrt(0.25 / 12) / 0.5, 1 / std::sqrt(12.0)), 1e-12);
}

TEST(SurfaceWaveOnset, PointsOfTheOtherBoundaryAreNotPartOfTheCurve) {
  // Walled points that wave beside periodic ones that do not: the periodic curve has no onset.
  std::vector<SurfaceWaveRun> runs{run(2, 1, 12, 0, 0.1), run(3, 1, 12, 0, 0.1)};
  for (double g : {2.0, 3.0}) {
    SurfaceWaveRun walled = run(g, 1, 12, 12, 3.0);
    walled.point.periodic = false;
    runs.push_back(walled);
  }
  const auto s = summaries(runs);
  EXPECT_EQ(waveOnset({2, 3}, 0, 10, 120, true, s).bound, "> 3");
  EXPECT_EQ(waveOnset({2, 3}, 0, 10, 120, false, s).bound, "< 2");
}

}  // namespace
}  // namespace granwave
