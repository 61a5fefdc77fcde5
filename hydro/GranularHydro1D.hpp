#pragma once
// Navier-Stokes-order hydrodynamics of inelastic hard disks (d = 2) for the horizontally
// averaged layer, in the frame of the vibrating plate (physics-hydro.md 2.1):
//   d(rho)/dt + d(rho u)/dz = 0
//   d(rho u)/dt + d(rho u^2 + P_zz)/dz = -rho g_eff(t)
//   dE/dt + d((E + P_zz) u + q)/dz = -rho u g_eff(t) - D_c
//   E = rho u^2/2 + rho theta,  P_zz = p - (lambda_b + eta) du/dz,  q = -kappa_theta d(theta)/dz
//   g_eff(t) = g (1 - Gamma sin(omega t))
// on z' in [0, L_z] (plate to lid), with zero mass flux through both walls, the wall's
// collisional dissipation flux D_w = Phi_W^wall p sqrt(theta/(2 pi)) as the energy flux into
// each wall, reflecting ghost cells for the inviscid flux and u = 0 at the wall for the
// viscous one.
// Method of lines: finite volumes of width dz, Kurganov-Tadmor central-upwind fluxes with
// MUSCL reconstruction of (rho, u, theta) (van Albada limiter: smooth, so Newton converges),
// central viscous and heat fluxes. Unknowns interleaved per cell [rho, rho u, E], so the
// Jacobian is banded with half-bandwidth 3 s + 2 = 8 (stencil s = 2).
// Floors (rho >= rho_min, theta >= theta_min) are applied only to temporaries inside the
// right-hand side, never to the state (CVODE guide).
#include <string>
#include <vector>

#include "hydro/ConstitutiveModel.hpp"

namespace granwave::hydro {

struct HydroGeometry {
  int cells = 400;
  double height = 0.06;  // L_z, m
  double gravity = 9.81;
  double amplitude = 0;  // A, m
  double omega = 0;      // rad/s
};

class GranularHydro1D {
 public:
  static constexpr int kVars = 3;  // rho, rho u, E per cell
  static constexpr int kHalfBand = 8;

  GranularHydro1D(const HydroGeometry& geometry, const ConstitutiveModel& model);

  int size() const { return kVars * g_.cells; }
  double dz() const { return g_.height / g_.cells; }
  double cellCentre(int i) const { return (i + 0.5) * dz(); }
  const HydroGeometry& geometry() const { return g_; }
  const ConstitutiveModel& model() const { return model_; }
  double effectiveGravity(double t) const;

  // dU/dt; returns 0, or 1 (recoverable) if the state is not finite.
  int rightHandSide(double t, const double* U, double* dUdt) const;

  // Floors used on temporaries.
  double rhoFloor() const { return rho_min_; }
  double thetaFloor() const { return theta_min_; }
  std::string componentName(int k) const;

 private:
  struct Primitive {
    double rho, u, theta;
  };
  Primitive primitive(const double* U, int i) const;
  HydroGeometry g_;
  ConstitutiveModel model_;
  double rho_min_, theta_min_;
  mutable std::vector<Primitive> prim_;
  mutable std::vector<LocalState> local_;
  mutable std::vector<double> flux_;
};

}  // namespace granwave::hydro
