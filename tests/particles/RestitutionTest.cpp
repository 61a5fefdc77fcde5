// The three normal-restitution laws of the paper (Eqs. 4, 5) at worked values.
#include <gtest/gtest.h>

#include <cmath>

#include "particles/Restitution.hpp"

using granwave::Restitution;

TEST(Restitution, ConstantLawIgnoresImpactSpeed) {
  const Restitution e = Restitution::constant(0.7);
  EXPECT_DOUBLE_EQ(e(0.0), 0.7);
  EXPECT_DOUBLE_EQ(e(3.0), 0.7);
}

TEST(Restitution, DryLawIsOneMinusKappaTimesFifthRootOfSpeed) {
  // e = 1 - 0.1 v^(1/5): v = 1 m/s -> 0.9; v = 32 m/s -> 1 - 0.1*2 = 0.8; v -> 0 -> 1.
  const Restitution e = Restitution::dry(0.1);
  EXPECT_NEAR(e(1.0), 0.9, 1e-15);
  EXPECT_NEAR(e(32.0), 0.8, 1e-15);
  EXPECT_DOUBLE_EQ(e(0.0), 1.0);
  EXPECT_GT(e(1e-3), e(1e-2));  // slower impacts are more elastic
}

TEST(Restitution, DryLawIsClampedAtZeroForExtremeSpeeds) {
  const Restitution e = Restitution::dry(0.1);
  EXPECT_DOUBLE_EQ(e(1e6), 0.0);  // 1 - 0.1 * 15.8 < 0
}

TEST(Restitution, WetLawVanishesBelowOnsetVelocityAndIsContinuousThere) {
  // Paper values: q = rho d / (9 eta) = 2580 * 0.002 / 9e-3 = 573.33 s/m, St_c = 40,
  // v_c = St_c / q = 0.06977 m/s, e_inf = 0.91.
  const double q = 2580.0 * 0.002 / (9.0 * 1.0e-3);
  const Restitution e = Restitution::wet(0.91, 40.0, q);
  EXPECT_NEAR(e.onsetVelocity(), 0.069767, 1e-6);
  EXPECT_DOUBLE_EQ(e(0.5 * e.onsetVelocity()), 0.0);
  EXPECT_NEAR(e(e.onsetVelocity()), 0.0, 1e-15);
  // v = 1 m/s: 0.91 (1 - 40 / 573.33) = 0.84651
  EXPECT_NEAR(e(1.0), 0.91 * (1.0 - 40.0 / q), 1e-15);
  EXPECT_NEAR(e(1e9), 0.91, 1e-6);  // tends to e_inf
}
