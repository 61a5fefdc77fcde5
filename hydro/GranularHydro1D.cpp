#include "hydro/GranularHydro1D.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace granwave::hydro {

namespace {

// max(x, floor), smoothed over a width of floor/10 so the right-hand side stays
// differentiable (Newton needs it; physics-hydro.md 5.6).
inline double smoothFloor(double x, double floor) {
  const double w = 0.1 * floor;
  return 0.5 * (x + floor + std::sqrt((x - floor) * (x - floor) + w * w));
}

// Smooth van Albada slope: (a (b^2 + e) + b (a^2 + e)) / (a^2 + b^2 + 2 e).
inline double slope(double a, double b, double eps2) {
  return (a * (b * b + eps2) + b * (a * a + eps2)) / (a * a + b * b + 2 * eps2);
}

}  // namespace

GranularHydro1D::GranularHydro1D(const HydroGeometry& g, const ConstitutiveModel& model)
    : g_(g), model_(model) {
  // Floors far below anything physical: 1e-8 of close packing, 1e-8 of g sigma.
  const double rho_cp = model.mass * (std::numbers::pi / (2 * std::sqrt(3.0))) /
                        (std::numbers::pi * model.sigma * model.sigma / 4);
  rho_min_ = 1e-8 * rho_cp;
  theta_min_ = 1e-8 * std::max(g.gravity, 1.0) * model.sigma;
  prim_.resize(g.cells + 4);
  local_.resize(g.cells);
  flux_.resize(static_cast<std::size_t>(kVars) * (g.cells + 1));
}

double GranularHydro1D::effectiveGravity(double t) const {
  // g_eff = g + z_b''(t) = g - A w^2 sin(w t)
  return g_.gravity - g_.amplitude * g_.omega * g_.omega * std::sin(g_.omega * t);
}

GranularHydro1D::Primitive GranularHydro1D::primitive(const double* U, int i) const {
  const double* c = U + kVars * i;
  const double rho = smoothFloor(c[0], rho_min_);
  const double u = c[1] / rho;
  const double theta = smoothFloor(c[2] / rho - 0.5 * u * u, theta_min_);
  return {rho, u, theta};
}

std::string GranularHydro1D::componentName(int k) const {
  static const char* names[kVars] = {"density", "momentum", "energy"};
  const int i = k / kVars;
  return "cell " + std::to_string(i) + " (z' = " + std::to_string(cellCentre(i) * 1e3) +
         " mm above the plate), " + names[k % kVars];
}

