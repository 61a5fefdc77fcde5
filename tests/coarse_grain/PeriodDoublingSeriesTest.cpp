// The state of a bistable layer as a time series (coarse_grain/PeriodDoublingSeries.hpp) and
// the run period every command shares (coarse_grain/PeriodDetector.hpp, runPeriod), on
// centre-of-mass series whose state is known by construction.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "coarse_grain/PeriodDetector.hpp"
#include "coarse_grain/PeriodDoublingSeries.hpp"

using namespace granwave;

namespace {
constexpr int kM = 100;

// A drive-frequency motion of 5 mm and, in cycles [from, to), an f/2 subharmonic of relative
// amplitude `sub` (its strength, by construction).
std::vector<double> switching(int cycles, int from, int to, double sub) {
  std::vector<double> h;
  for (int k = 0; k < cycles * kM; ++k) {
    const double t = static_cast<double>(k) / kM;  // in cycles
    double v = std::sin(2 * std::numbers::pi * t);
    if (t >= from && t < to) v += sub * std::sin(std::numbers::pi * t + 0.3);
    h.push_back(0.02 + 0.005 * v);
  }
  return h;
}
}  // namespace

TEST(PeriodDoublingSeries, FindsThePeriodTwoEpisodeWindowByWindow) {
  // 12 windows after 24 discarded cycles; period 2 in windows 4-7 (cycles 72-120).
  const PeriodDoublingSeries s = periodDoublingSeries(switching(168, 72, 120, 0.5), kM, 24);
  ASSERT_EQ(s.f2_strength.size(), 12u);
  EXPECT_EQ(s.first_cycle, 24);
  for (std::size_t w = 0; w < 12; ++w) {
    const bool episode = w >= 4 && w < 8;
    EXPECT_EQ(s.period2[w], episode ? 1 : 0) << "window " << w;
    // A whole window inside the episode holds the subharmonic exactly: strength 0.5.
    if (episode) {
      EXPECT_NEAR(s.f2_strength[w], 0.5, 1e-9) << "window " << w;
    } else {
      EXPECT_LT(s.f2_strength[w], 1e-9) << "window " << w;
    }
  }
  EXPECT_DOUBLE_EQ(s.period2_share, 4.0 / 12.0);
  EXPECT_EQ(s.switches, 2);
  // Episodes: the known switching times exactly (they fall on window boundaries here).
  ASSERT_EQ(s.episodes.size(), 3u);
  EXPECT_EQ(s.episodes[0].first_cycle, 24);
  EXPECT_EQ(s.episodes[0].cycles, 48);
  EXPECT_EQ(s.episodes[0].period, 1);
  EXPECT_EQ(s.episodes[1].first_cycle, 72);
  EXPECT_EQ(s.episodes[1].cycles, 48);
  EXPECT_EQ(s.episodes[1].period, 2);
  EXPECT_EQ(s.episodes[2].first_cycle, 120);
  EXPECT_EQ(s.episodes[2].period, 1);
  // One block of 4 correlated windows: fewer effective windows than 12, and an interval
  // that holds the share.
  EXPECT_LT(s.effective_windows, 12.0);
  EXPECT_LT(s.share_low, s.period2_share);
  EXPECT_GT(s.share_high, s.period2_share);
}

TEST(PeriodDoublingSeries, EpisodeBoundariesInsideAWindowAreExactUpToOneWindow) {
  // Period 2 in cycles [77, 131) with noise: the episode must start within one window
  // (12 cycles) of 77 and end within one window of 131.
  std::vector<double> h = switching(180, 77, 131, 0.5);
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 0.0005);  // 10 % of the drive amplitude
  for (double& v : h) v += noise(rng);
  const PeriodDoublingSeries s = periodDoublingSeries(h, kM, 12);
  int begin = -1, end = -1;
  for (const StateEpisode& e : s.episodes)
    if (e.period == 2) {
      EXPECT_EQ(begin, -1) << "one period-2 episode expected";
      begin = e.first_cycle;
      end = e.first_cycle + e.cycles;
    }
  EXPECT_LE(std::abs(begin - 77), 12);
  EXPECT_LE(std::abs(end - 131), 12);
}

