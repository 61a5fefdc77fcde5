#include "particles/CollisionRule.hpp"

#include <algorithm>
#include <cmath>

namespace granwave {

double tangentialRestitution(const TangentialLaw& law, double e_n, double vn_abs, double vt_abs) {
  if (law.friction <= 0.0 || vt_abs <= 0.0) return -1.0;
  // |cot alpha| = |v_n| / |v_t| for the angle alpha between v_r and n.
  const double sliding = -1.0 + law.friction * (1.0 + e_n) * (vn_abs / vt_abs) / kBeta;
  return std::min(law.tangential_limit, sliding);
}

double pairNormalSpeed(Vec2 n, Vec2 v1, Vec2 v2) {
  // Spin does not contribute to the normal component of v_r.
  return -((v1.x - v2.x) * n.x + (v1.z - v2.z) * n.z);
}

PairCollisionResult collidePair(Vec2 n, Vec2 v1, Vec2 v2, double w1, double w2, double mass,
                                double diameter, double e_n, const TangentialLaw& law,
                                bool rough) {
  const double half_d = 0.5 * diameter;
  const double ws = w1 + w2;
  const Vec2 vr{v1.x - v2.x - half_d * ws * n.z, v1.z - v2.z + half_d * ws * n.x};
  const double vrn = vr.x * n.x + vr.z * n.z;  // < 0 when approaching
  const Vec2 vn{vrn * n.x, vrn * n.z};
  const Vec2 vt{vr.x - vn.x, vr.z - vn.z};
  const double vt_abs = std::sqrt(vt.x * vt.x + vt.z * vt.z);

  PairCollisionResult r;
  r.vn = -vrn;
  const bool tangential = rough && law.friction > 0.0;
  r.e_t = tangential ? tangentialRestitution(law, e_n, std::abs(vrn), vt_abs) : -1.0;
  const double cn = -0.5 * (1.0 + e_n) * mass;
  const double ct = tangential ? -0.5 * kBeta * (1.0 + r.e_t) * mass : 0.0;
  r.impulse = {cn * vn.x + ct * vt.x, cn * vn.z + ct * vt.z};
  r.v1 = {v1.x + r.impulse.x / mass, v1.z + r.impulse.z / mass};
  r.v2 = {v2.x - r.impulse.x / mass, v2.z - r.impulse.z / mass};
  if (tangential) {
    const double inertia = mass * diameter * diameter / 10.0;
    const double torque = n.z * r.impulse.x - n.x * r.impulse.z;  // (n x dp)_y
    const double dw = half_d / inertia * torque;
    r.w1 = w1 - dw;
    r.w2 = w2 - dw;
  } else {
    r.w1 = w1;
    r.w2 = w2;
  }
  return r;
}

WallCollisionResult collideWall(Vec2 n, Vec2 v, double w, Vec2 v_wall, double mass,
                                double diameter, double e_n, const TangentialLaw& law,
                                bool rough) {
  const double half_d = 0.5 * diameter;
  const Vec2 vr{v.x - v_wall.x - half_d * w * n.z, v.z - v_wall.z + half_d * w * n.x};
  const double vrn = vr.x * n.x + vr.z * n.z;
  const Vec2 vn{vrn * n.x, vrn * n.z};
  const Vec2 vt{vr.x - vn.x, vr.z - vn.z};
  const double vt_abs = std::sqrt(vt.x * vt.x + vt.z * vt.z);

  WallCollisionResult r;
  r.vn = -vrn;
  const bool tangential = rough && law.friction > 0.0;
  r.e_t = tangential ? tangentialRestitution(law, e_n, std::abs(vrn), vt_abs) : -1.0;
  const double cn = -(1.0 + e_n) * mass;
  const double ct = tangential ? -kBeta * (1.0 + r.e_t) * mass : 0.0;
  r.impulse = {cn * vn.x + ct * vt.x, cn * vn.z + ct * vt.z};
  r.v = {v.x + r.impulse.x / mass, v.z + r.impulse.z / mass};
  r.w = w;
  if (tangential) {
    const double inertia = mass * diameter * diameter / 10.0;
    r.w = w - half_d / inertia * (n.z * r.impulse.x - n.x * r.impulse.z);
  }
  return r;
}

}  // namespace granwave
