#pragma once
// Instantaneous collision of two equal rough spheres moving in the x-z plane and spinning
// about y (Walton 1986; Luding 1995; paper Eqs. 1-3):
//   v_r = v1 - v2 - (d/2)(w1 + w2) e_y x n,      n = (r1 - r2)/|r1 - r2|
//   dp  = -(1/2)(1 + e_n) m v_n - (beta/2)(1 + e_t) m v_t,   beta = 2/7 for solid spheres
//   v1' = v1 + dp/m, v2' = v2 - dp/m, w' = w - (d/(2I)) (n x dp)_y for both spheres
// Tangential restitution in Luding's convention (v_t' = -e_t v_t; e_t = -1 smooth, +1 rough),
// limited by Coulomb friction: e_t = min(e_t0, -1 + mu (1 + e_n) |cot alpha| / beta).
// A wall is a partner of infinite mass and no spin: dp = -(1 + e_n) m v_n - beta (1 + e_t) m v_t.
// Vectors are (x, z) pairs; e_y x (nx, nz) = (nz, -nx).

namespace granwave {

struct Vec2 {
  double x = 0, z = 0;
};

// Which tangential impulse a contact gets. Smooth: none (v_t' = v_t, e_t = -1). RoughElastic:
// e_t = +1, the tangential contact velocity is reversed with no loss (with e_n = 1 the
// collision conserves kinetic plus rotational energy). Coulomb: Luding's friction law below
// (smooth when mu = 0).
enum class TangentialRule { Smooth, RoughElastic, Coulomb };

struct TangentialLaw {
  double friction = 0;          // mu; 0 = smooth contact, no tangential impulse
  double tangential_limit = 0;  // e_t0
};

// Moment of inertia of a solid sphere I = m d^2 / 10 gives beta = 2/7 (paper).
inline constexpr double kBeta = 2.0 / 7.0;

// Luding's tangential restitution for a contact with normal speed vn_abs and tangential
// speed vt_abs (both >= 0) and normal restitution e_n.
double tangentialRestitution(const TangentialLaw& law, double e_n, double vn_abs, double vt_abs);

struct PairCollisionResult {
  Vec2 v1, v2;            // post-collision velocities
  double w1 = 0, w2 = 0;  // post-collision spins (unchanged when friction is 0)
  Vec2 impulse;           // dp on particle 1, kg m/s
  double vn = 0;          // |normal relative velocity| at impact, m/s (>= 0 when approaching)
  double e_t = -1;        // tangential restitution used
};

// e_n already evaluated by the caller (it depends on vn, the law and the TC rule); `rule`
// chooses the tangential impulse (the TC model and the walls have their own).
PairCollisionResult collidePair(Vec2 n, Vec2 v1, Vec2 v2, double w1, double w2, double mass,
                                double diameter, double e_n, const TangentialLaw& law,
                                TangentialRule rule);

// Normal relative speed of an approaching pair (>= 0), from the same v_r as collidePair.
double pairNormalSpeed(Vec2 n, Vec2 v1, Vec2 v2);

struct WallCollisionResult {
  Vec2 v;
  double w = 0;
  Vec2 impulse;
  double vn = 0;  // |normal velocity relative to the wall| at impact
  double e_t = -1;
};

// n points from the wall into the container; v_wall is the wall's velocity.
WallCollisionResult collideWall(Vec2 n, Vec2 v, double w, Vec2 v_wall, double mass, double diameter,
                                double e_n, const TangentialLaw& law, TangentialRule rule);

}  // namespace granwave
