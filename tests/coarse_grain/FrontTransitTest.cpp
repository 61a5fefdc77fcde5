// The front's transit speeds between mass fractions of the layer (coarse_grain/FrontTransit.hpp)
// on a prescribed track through a uniform layer, where every passage is known in closed form.
// Layer: rows of spacing dz at heights (j + 1/2) dz, density rho on rows 5..44 and empty around,
// so the trapezoidal mass below a height h inside the layer is rho (h - 5 dz) and the share of
// the layer's mass below it is q(h) = (h - 0.005 m) / 0.04 m, exactly (the density is linear
// between rows, and the half-row ramps at both edges add rho dz / 2 each).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "coarse_grain/FrontTransit.hpp"

using namespace granwave;

namespace {

constexpr double kDz = 0.001, kDt = 1e-4, kRho = 0.8;  // m, s, area fraction

FrontProfiles uniformLayer(int phases = 200) {
  FrontProfiles p;
  p.phases = phases;
  p.nz = 60;
  for (int j = 0; j < p.nz; ++j) p.z.push_back((j + 0.5) * kDz);
  for (int ph = 0; ph < phases; ++ph)
    for (int j = 0; j < p.nz; ++j) {
      p.density.push_back(j >= 5 && j <= 44 ? kRho : 0.0);
      p.velocity.push_back(0.0);
    }
  return p;
}

// A track at `fast` m/s for `fast_phases` phases from 6 mm, then at `slow` m/s up to `top`.
TrackedFront track(double fast, int fast_phases, double slow, double top) {
  TrackedFront f;
  double z = 0.006;
  for (int k = 0; z <= top + 1e-12; ++k) {
    f.time.push_back(k * kDt);
    f.height.push_back(z);
    z += (k < fast_phases ? fast : slow) * kDt;
  }
  f.points = static_cast<int>(f.time.size());
  f.resolved = true;
  return f;
}

}  // namespace

TEST(FrontTransit, MassFractionBelowAHeightOfAUniformLayerIsItsShareOfTheThickness) {
  const FrontProfiles p = uniformLayer();
  EXPECT_NEAR(massFractionBelow(p, 0, 0.025), 0.5, 1e-12);
  EXPECT_NEAR(massFractionBelow(p, 3, 0.009), 0.1, 1e-12);
  EXPECT_NEAR(massFractionBelow(p, 0, 0.0413), 0.9075, 1e-12);
  EXPECT_EQ(massFractionBelow(p, 0, 0.0), 0.0);
  EXPECT_NEAR(massFractionBelow(p, 0, 1.0), 1.0, 1e-15);
}

TEST(FrontTransit, DeceleratingFrontHasItsSpeedInEachHalfOfTheLayer) {
  // 10 m/s (one row per phase) for 20 phases, to 26 mm (q = 0.525), then 2 m/s to 42 mm. It
  // passes q = 0.1 (9 mm) at 3 dt and q = 0.5 (25 mm) at 19 dt: 0.016 m / 16 dt = 10 m/s; and
  // q = 0.9 (41 mm) at 95 dt: 0.016 m / 76 dt = 2.105 m/s. One straight line through the whole
  // track gives neither.
  const FrontProfiles p = uniformLayer();
  const TrackedFront f = track(10.0, 20, 2.0, 0.042);
  const FrontTransit lower = frontTransit(p, f, kDt, 0.1, 0.5);
  ASSERT_TRUE(lower.reached);
  ASSERT_TRUE(lower.resolved);
  EXPECT_NEAR(lower.from_time, 3 * kDt, 1e-12);
  EXPECT_NEAR(lower.to_time, 19 * kDt, 1e-12);
  EXPECT_NEAR(lower.speed, 10.0, 1e-9);
  const FrontTransit upper = frontTransit(p, f, kDt, 0.5, 0.9);
  ASSERT_TRUE(upper.resolved);
  EXPECT_NEAR(upper.from_height, 0.025, 1e-12);
  EXPECT_NEAR(upper.to_height, 0.041, 1e-12);
  EXPECT_NEAR(upper.speed, 0.016 / (76 * kDt), 1e-9);
}

TEST(FrontTransit, PassageWithinFewerThanThreePhasesGivesABoundBelowTheTrueSpeed) {
  // 100 m/s: 10 rows per phase; q = 0.1 and 0.5 are passed one phase apart.
  const FrontProfiles p = uniformLayer();
  const FrontTransit t = frontTransit(p, track(100.0, 3, 2.0, 0.042), kDt, 0.1, 0.5);
  ASSERT_TRUE(t.reached);
  EXPECT_FALSE(t.resolved);
  EXPECT_TRUE(std::isnan(t.speed));
  EXPECT_GT(t.speed_lower_bound, 0.0);
  EXPECT_LE(t.speed_lower_bound, 100.0);
}

TEST(FrontTransit, FrontFirstSeenAboveTheLowerFractionIsBoundedAndOneEndingBelowNotReached) {
  const FrontProfiles p = uniformLayer();
  TrackedFront f = track(2.0, 0, 2.0, 0.030);  // 6 mm (q = 0.025) to 30 mm (q = 0.625)
  EXPECT_TRUE(frontTransit(p, f, kDt, 0.1, 0.5).resolved);
  // Seen first at 14 mm (q = 0.225), as the tracker starts a front that crossed a packed bottom
  // within the phase before: it passed q = 0.1 (9 mm) in that phase, and q = 0.5025 (25.1 mm)
  // 55.5 phases after the first tracked one, so within 57 phase intervals: above 16.1 mm / 57 dt
  // (the true 16.1 mm / 56.5 dt or less).
  for (int k = 0; k < 40; ++k) {  // drop the first 40 points: 6 mm + 40 x 0.2 mm = 14 mm
    f.time.erase(f.time.begin());
    f.height.erase(f.height.begin());
  }
  const FrontTransit late = frontTransit(p, f, kDt, 0.1, 0.5025);
  EXPECT_TRUE(late.reached);
  EXPECT_FALSE(late.resolved);
  EXPECT_NEAR(late.from_height, 0.009, 1e-12);
  EXPECT_NEAR(late.speed_lower_bound, 0.0161 / (57 * kDt), 1e-9);
  EXPECT_LT(late.speed_lower_bound, 0.0161 / (56.5 * kDt));
  EXPECT_FALSE(frontTransit(p, f, kDt, 0.5, 0.9).reached);  // the track ends at q = 0.625
}

TEST(FrontTransit, FractionsOutsideTheUnitIntervalOrOutOfOrderAreRefused) {
  const FrontProfiles p = uniformLayer();
  const TrackedFront f = track(10.0, 20, 2.0, 0.042);
  EXPECT_THROW(frontTransit(p, f, kDt, 0.5, 0.5), std::invalid_argument);
  EXPECT_THROW(frontTransit(p, f, kDt, -0.1, 0.5), std::invalid_argument);
  EXPECT_THROW(frontTransit(p, f, kDt, 0.5, 1.1), std::invalid_argument);
}
