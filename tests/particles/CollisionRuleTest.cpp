// Collision rule of Walton (1986) / Luding (1995) as written in the paper (Eqs. 1-3), on
// worked cases. Checks follow from the rule itself, not from earlier output: momentum
// conservation, angular momentum about the contact point, the definitions
// e_n = -v_r'.n / v_r.n and e_t = v_r'.t / v_r.t, and the energy loss formulas.
#include <gtest/gtest.h>

#include <cmath>

#include "particles/CollisionRule.hpp"

using namespace granwave;

namespace {
constexpr double kM = 1.08e-5, kD = 0.002, kI = kM * kD * kD / 10.0;

Vec2 contactVelocity(Vec2 v1, Vec2 v2, double w1, double w2, Vec2 n) {
  const double h = 0.5 * kD * (w1 + w2);
  return {v1.x - v2.x - h * n.z, v1.z - v2.z + h * n.x};
}
double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.z * b.z; }
double energy(Vec2 v1, Vec2 v2, double w1, double w2) {
  return 0.5 * kM * (dot(v1, v1) + dot(v2, v2)) + 0.5 * kI * (w1 * w1 + w2 * w2);
}
}  // namespace

TEST(CollisionRule, HeadOnSmoothCollisionLosesOneMinusESquaredOfRelativeEnergy) {
  // Equal masses, head-on: Delta E = (1 - e^2) (m/4) v_n^2 (reduced mass m/2).
  const Vec2 n{1, 0};
  const Vec2 v1{-1.0, 0}, v2{1.0, 0};
  const double e = 0.8;
  const auto r = collidePair(n, v1, v2, 0, 0, kM, kD, e, {}, TangentialRule::Smooth);
  EXPECT_NEAR(r.v1.x, 0.8, 1e-15);
  EXPECT_NEAR(r.v2.x, -0.8, 1e-15);
  EXPECT_NEAR(r.v1.x + r.v2.x, 0.0, 1e-15);
  EXPECT_NEAR(energy(v1, v2, 0, 0) - energy(r.v1, r.v2, 0, 0), (1 - e * e) * kM / 4 * 4.0, 1e-18);
  EXPECT_DOUBLE_EQ(r.vn, 2.0);
}

TEST(CollisionRule, NormalRestitutionAndMomentumHoldForObliqueRoughCollision) {
  const Vec2 n{std::cos(0.3), std::sin(0.3)};
  const Vec2 v1{-0.7, 0.2}, v2{0.4, -0.5};
  const double w1 = 30.0, w2 = -12.0, e = 0.85;
  const TangentialLaw law{0.5, 0.35};
  const auto r = collidePair(n, v1, v2, w1, w2, kM, kD, e, law, TangentialRule::Coulomb);
  const Vec2 vr = contactVelocity(v1, v2, w1, w2, n);
  const Vec2 vr2 = contactVelocity(r.v1, r.v2, r.w1, r.w2, n);
  EXPECT_NEAR(-dot(vr2, n) / dot(vr, n), e, 1e-12);
  EXPECT_NEAR(r.v1.x + r.v2.x, v1.x + v2.x, 1e-15);
  EXPECT_NEAR(r.v1.z + r.v2.z, v1.z + v2.z, 1e-15);
  // Angular momentum of each sphere about the contact point P is conserved: the impulse
  // acts at P, so I w + ((r - P) x m v)_y is unchanged; r - P = +(d/2) n for sphere 1 and
  // -(d/2) n for sphere 2.
  auto ang = [&](Vec2 v, double w, double sign) {
    const Vec2 off{sign * 0.5 * kD * n.x, sign * 0.5 * kD * n.z};
    return kI * w + kM * (off.z * v.x - off.x * v.z);
  };
  EXPECT_NEAR(ang(r.v1, r.w1, 1), ang(v1, w1, 1), 1e-15);
  EXPECT_NEAR(ang(r.v2, r.w2, -1), ang(v2, w2, -1), 1e-15);
  EXPECT_LE(energy(r.v1, r.v2, r.w1, r.w2), energy(v1, v2, w1, w2));
}

