// Period of the centre-of-mass motion from its spectrum, on series of known period.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "coarse_grain/PeriodDetector.hpp"

using namespace granwave;

namespace {
constexpr int kM = 100;
// h(t) over `cycles` drive cycles: a drive-frequency motion plus a subharmonic f/p of
// relative amplitude `sub`, plus white noise.
std::vector<double> series(int cycles, int p, double sub, double noise, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0.0, noise);
  std::vector<double> h;
  for (int k = 0; k < cycles * kM; ++k) {
    const double t = static_cast<double>(k) / kM;  // in cycles
    double v = std::sin(2 * std::numbers::pi * t);
    if (p > 1) v += sub * std::sin(2 * std::numbers::pi * t / p + 0.3);
    h.push_back(0.02 + 0.005 * v + (noise > 0 ? n(rng) : 0.0));
  }
  return h;
}
}  // namespace

TEST(PeriodDetector, PureDriveMotionIsPeriodOne) {
  const PeriodResult r = detectPeriod(series(60, 1, 0, 0, 1), 6);
  EXPECT_EQ(r.period, 1);
  EXPECT_LT(r.strength[2], 1e-10);
  EXPECT_NEAR(r.harmonic_amplitude, 0.005, 1e-9);
}

TEST(PeriodDetector, SubharmonicOfHalfFrequencyIsPeriodTwo) {
  const PeriodResult r = detectPeriod(series(60, 2, 0.5, 1e-4, 2), 6);
  EXPECT_EQ(r.period, 2);
  EXPECT_NEAR(r.strength[2], 0.5, 0.02);  // amplitude ratio by construction
}

TEST(PeriodDetector, SubharmonicOfThirdFrequencyIsPeriodThree) {
  const PeriodResult r = detectPeriod(series(60, 3, 0.3, 1e-4, 3), 6);
  EXPECT_EQ(r.period, 3);
  EXPECT_NEAR(r.strength[3], 0.3, 0.02);
}

TEST(PeriodDetector, WeakSubharmonicBelowThresholdIsPeriodOne) {
  EXPECT_EQ(detectPeriod(series(60, 2, 0.05, 1e-4, 4), 6).period, 1);
}

TEST(PeriodDetector, TooShortSeriesIsRejected) {
  EXPECT_THROW(detectPeriod(series(10, 1, 0, 0, 5), 0), std::invalid_argument);
}
