#pragma once
// The local constitutive model the discrete operator needs in one cell: pressures, transport
// coefficients, collisional cooling, sound speeds and the wall-loss factor, as functions of
// (rho, theta). It composes the closures the scene chooses (pair correlation, contact
// pressure, restitution closure, Jenkins-Richman or Garzo-Dufty transport) and applies the
// Knudsen limiter: eta, lambda_b and kappa are multiplied by 1 / (1 + l / l_max), l the mean
// free path 1/(2 sqrt(2) sigma n g2), so the diffusivities stay bounded in the dilute gas above
// and below the layer, where Navier-Stokes order does not hold anyway (docs/hydro.md).
// Everything is a template on the scalar type (hydro/Scalar.hpp) for the exact Jacobian.
#include <cmath>
#include <numbers>

#include "hydro/ContactPressure.hpp"
#include "hydro/PairCorrelation.hpp"
#include "hydro/RestitutionClosure.hpp"
#include "hydro/RoughCollisions.hpp"
#include "hydro/TransportCoefficients.hpp"

namespace granwave::hydro {

enum class TransportSet { JenkinsRichman, GarzoDufty };

template <class S = double>
struct LocalState {
  S p;                  // total pressure: kinetic-collisional + contact, N/m
  S p_kinetic;          // n T (1 + Phi_P nu g2), N/m
  S viscosity;          // lambda_b + eta (d = 2 normal-stress coefficient), kg/s, limited
  S shear_viscosity;    // eta alone (the 2D operator's shear stress), kg/s, limited
  S kappa_theta;        // heat flux q = -kappa_theta d(theta)/dz, kg/s, limited
  S cooling;            // D_c, W/m^2
  S sound_speed;        // adiabatic, m/s (contact part included)
  S isothermal_speed2;  // dp/drho at fixed theta, m^2/s^2
  S wall_loss;          // Phi_W^wall sqrt(theta/(2 pi)), m/s: energy flux into a wall per p_kinetic
  S g2;                 // the pair correlation at the cell's area fraction
  S phi_p;              // <1 + e>_P at the cell's temperature
};

struct ConstitutiveModel {
  double mass = 0, sigma = 0;
  RestitutionClosure restitution;       // pair collisions
  RestitutionClosure wall_restitution;  // particle-wall collisions (the paper: the same law)
  TransportSet transport = TransportSet::JenkinsRichman;
  PairCorrelation pair_correlation;  // g2(nu) and its close-packing limit
  ContactPressure contact;           // p_c(nu); scale 0 = none
  RoughParticles rough;              // rotation as a field; disabled = smooth disks
  double knudsen_length = 0;         // l_max, m (0 = no limiter)
  double side_wall_width = 0;        // L_x, m, for the side-wall sink (0 = no side walls)

  double areaFraction(double rho) const { return rho * diskArea() / mass; }
  double diskArea() const { return std::numbers::pi * sigma * sigma / 4; }
  // The area fraction no state may reach (close packing of the chosen g2).
  double packingLimit() const { return pair_correlation.limit(); }

  template <class S>
  LocalState<S> evaluate(const S& rho, const S& theta) const;
  LocalState<double> evaluate(double rho, double theta) const {
    return evaluate<double>(rho, theta);
  }
  // Total pressure p_kinetic + p_c.
  double pressure(double rho, double theta) const { return evaluate(rho, theta).p; }
  // Energy flux into a flat wall: Phi_W^wall(theta) p sqrt(theta / (2 pi)), p the kinetic
  // pressure (the wall's collision rate n_c sqrt(T/(2 pi m)) with n_c T = p).
  double wallDissipation(double p, double theta) const;
  // Side walls of the Q2D cell as a sink per unit area:
  // D_side = (2 / L_x) Phi_W^wall(theta) p sqrt(theta / (2 pi)); 0 without side walls.
  double sideWallSink(double p, double theta) const;
};

template <class S>
LocalState<S> ConstitutiveModel::evaluate(const S& rho, const S& theta) const {
  using std::sqrt;
  const DiskGas gas{mass, sigma};
  const S nu = rho * (diskArea() / mass);
  S g2, dg2;
  pair_correlation.g2WithDerivative(nu, g2, dg2);
  const MaxwellAveragesOf<S> averages = restitution.averagesOf(theta);
  const S& phi_w = averages.phi_w;
  const S& phi_p = averages.phi_p;
  const Transport<S> t = transport == TransportSet::GarzoDufty
                             ? garzoDufty(gas, rho, theta, g2, phi_w, phi_p)
                             : jenkinsRichman(gas, rho, theta, g2, phi_w, phi_p);
  S limiter = constantLike(rho, 1.0);
  if (knudsen_length > 0) {
    const S free_path = 1.0 / (2.0 * std::numbers::sqrt2 * sigma * (rho / mass) * g2);
    limiter = 1.0 / (1.0 + free_path / knudsen_length);
  }
  // Sound speeds of p = n T F + p_c, F = 1 + Phi_P nu g2 (d = 2, docs/hydro.md):
  //   c_T^2 = theta (F + nu F_nu) + dp_c/drho,  c_s^2 = c_T^2 + theta F (F + theta F_theta).
  const S F = 1.0 + phi_p * nu * g2;
  const S nuF_nu = nu * phi_p * (g2 + nu * dg2);
  const S thetaF_theta = theta * averages.dphi_p * nu * g2;
  const S dpc_drho = contact.derivative(nu) * (diskArea() / mass);
  LocalState<S> s;
  s.p_kinetic = t.p;
  s.p = t.p + contact.pressure(nu);
  s.viscosity = (t.lambda_b + t.eta) * limiter;  // d = 2: lambda_b + 2 eta (d - 1)/d
  s.shear_viscosity = t.eta * limiter;
  s.kappa_theta = t.kappa_theta * limiter;
  s.cooling = t.D_c;
  s.isothermal_speed2 = theta * (F + nuF_nu) + dpc_drho;
  s.sound_speed = sqrt(s.isothermal_speed2 + theta * F * (F + thetaF_theta));
  const S phi_wall =
      wall_restitution == restitution ? averages.phi_wall : wall_restitution.phiWall(theta);
  s.wall_loss = phi_wall * sqrt(theta / (2 * std::numbers::pi));
  s.g2 = g2;
  s.phi_p = phi_p;
  return s;
}

}  // namespace granwave::hydro