TEST(CollisionRule, SlidingBranchHasCoulombLimitedTangentialImpulse) {
  // Grazing impact (large |v_t| / |v_n|): e_t = -1 + mu (1 + e_n) |cot alpha| / beta < e_t0,
  // so |dp_t| = mu |dp_n| exactly (Coulomb).
  const Vec2 n{0, 1};
  const Vec2 v1{1.0, -0.1}, v2{0, 0};
  const TangentialLaw law{0.5, 0.35};
  const double e = 0.9;
  const auto r = collidePair(n, v1, v2, 0, 0, kM, kD, e, law, TangentialRule::Coulomb);
  const double expected_et = -1.0 + 0.5 * 1.9 * (0.1 / 1.0) / kBeta;
  EXPECT_NEAR(r.e_t, expected_et, 1e-12);
  EXPECT_LT(r.e_t, 0.35);
  EXPECT_NEAR(std::abs(r.impulse.x), 0.5 * std::abs(r.impulse.z), 1e-18);
  const Vec2 vr = contactVelocity(v1, v2, 0, 0, n);
  const Vec2 vr2 = contactVelocity(r.v1, r.v2, r.w1, r.w2, n);
  EXPECT_NEAR(vr2.x / vr.x, -r.e_t, 1e-12);  // v_t' = -e_t v_t (Luding's convention)
}

TEST(CollisionRule, StickingBranchUsesLimitingTangentialRestitution) {
  // Near-normal impact: the Coulomb expression exceeds e_t0, so e_t = e_t0 = 0.35.
  const Vec2 n{0, 1};
  const Vec2 v1{0.05, -1.0}, v2{0, 0};
  const TangentialLaw law{0.5, 0.35};
  const auto r = collidePair(n, v1, v2, 0, 0, kM, kD, 0.9, law, TangentialRule::Coulomb);
  EXPECT_DOUBLE_EQ(r.e_t, 0.35);
  const Vec2 vr2 = contactVelocity(r.v1, r.v2, r.w1, r.w2, n);
  EXPECT_NEAR(vr2.x, -0.35 * 0.05, 1e-14);
}

TEST(CollisionRule, ZeroFrictionOrSmoothFlagLeavesSpinAndTangentialVelocity) {
  const Vec2 n{0.6, 0.8};
  const Vec2 v1{0.3, -0.9}, v2{-0.2, 0.1};
  for (bool rough : {false, true}) {
    const TangentialLaw law{rough ? 0.0 : 0.5, 0.35};
    const auto r = collidePair(n, v1, v2, 5.0, -3.0, kM, kD, 0.9, law,
                               rough ? TangentialRule::Coulomb : TangentialRule::Smooth);
    EXPECT_DOUBLE_EQ(r.w1, 5.0);
    EXPECT_DOUBLE_EQ(r.w2, -3.0);
    EXPECT_DOUBLE_EQ(r.e_t, -1.0);
    const Vec2 t{-n.z, n.x};
    EXPECT_NEAR(dot(r.v1, t), dot(v1, t), 1e-15);
  }
}

TEST(CollisionRule, PerfectlyRoughElasticCollisionConservesEnergy) {
  // e_n = 1 and e_t = +1 (e_t0 = 1, large mu): no dissipation at all (Luding 1995).
  const Vec2 n{std::cos(1.1), std::sin(1.1)};
  const Vec2 v1{0.3, -0.9}, v2{-0.2, 0.1};
  const auto r =
      collidePair(n, v1, v2, 7.0, 2.0, kM, kD, 1.0, {100.0, 1.0}, TangentialRule::Coulomb);
  EXPECT_DOUBLE_EQ(r.e_t, 1.0);
  EXPECT_NEAR(energy(r.v1, r.v2, r.w1, r.w2) / energy(v1, v2, 7.0, 2.0), 1.0, 1e-13);
}

TEST(CollisionRule, WallCollisionUsesParticleMassAndWallVelocity) {
  // A particle hitting a plate moving up at 0.5 m/s: relative normal speed 1.5, and with
  // the wall as infinite mass the rebound is v' = u_w + e (u_w - v).
  const auto r =
      collideWall({0, 1}, {0.2, -1.0}, 0, {0, 0.5}, kM, kD, 0.8, {}, TangentialRule::Smooth);
  EXPECT_NEAR(r.vn, 1.5, 1e-15);
  EXPECT_NEAR(r.v.z, 0.5 + 0.8 * 1.5, 1e-15);
  EXPECT_DOUBLE_EQ(r.v.x, 0.2);
  EXPECT_NEAR(r.impulse.z, kM * (1.0 + 0.8) * 1.5, 1e-18);
}

TEST(CollisionRule, RoughWallTangentialRestitutionHoldsAtContactPoint) {
  const Vec2 n{0, 1};
  const auto r =
      collideWall(n, {0.05, -1.0}, 3.0, {0, 0}, kM, kD, 0.9, {0.5, 0.35}, TangentialRule::Coulomb);
  const double vt_before = 0.05 - 0.5 * kD * 3.0 * 1.0;  // v_x - (d/2) w n_z
  const double vt_after = r.v.x - 0.5 * kD * r.w;
  EXPECT_NEAR(vt_after / vt_before, -r.e_t, 1e-12);
  EXPECT_NEAR(r.v.z, 0.9, 1e-15);
}
