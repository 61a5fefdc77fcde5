#pragma once
// The local constitutive model the PDE right-hand side needs at one point: pressure,
// transport coefficients, collisional cooling, sound speed and the wall's dissipation
// factor, as functions of (rho, theta). It composes the closures (pair correlation,
// restitution closure, JR or Garzo-Dufty transport) chosen by the scene, and applies the
// Knudsen limiter: eta, lambda_b and kappa are multiplied by 1 / (1 + l / l_max), l the mean
// free path 1/(2 sqrt(2) sigma n g2), so the diffusivities stay bounded in the dilute gas
// above and below the layer, where Navier-Stokes order does not hold anyway
// (physics-hydro.md 2.3, option 2; docs/hydro.md says why this option).
#include "hydro/RestitutionClosure.hpp"
#include "hydro/TransportCoefficients.hpp"

namespace granwave::hydro {

enum class TransportSet { JenkinsRichman, GarzoDufty };

struct LocalState {
  double p = 0;            // Pa m (2D pressure)
  double viscosity = 0;    // lambda_b + eta (d = 2 normal-stress coefficient), kg/s
  double kappa_theta = 0;  // heat flux q = -kappa_theta d(theta)/dz, kg/s
  double cooling = 0;      // D_c, W/m^2
  double sound_speed = 0;  // m/s, adiabatic
};

struct ConstitutiveModel {
  double mass = 0, sigma = 0;
  RestitutionClosure restitution;       // pair collisions
  RestitutionClosure wall_restitution;  // particle-wall collisions (the paper: the same law)
  TransportSet transport = TransportSet::JenkinsRichman;
  double knudsen_length = 0;   // l_max, m (0 = no limiter)
  double side_wall_width = 0;  // L_x, m, for the side-wall sink (0 = no side walls)

  // Everything (pressure, transport, cooling, sound speed) at cell centres.
  LocalState evaluate(double rho, double theta) const;
  // Only p = n T (1 + Phi_P nu g2): the face fluxes need nothing else.
  double pressure(double rho, double theta) const;
  // Energy flux into a flat wall: Phi_W^wall(theta) p sqrt(theta / (2 pi)).
  double wallDissipation(double p, double theta) const;
  // Side walls of the Q2D cell as a sink per unit area (physics-hydro.md 2.2, optional):
  // D_side = (2 / L_x) Phi_W^wall(theta) p sqrt(theta / (2 pi)); 0 without side walls.
  double sideWallSink(double p, double theta) const;
};

}  // namespace granwave::hydro
