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

namespace {

struct ContactImpulse {
  Vec2 dp;        // impulse on the particle (particle 1 of a pair)
  double vn = 0;  // approach speed, >= 0 when approaching
  double e_t = -1;
};

// dp = -m_eff (1 + e_n) v_n - m_eff beta (1 + e_t) v_t, with v_n, v_t the normal and
// tangential parts of the contact-point relative velocity v_r; m_eff = m/2 for two equal
// spheres, m against a wall (paper Eq. 3 and its wall form).
ContactImpulse contactImpulse(Vec2 n, Vec2 vr, double m_eff, double e_n, const TangentialLaw& law,
                              TangentialRule rule) {
  const double vrn = vr.x * n.x + vr.z * n.z;  // < 0 when approaching
  const Vec2 vn{vrn * n.x, vrn * n.z};
  const Vec2 vt{vr.x - vn.x, vr.z - vn.z};
  ContactImpulse c;
  c.vn = -vrn;
  const bool coulomb = rule == TangentialRule::Coulomb && law.friction > 0.0;
  const bool tangential = coulomb || rule == TangentialRule::RoughElastic;
  if (coulomb)
    c.e_t = tangentialRestitution(law, e_n, std::abs(vrn), std::sqrt(vt.x * vt.x + vt.z * vt.z));
  else if (rule == TangentialRule::RoughElastic)
    c.e_t = 1.0;  // v_t' = -v_t (Luding's e_t = +1)
  const double cn = -(1.0 + e_n) * m_eff;
  const double ct = tangential ? -kBeta * (1.0 + c.e_t) * m_eff : 0.0;
  c.dp = {cn * vn.x + ct * vt.x, cn * vn.z + ct * vt.z};
  return c;
}

// Spin change of a sphere whose contact point (centre + (d/2)(-n)) takes the impulse dp.
double spinChange(Vec2 n, Vec2 dp, double mass, double diameter) {
  const double inertia = mass * diameter * diameter / 10.0;
  return -0.5 * diameter / inertia * (n.z * dp.x - n.x * dp.z);  // -(d/(2I)) (n x dp)_y
}

}  // namespace

PairCollisionResult collidePair(Vec2 n, Vec2 v1, Vec2 v2, double w1, double w2, double mass,
                                double diameter, double e_n, const TangentialLaw& law,
                                TangentialRule rule) {
  const double half_d = 0.5 * diameter;
  const double ws = w1 + w2;
  const Vec2 vr{v1.x - v2.x - half_d * ws * n.z, v1.z - v2.z + half_d * ws * n.x};
  const ContactImpulse c = contactImpulse(n, vr, 0.5 * mass, e_n, law, rule);
  PairCollisionResult r;
  r.vn = c.vn;
  r.e_t = c.e_t;
  r.impulse = c.dp;
  r.v1 = {v1.x + c.dp.x / mass, v1.z + c.dp.z / mass};
  r.v2 = {v2.x - c.dp.x / mass, v2.z - c.dp.z / mass};
  const double dw = c.e_t > -1.0 ? spinChange(n, c.dp, mass, diameter) : 0.0;
  r.w1 = w1 + dw;  // both spheres: -(d/2I) n x dp (paper Eq. 2)
  r.w2 = w2 + dw;
  return r;
}

WallCollisionResult collideWall(Vec2 n, Vec2 v, double w, Vec2 v_wall, double mass, double diameter,
                                double e_n, const TangentialLaw& law, TangentialRule rule) {
  const double half_d = 0.5 * diameter;
  const Vec2 vr{v.x - v_wall.x - half_d * w * n.z, v.z - v_wall.z + half_d * w * n.x};
  const ContactImpulse c = contactImpulse(n, vr, mass, e_n, law, rule);
  WallCollisionResult r;
  r.vn = c.vn;
  r.e_t = c.e_t;
  r.impulse = c.dp;
  r.v = {v.x + c.dp.x / mass, v.z + c.dp.z / mass};
  r.w = w + (c.e_t > -1.0 ? spinChange(n, c.dp, mass, diameter) : 0.0);
  return r;
}

}  // namespace granwave