int GranularHydro1D::rightHandSide(double t, const double* U, double* dUdt) const {
  const int N = g_.cells;
  const double h = dz();
  for (int k = 0; k < kVars * N; ++k)
    if (!std::isfinite(U[k])) return 1;  // recoverable: CVODE retries with a smaller step

  // Primitives with two reflecting ghost cells at each wall (index shift 2).
  for (int i = 0; i < N; ++i) prim_[i + 2] = primitive(U, i);
  prim_[1] = {prim_[2].rho, -prim_[2].u, prim_[2].theta};
  prim_[0] = {prim_[3].rho, -prim_[3].u, prim_[3].theta};
  prim_[N + 2] = {prim_[N + 1].rho, -prim_[N + 1].u, prim_[N + 1].theta};
  prim_[N + 3] = {prim_[N].rho, -prim_[N].u, prim_[N].theta};
  for (int i = 0; i < N; ++i) local_[i] = model_.evaluate(prim_[i + 2].rho, prim_[i + 2].theta);

  const double eps_rho2 = rho_min_ * rho_min_, eps_u2 = 1e-12, eps_t2 = theta_min_ * theta_min_;
  auto faceState = [&](int cell, double side) {  // cell in ghost indexing; side = +1/2 or -1/2
    const Primitive& a = prim_[cell - 1];
    const Primitive& b = prim_[cell];
    const Primitive& c = prim_[cell + 1];
    Primitive s;
    s.rho = smoothFloor(b.rho + side * slope(b.rho - a.rho, c.rho - b.rho, eps_rho2), rho_min_);
    s.u = b.u + side * slope(b.u - a.u, c.u - b.u, eps_u2);
    s.theta = smoothFloor(b.theta + side * slope(b.theta - a.theta, c.theta - b.theta, eps_t2),
                          theta_min_);
    return s;
  };

  // Faces f = 0..N between ghost-indexed cells f+1 (left) and f+2 (right).
  for (int f = 0; f <= N; ++f) {
    const Primitive L = faceState(f + 1, +0.5);
    const Primitive R = faceState(f + 2, -0.5);
    const double pL = model_.pressure(L.rho, L.theta);
    const double pR = model_.pressure(R.rho, R.theta);
    // Wave-speed bound from the adjacent cells' sound speeds (local Lax-Friedrichs); the
    // sound speed is computed once per cell, in evaluate().
    const double cL = local_[std::max(f - 1, 0)].sound_speed;
    const double cR = local_[std::min(f, N - 1)].sound_speed;
    const double mL = L.rho * L.u, mR = R.rho * R.u;
    const double EL = L.rho * (0.5 * L.u * L.u + L.theta), ER = R.rho * (0.5 * R.u * R.u + R.theta);
    // Local speed bound, smoothed: sqrt(x^2 + tiny) for |x|.
    const double aL = std::sqrt(L.u * L.u + 1e-12) + cL;
    const double aR = std::sqrt(R.u * R.u + 1e-12) + cR;
    const double a = 0.5 * (aL + aR + std::sqrt((aL - aR) * (aL - aR) + 1e-12));
    double* F = &flux_[static_cast<std::size_t>(kVars) * f];
    F[0] = 0.5 * (mL + mR) - 0.5 * a * (R.rho - L.rho);
    F[1] = 0.5 * (mL * L.u + pL + mR * R.u + pR) - 0.5 * a * (mR - mL);
    F[2] = 0.5 * ((EL + pL) * L.u + (ER + pR) * R.u) - 0.5 * a * (ER - EL);
    if (f == 0 || f == N) {  // walls: no mass or convective energy through them
      F[0] = 0;
      F[2] = 0;
    }
    // Viscous and heat fluxes.
    if (f > 0 && f < N) {
      const Primitive& pa = prim_[f + 1];
      const Primitive& pb = prim_[f + 2];
      const LocalState& la = local_[f - 1];
      const LocalState& lb = local_[f];
      const double tau = 0.5 * (la.viscosity + lb.viscosity) * (pb.u - pa.u) / h;
      const double q = -0.5 * (la.kappa_theta + lb.kappa_theta) * (pb.theta - pa.theta) / h;
      F[1] -= tau;
      F[2] += -tau * 0.5 * (pa.u + pb.u) + q;
    } else {
      const int i = f == 0 ? 0 : N - 1;
      const Primitive& p = prim_[i + 2];
      const LocalState& l = local_[i];
      const double du = f == 0 ? (p.u - 0.0) / (0.5 * h) : (0.0 - p.u) / (0.5 * h);
      F[1] -= l.viscosity * du;
      const double Dw = model_.wallDissipation(l.p, p.theta);
      F[2] += f == 0 ? -Dw : Dw;  // energy flows out through both walls
    }
  }

  const double geff = effectiveGravity(t);
  for (int i = 0; i < N; ++i) {
    const double* Fl = &flux_[static_cast<std::size_t>(kVars) * i];
    const double* Fr = &flux_[static_cast<std::size_t>(kVars) * (i + 1)];
    double* d = dUdt + kVars * i;
    const double* c = U + kVars * i;
    d[0] = -(Fr[0] - Fl[0]) / h;
    d[1] = -(Fr[1] - Fl[1]) / h - c[0] * geff;
    // Work of gravity with the same mass fluxes that move the mass: then total energy
    // (kinetic + internal + potential) is conserved by the discretisation itself.
    d[2] = -(Fr[2] - Fl[2]) / h - 0.5 * (Fl[0] + Fr[0]) * geff - local_[i].cooling -
           model_.sideWallSink(local_[i].p, prim_[i + 2].theta);
  }
  for (int k = 0; k < kVars * N; ++k)
    if (!std::isfinite(dUdt[k])) return 1;
  return 0;
}

}  // namespace granwave::hydro
