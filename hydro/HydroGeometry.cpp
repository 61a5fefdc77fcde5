#include "hydro/HydroGeometry.hpp"

#include <cmath>

namespace granwave::hydro {

namespace {

// Quintic ramp r(s) = 10 s^3 - 15 s^4 + 6 s^5 on s = t / t_r in [0, 1]: r, r' and r'' are
// continuous, so g_eff(t) is smooth at both ends of the ramp.
struct Ramp {
  double r = 1, dr = 0, d2r = 0;  // r, dr/dt, d2r/dt2
};
Ramp ramp(double t, double t_r) {
  if (t_r <= 0 || t >= t_r) return {};
  if (t <= 0) return {0, 0, 0};
  const double s = t / t_r;
  return {s * s * s * (10 - 15 * s + 6 * s * s), 30 * s * s * (1 - s) * (1 - s) / t_r,
          60 * s * (1 - s) * (1 - 2 * s) / (t_r * t_r)};
}

}  // namespace

double HydroGeometry::plateHeight(double t) const {
  return amplitude * ramp(t, ramp_time).r * std::sin(omega * t);
}

double HydroGeometry::plateVelocity(double t) const {
  const Ramp r = ramp(t, ramp_time);
  return amplitude * (r.dr * std::sin(omega * t) + r.r * omega * std::cos(omega * t));
}

double HydroGeometry::plateAcceleration(double t) const {
  const Ramp r = ramp(t, ramp_time);
  const double s = std::sin(omega * t), c = std::cos(omega * t);
  return amplitude * (r.d2r * s + 2 * r.dr * omega * c - r.r * omega * omega * s);
}

}  // namespace granwave::hydro