TEST(PeriodDoublingSeries, NoiseAloneNeverMakesAPeriodTwoWindow) {
  // Period 1 under white noise of 0.4 of the drive amplitude per sample: the noise threshold
  // rises above the floor where the noise is large, and no window of 60 is called period 2
  // (expected false calls: 60 x e^-9 ~ 0.007).
  std::vector<double> h = switching(732, 0, 0, 0);
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0.0, 0.002);
  for (double& v : h) v += noise(rng);
  const PeriodDoublingSeries s = periodDoublingSeries(h, kM, 12);
  ASSERT_EQ(s.period2.size(), 60u);
  for (std::size_t w = 0; w < s.period2.size(); ++w) {
    EXPECT_EQ(s.period2[w], 0) << "window " << w;
    EXPECT_GE(s.threshold[w], 3 * s.noise_strength[w]);
    EXPECT_GE(s.threshold[w], 0.1);
  }
  EXPECT_EQ(s.episodes.size(), 1u);
  // White noise: each f/2 comb and each shifted comb holds 50 bins of mean power
  // n sigma^2 against the harmonic's (n A / 2)^2, n = 1200 samples: s_n ~ sqrt(50 * 4 sigma^2 /
  // (n A^2)) = sqrt(200 * 0.16 / 1200) = 0.163, within 30 % (six combs of 50 bins).
  double mean = 0;
  for (double v : s.noise_strength) mean += v / static_cast<double>(s.noise_strength.size());
  EXPECT_NEAR(mean, 0.163, 0.05);
}

TEST(PeriodDoublingSeries, ALayerThatNeverSwitchesCountsAsOneObservation) {
  const PeriodDoublingSeries s = periodDoublingSeries(switching(60, 0, 60, 0.5), kM, 12);
  EXPECT_DOUBLE_EQ(s.period2_share, 1.0);
  EXPECT_EQ(s.switches, 0);
  EXPECT_DOUBLE_EQ(s.effective_windows, 1.0);
  // Wilson 95 % for 1 of 1: [1 / (1 + z^2), 1] = [0.2065, 1].
  EXPECT_NEAR(s.share_low, 1.0 / (1.0 + 1.959963984540054 * 1.959963984540054), 1e-12);
  EXPECT_DOUBLE_EQ(s.share_high, 1.0);
}

TEST(PeriodDoublingSeries, WilsonIntervalMatchesTheClosedForm) {
  // p = 0.5, n = 100: centre 0.5, half width z sqrt(0.25/100 + z^2/40000) / (1 + z^2/100)
  // = 0.0962 (Wilson 1927).
  double lo = 0, hi = 0;
  wilsonInterval(0.5, 100, lo, hi);
  EXPECT_NEAR(lo, 0.4038, 1e-4);
  EXPECT_NEAR(hi, 0.5962, 1e-4);
}

TEST(PeriodDoublingSeries, RejectsWindowsThatAreNotWholeTwelves) {
  EXPECT_THROW(periodDoublingSeries(switching(60, 0, 0, 0), kM, 0, 10), std::invalid_argument);
  EXPECT_THROW(periodDoublingSeries(switching(20, 0, 0, 0), kM, 10), std::invalid_argument);
}

TEST(RunPeriod, LeavesOutTheLargerTransientAndFindsTheSteadyPeriod) {
  // 100 cycles: a fifth is 20; period 2 throughout.
  const RunPeriod r = runPeriod(switching(100, 0, 100, 0.5), kM);
  EXPECT_GE(r.discarded, 20);
  EXPECT_EQ(r.result.period, 2);
  EXPECT_THROW(runPeriod(switching(14, 0, 0, 0), kM), std::invalid_argument);
}
