// Steady-state detection on series with a known transient.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "coarse_grain/SteadyStateDetector.hpp"

using namespace granwave;

TEST(SteadyStateDetector, DetectsTheEndOfAnExponentialTransient) {
  // h_c = 1 + exp(-c / 4) + noise 1e-3: the transient term falls below the noise (3 sigma of
  // a window mean ~ 1e-3) near c = 4 ln(1e3) ~ 28; detection must be after c ~ 15 and not
  // later than ~ 35.
  std::mt19937_64 rng(5);
  std::normal_distribution<double> noise(0.0, 1e-3);
  SteadyStateDetector det;
  for (int c = 0; c < 100 && !det.steady(); ++c)
    det.addCycle(1.0 + std::exp(-c / 4.0) + noise(rng));
  ASSERT_TRUE(det.steady());
  EXPECT_GE(det.steadyFrom(), 15);
  EXPECT_LE(det.steadyFrom(), 35);
}

TEST(SteadyStateDetector, StationaryNoiseIsSteadyAfterTheMinimum) {
  std::mt19937_64 rng(6);
  std::normal_distribution<double> noise(0.0, 1e-2);
  SteadyStateDetector det;
  for (int c = 0; c < 200 && !det.steady(); ++c) det.addCycle(2.0 + noise(rng));
  ASSERT_TRUE(det.steady());
  EXPECT_LE(det.steadyFrom(), 15);
  EXPECT_GE(det.steadyFrom(), 5);
}

TEST(SteadyStateDetector, PeriodTwoAlternationIsSteady) {
  // Alternating cycle means (a period-2 layer) average out over even windows.
  SteadyStateDetector det;
  for (int c = 0; c < 40 && !det.steady(); ++c) det.addCycle(c % 2 ? 1.1 : 0.9);
  EXPECT_TRUE(det.steady());
}

TEST(SteadyStateDetector, SteadyDriftIsNeverSteady) {
  SteadyStateDetector det;
  for (int c = 0; c < 200; ++c) det.addCycle(1.0 + 0.01 * c);
  EXPECT_FALSE(det.steady());
}
