// The rough-elastic reading of the paper's "tangential COR set to 1" (walls) and
// "e_n = e_t = 1" (TC collisions): Luding's e_t = +1, the tangential velocity of the contact
// point is reversed. Checked on worked collisions of solid spheres (I = m d^2 / 10, beta = 2/7)
// against the definitions, with energy and angular momentum booked by hand:
// - e_n = 1, e_t = +1 conserves translational plus rotational energy exactly (Luding 1995);
// - the impulse acts at the contact point, so angular momentum about it (wall) or about the
//   origin (pair) is conserved;
// - a smooth contact leaves spin and tangential velocity alone.
#include <gtest/gtest.h>

#include <cmath>

#include "particles/CollisionRule.hpp"

using namespace granwave;

namespace {
constexpr double kM = 1.08e-5, kD = 0.002, kI = kM * kD * kD / 10.0;

double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.z * b.z; }
double cross(Vec2 a, Vec2 b) { return a.z * b.x - a.x * b.z; }  // (a x b)_y in the x-z plane
double sphereEnergy(Vec2 v, double w) { return 0.5 * kM * dot(v, v) + 0.5 * kI * w * w; }
// Tangential velocity of the contact point of a sphere touching a wall of normal n.
double wallContactTangential(Vec2 v, double w, Vec2 n) {
  const Vec2 t{-n.z, n.x};
  const Vec2 vc{v.x - 0.5 * kD * w * n.z, v.z + 0.5 * kD * w * n.x};
  return dot(vc, t);
}
}  // namespace

TEST(RoughElasticContact, WallReversesContactTangentialVelocityWithoutEnergyLoss) {
  // A sphere hits a resting floor at v = (0.3, -1.0) m/s spinning at w = 40 rad/s.
  const Vec2 n{0, 1}, v{0.3, -1.0};
  const double w = 40.0;
  const auto r = collideWall(n, v, w, {0, 0}, kM, kD, 1.0, {}, TangentialRule::RoughElastic);
  EXPECT_DOUBLE_EQ(r.e_t, 1.0);
  EXPECT_NEAR(r.v.z, 1.0, 1e-15);
  // u = v_x - (d/2) w = 0.26 m/s before, -0.26 after.
  EXPECT_NEAR(wallContactTangential(r.v, r.w, n), -wallContactTangential(v, w, n), 1e-14);
  EXPECT_NEAR(sphereEnergy(r.v, r.w) / sphereEnergy(v, w), 1.0, 1e-14);
  // Worked numbers: dp_x = -2 beta m u, so v_x' = 0.3 - (4/7) 0.26 and
  // w' = w - (d/(2I)) (n x dp)_y = w + (d/(2I)) (4/7) m u.
  const double u = 0.3 - 0.5 * kD * w;
  EXPECT_NEAR(r.v.x, 0.3 - 4.0 / 7.0 * u, 1e-15);
  EXPECT_NEAR(r.w, w + (4.0 / 7.0) * u * kM * 0.5 * kD / kI, 1e-11);
}

TEST(RoughElasticContact, WallConservesAngularMomentumAboutTheContactPoint) {
  // L_c = m (d/2) (n x v)_y + I w: the wall's impulse acts at the contact point.
  const Vec2 n{-1, 0}, v{0.7, 0.2};  // right side wall
  const double w = -25.0;
  const auto r = collideWall(n, v, w, {0, 0}, kM, kD, 0.8, {}, TangentialRule::RoughElastic);
  const double before = kM * 0.5 * kD * cross(n, v) + kI * w;
  const double after = kM * 0.5 * kD * cross(n, r.v) + kI * r.w;
  EXPECT_NEAR(after, before, 1e-13 * std::abs(kI * w));
  EXPECT_NEAR(wallContactTangential(r.v, r.w, n), -wallContactTangential(v, w, n), 1e-14);
}

TEST(RoughElasticContact, PairConservesMomentumAngularMomentumAndEnergy) {
  // Sphere 2 at the origin, sphere 1 at r1 = d n; oblique impact with spins.
  const Vec2 n{std::cos(2.2), std::sin(2.2)};
  const Vec2 v1{-0.4, 0.1}, v2{0.3, -0.6};
  const double w1 = 12.0, w2 = -30.0;
  const auto r = collidePair(n, v1, v2, w1, w2, kM, kD, 1.0, {}, TangentialRule::RoughElastic);
  EXPECT_NEAR(r.v1.x + r.v2.x, v1.x + v2.x, 1e-15);
  EXPECT_NEAR(r.v1.z + r.v2.z, v1.z + v2.z, 1e-15);
  const Vec2 r1{kD * n.x, kD * n.z};
  const double l_before = kM * cross(r1, v1) + kI * (w1 + w2);
  const double l_after = kM * cross(r1, r.v1) + kI * (r.w1 + r.w2);
  EXPECT_NEAR(l_after, l_before, 1e-12 * kI * 30.0);
  const double e_before = sphereEnergy(v1, w1) + sphereEnergy(v2, w2);
  const double e_after = sphereEnergy(r.v1, r.w1) + sphereEnergy(r.v2, r.w2);
  EXPECT_NEAR(e_after / e_before, 1.0, 1e-14);
  // v_r.t reversed at the contact point (Luding's e_t = +1), v_r.n reversed (e_n = 1).
  const Vec2 t{-n.z, n.x};
  auto vr = [&](Vec2 a, Vec2 b, double wa, double wb) {
    const double h = 0.5 * kD * (wa + wb);
    return Vec2{a.x - b.x - h * n.z, a.z - b.z + h * n.x};
  };
  EXPECT_NEAR(dot(vr(r.v1, r.v2, r.w1, r.w2), t), -dot(vr(v1, v2, w1, w2), t), 1e-14);
  EXPECT_NEAR(dot(vr(r.v1, r.v2, r.w1, r.w2), n), -dot(vr(v1, v2, w1, w2), n), 1e-14);
}

TEST(RoughElasticContact, CoulombWithoutFrictionAndSmoothLeaveSpinAndTangentialVelocity) {
  const Vec2 n{0, 1}, v{0.3, -1.0};
  for (TangentialRule rule : {TangentialRule::Smooth, TangentialRule::Coulomb}) {
    const auto r = collideWall(n, v, 40.0, {0, 0}, kM, kD, 1.0, {0.0, 0.35}, rule);
    EXPECT_DOUBLE_EQ(r.w, 40.0);
    EXPECT_DOUBLE_EQ(r.v.x, 0.3);
    EXPECT_DOUBLE_EQ(r.e_t, -1.0);
  }
}
