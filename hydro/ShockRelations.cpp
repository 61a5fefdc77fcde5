#include "hydro/ShockRelations.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "hydro/SoundSpeed.hpp"

namespace granwave::hydro {

namespace {

constexpr double kDimension = 2.0;  // translational kinetics of disks
constexpr double kInf = std::numeric_limits<double>::infinity();

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument("ShockRelations: " + message);
}

void requireUpstream(double nu1, double piston_speed) {
  require(nu1 > 0.0 && nu1 < 1.0,
          "upstream area fraction nu1 = " + std::to_string(nu1) + " must be in (0, 1)");
  require(piston_speed > 0.0 && std::isfinite(piston_speed),
          "piston speed U_p = " + std::to_string(piston_speed) + " m/s must be finite and > 0");
}

// Brent's method (zeroin) on [a, b] with f(a) f(b) <= 0; converges to a few ulps of the root.
template <class F>
double brentRoot(const F& f, double a, double b, double fa, double fb) {
  if (fa == 0.0) return a;
  if (fb == 0.0) return b;
  constexpr double eps = std::numeric_limits<double>::epsilon();
  double c = a, fc = fa, d = b - a, e = d;
  for (int iter = 0; iter < 300; ++iter) {
    if ((fb > 0.0) == (fc > 0.0)) {
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tol = 2.0 * eps * std::abs(b) + std::numeric_limits<double>::min();
    const double m = 0.5 * (c - b);
    if (std::abs(m) <= tol || fb == 0.0) return b;
    if (std::abs(e) >= tol && std::abs(fa) > std::abs(fb)) {
      const double s = fb / fa;
      double p, q;
      if (a == c) {  // secant
        p = 2.0 * m * s;
        q = 1.0 - s;
      } else {  // inverse quadratic interpolation
        const double qa = fa / fc, r = fb / fc;
        p = s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0));
        q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0.0) {
        q = -q;
      } else {
        p = -p;
      }
      if (2.0 * p < std::min(3.0 * m * q - std::abs(tol * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = m;
        e = m;
      }
    } else {
      d = m;
      e = m;
    }
    a = b;
    fa = fb;
    b += std::abs(d) > tol ? d : (m > 0.0 ? tol : -tol);
    fb = f(b);
  }
  return b;
}

// Root of f on (nu1, 1) with f(nu1) of sign `sign_low` and f -> -sign_low as nu -> 1 (g2
// diverges): the upper bracket is moved towards 1 until the sign changes.
template <class F>
double rootAboveUpstream(const F& f, double nu1, double f_low, const char* what) {
  double hi = nu1 + 0.999 * (1.0 - nu1);
  double f_hi = f(hi);
  while ((f_hi > 0.0) == (f_low > 0.0) && 1.0 - hi > 1e-14) {
    hi = 1.0 - 1e-3 * (1.0 - hi);
    f_hi = f(hi);
  }
  if ((f_hi > 0.0) == (f_low > 0.0)) {
    throw std::runtime_error(std::string("ShockRelations: no ") + what +
                             " root below nu2 = 1 for nu1 = " + std::to_string(nu1));
  }
  return brentRoot(f, nu1, hi, f_low, f_hi);
}

double upstreamMach(const GasState& up, double speed, const RestitutionClosure& r) {
  const double c1 = adiabaticSoundSpeed(up.nu, up.theta, r);
  return c1 > 0.0 ? speed / c1 : kInf;
}

}  // namespace

ShockSolution strongShock(double nu1, double piston_speed, const RestitutionClosure& restitution) {
  requireUpstream(nu1, piston_speed);
  const double theta2 = piston_speed * piston_speed / kDimension;
  // f(nu2) = d nu1 - (nu2 - nu1) F(nu2, theta2): > 0 at nu1, -> -inf at 1, decreasing.
  const auto f = [&](double nu2) {
    return kDimension * nu1 - (nu2 - nu1) * pressureFactor(nu2, theta2, restitution);
  };
  ShockSolution s;
  s.nu = rootAboveUpstream(f, nu1, kDimension * nu1, "strong-shock");
  s.theta = theta2;
  s.speed = piston_speed * s.nu / (s.nu - nu1);
  s.mach = kInf;
  return s;
}

ShockSolution rankineHugoniot(const GasState& up, double piston_speed,
                              const RestitutionClosure& restitution) {
  requireUpstream(up.nu, piston_speed);
  require(up.theta >= 0.0 && std::isfinite(up.theta),
          "upstream theta1 = " + std::to_string(up.theta) + " m^2/s^2 must be finite and >= 0");
  const double U2 = piston_speed * piston_speed;
  const double thetaF1 = up.theta * pressureFactor(up.nu, up.theta, restitution);  // p1/rho1
  const auto theta2Of = [&](double nu2) {
    return up.theta + (2.0 / kDimension) * (thetaF1 * (1.0 - up.nu / nu2) + 0.5 * U2);
  };
  // H(nu2) = (theta2 F2 - theta1 F1 / r)(r - 1) - U_p^2, r = nu2/nu1.
  const auto H = [&](double nu2) {
    const double r = nu2 / up.nu;
    const double theta2 = theta2Of(nu2);
    const double thetaF2 = theta2 * pressureFactor(nu2, theta2, restitution);
    return (thetaF2 - thetaF1 / r) * (nu2 - up.nu) / up.nu - U2;
  };
  ShockSolution s;
  s.nu = rootAboveUpstream(H, up.nu, -U2, "Rankine-Hugoniot");
  s.theta = theta2Of(s.nu);
  s.speed = piston_speed * s.nu / (s.nu - up.nu);
  s.mach = upstreamMach(up, s.speed, restitution);
  return s;
}

JumpResiduals jumpResiduals(const GasState& up, const ShockSolution& down, double piston_speed,
                            const RestitutionClosure& restitution) {
  const double nu1 = up.nu, nu2 = down.nu, s = down.speed, U = piston_speed;
  // Pressures and specific areas in units of m / (pi sigma^2 / 4): rho -> nu.
  const double p1 = nu1 * up.theta * pressureFactor(nu1, up.theta, restitution);
  const double p2 = nu2 * down.theta * pressureFactor(nu2, down.theta, restitution);
  const double flux = nu1 * s;  // rho1 s
  JumpResiduals r;
  r.mass = (nu1 * s - nu2 * (s - U)) / flux;
  r.momentum = (p2 - p1 - flux * U) / (flux * U);
  r.energy =
      (0.5 * kDimension * (down.theta - up.theta) - 0.5 * (p1 + p2) * (1.0 / nu1 - 1.0 / nu2)) /
      (0.5 * kDimension * down.theta);
  return r;
}

double idealGasDensityRatio(double mach) {
  const double M2 = mach * mach;
  return 3.0 * M2 / (M2 + 2.0);
}

double idealGasPressureRatio(double mach) { return (4.0 * mach * mach - 1.0) / 3.0; }

IdealGasShock idealGasPistonShock(double theta1, double piston_speed) {
  require(piston_speed > 0.0,
          "piston speed U_p = " + std::to_string(piston_speed) + " m/s must be > 0");
  require(theta1 >= 0.0, "upstream theta1 = " + std::to_string(theta1) + " must be >= 0");
  constexpr double gamma = (kDimension + 2.0) / kDimension;
  const double a = 0.25 * (gamma + 1.0) * piston_speed;
  IdealGasShock r;
  r.speed = a + std::sqrt(a * a + gamma * theta1);
  r.density_ratio = r.speed / (r.speed - piston_speed);
  // p = rho theta: p2/p1 = 1 + rho1 s U_p / p1 = 1 + s U_p / theta1.
  r.theta = theta1 + (2.0 / kDimension) * (0.5 * piston_speed * piston_speed +
                                           theta1 * (1.0 - 1.0 / r.density_ratio));
  if (theta1 > 0.0) {
    r.mach = r.speed / std::sqrt(gamma * theta1);
    r.pressure_ratio = 1.0 + r.speed * piston_speed / theta1;
    r.temperature_ratio = r.theta / theta1;
  } else {
    r.mach = r.pressure_ratio = r.temperature_ratio = kInf;
  }
  return r;
}

double compactionFrontSpeed(double nu1, double piston_speed, double nu_max) {
  require(nu1 >= 0.0 && nu1 < nu_max, "upstream area fraction nu1 = " + std::to_string(nu1) +
                                          " must be in [0, nu_max = " + std::to_string(nu_max) +
                                          ")");
  return piston_speed * nu_max / (nu_max - nu1);
}

}  // namespace granwave::hydro
