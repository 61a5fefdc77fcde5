#pragma once
// Time until two spheres of diameter d, moving with constant relative velocity v from
// relative position r, first touch: smallest tau >= 0 with |r + v tau| = d.
// Gravity is the same for all particles, so pair relative motion is a straight line even
// under gravity. Cancellation-free root 2c / (-b + sqrt(b^2 - ac)) as in DynamO's
// ray-sphere kernel; a slightly overlapping but approaching pair collides at once (tau = 0);
// a receding pair never collides. A touching pair whose approach speed is below
// `approach_tol` (round-off, e.g. right after an e_n = 0 collision) is not approaching:
// colliding it "at once" would change nothing and repeat forever.
// Round-off in a velocity difference scales with the velocities themselves, so callers
// pass kApproachTolerance times the particles' speeds.
inline constexpr double kApproachTolerance = 1e-9;
#include <cmath>
#include <limits>

namespace granwave {

inline double pairCollisionTime(double rx, double rz, double vx, double vz, double diameter,
                                double approach_tol = 0.0) {
  constexpr double kNever = std::numeric_limits<double>::infinity();
  const double b = rx * vx + rz * vz;
  if (b >= 0.0) return kNever;
  const double c = rx * rx + rz * rz - diameter * diameter;
  const double a = vx * vx + vz * vz;
  if (c <= 0.0) return -b > approach_tol * diameter ? 0.0 : kNever;
  const double disc = b * b - a * c;
  if (disc < 0.0) return kNever;
  return c / (-b + std::sqrt(disc));
}

// Two particles carried by the same wall keep their vertical separation rz, so they can only
// meet horizontally: at |rx| = sqrt(d^2 - rz^2) (never if |rz| >= d). A pair found at or
// inside that distance (round-off) collides at once only if it approaches along the contact
// normal n = (rx, rz) / d faster than round-off: -rx vx / d > approach_tol, as for free pairs
// (pairCollisionTime). A pair stacked exactly on top of each other (rx = 0, e.g. both against
// a side wall) has a vertical normal: sliding sideways moves it apart, never together.
inline double riderPairCollisionTime(double rx, double rz, double vx, double diameter,
                                     double approach_tol = 0.0) {
  constexpr double kNever = std::numeric_limits<double>::infinity();
  const double w2 = diameter * diameter - rz * rz;
  if (w2 <= 0.0) return kNever;
  const double gap = std::abs(rx) - std::sqrt(w2);
  const double closing = rx > 0 ? -vx : vx;  // > 0 when |rx| decreases
  if (gap <= 0.0) return closing * std::abs(rx) > approach_tol * diameter ? 0.0 : kNever;
  return closing > approach_tol ? gap / closing : kNever;
}

}  // namespace granwave
