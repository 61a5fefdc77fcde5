#pragma once
// Navier-Stokes-order hydrodynamics of inelastic hard disks (d = 2) for the horizontally
// averaged layer, in the frame of the vibrating plate and in Lagrangian mass coordinates
// (docs/hydro.md, "Model"). The layer of mass M per unit width is cut into N cells of equal
// mass m_c = M/N; nodes j = 0..N at heights z_j with velocities u_j bound the cells, cell i
// (nodes i, i+1) has length l_i = z_{i+1} - z_i, density rho_i = m_c/l_i and temperature
// theta_i:
//
//   dz_j/dt     = u_j
//   du_j/dt     = -(Pi_j - Pi_{j-1}) / m_c - g_eff(t)                (interior nodes)
//   dtheta_i/dt = [-(p_k + q) du_i + mu_b du_i^2 / l_i - (Q_{i+1} - Q_i) - (D_c + D_side) l_i] /
//   m_c
//
// with du_i = u_{i+1} - u_i, the normal stress Pi_i = p_k + p_c + q - mu_b du_i/l_i, the heat
// flux Q_j = -kappa_theta (theta_j - theta_{j-1}) / (distance between cell centres) and
// g_eff(t) = g + z_b''(t). The two boundary nodes carry half a cell and meet the plate (z = 0)
// and the lid (z = L_z) through a unilateral contact: a repulsive pressure within
// kContactRange of the wall, a dashpot on approach whose work heats the wall cell, and the
// wall collisions' energy loss Phi_W^wall p_k sqrt(theta/(2 pi)). Away from a wall the
// boundary node is a free surface (Pi = 0 outside): the layer lands, rests and lifts off.
//
// Why Lagrangian: mass is conserved exactly, a resting layer is an exact discrete
// equilibrium (node forces are pressure differences of neighbouring cells, nothing is
// reconstructed), there is no vacuum to integrate (an Eulerian grid spends most cells on the
// near-empty box, whose gas forced steps of 1e-11 s), and the cells follow the mass, so the
// dense layer is resolved at 0.1 sigma with 100 cells. q is a von Neumann-Richtmyer artificial
// viscosity (quadratic and linear) that spreads a shock over a few cells; its work, like the
// physical viscosity's, heats the cell. The contact pressure p_c is elastic: it enters the
// stress, not the temperature equation.
//
// Rough particles (ConstitutiveModel::rough) add the rotational temperature theta_r of each
// cell, changed only by collisions (hydro/RoughCollisions.hpp; its transport is neglected).
//
// Unknowns interleaved per block j = [z_j, u_j, theta_j (, theta_r,j)] (the last block,
// j = N, holds only z_N, u_N), so the Jacobian is banded (half-bandwidth 3 K - 1 for K
// unknowns per block) and computed exactly by forward-mode differentiation of the same code
// (hydro/Scalar.hpp).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "hydro/ConstitutiveModel.hpp"

namespace granwave::hydro {

struct HydroGeometry {
  int cells = 100;       // N, cells of equal mass
  double height = 0.06;  // L_z, plate to lid, m
  double gravity = 9.81;
  double amplitude = 0;  // A, m
  double omega = 0;      // rad/s
  double ramp_time = 0;  // s: the amplitude grows from 0 to A over this time (quintic ramp)

  // The plate z_b(t) = A r(t) sin(omega t) and its derivatives, r the ramp.
  double plateHeight(double t) const;
  double plateVelocity(double t) const;
  double plateAcceleration(double t) const;
};

// Writes one element of a banded Jacobian: (row, column, value).
using BandWriter = std::function<void(int row, int column, double value)>;

class GranularHydro1D {
 public:
  // Artificial viscosity q = rho (c2 du^2 + c1 c_s |du|) in compression (Caramana, Shashkov
  // & Whalen, J. Comput. Phys. 144, 70 (1998), the 1D forms). The physical viscosity already
  // resolves the shocks on cells of ~0.1 sigma; measured on the paper's scene, the usual
  // c2 = 1, c1 = 0.2 doubled the centre-of-mass error of 100 cells (5.4e-3 against 800 cells)
  // against c2 = 0.25, c1 = 0 (1.7e-3), and both ran the whole stability grid (docs/hydro.md).
  static constexpr double kQuadraticViscosity = 0.25, kLinearViscosity = 0.0;
  // The wall contact acts within kContactRange particle diameters of a wall; its elastic
  // stress is P_c (p/kContactStiffness)^3 at a penetration p into that range (in diameters),
  // P_c = rho_cp g sigma: a layer of k close-packed rows rests 0.01 k^(1/3) sigma into it, a
  // shock of 1000 P_c reaches 0.1 sigma.
  static constexpr double kContactRange = 0.05, kContactStiffness = 0.01;

  // column_mass = M, kg/m.
  GranularHydro1D(const HydroGeometry& geometry, const ConstitutiveModel& model,
                  double column_mass);
  ~GranularHydro1D();
  GranularHydro1D(const GranularHydro1D&) = delete;
  GranularHydro1D& operator=(const GranularHydro1D&) = delete;

  int cells() const { return g_.cells; }
  // Unknowns per block: 3 (z, u, theta), 4 with the rotational temperature.
  int variables() const { return vars_; }
  int size() const { return vars_ * g_.cells + 2; }
  int halfBand() const { return 3 * vars_ - 1; }
  bool rough() const { return vars_ == 4; }
  double cellMass() const { return m_c_; }
  double columnMass() const { return m_c_ * g_.cells; }
  const HydroGeometry& geometry() const { return g_; }
  const ConstitutiveModel& model() const { return model_; }
  double effectiveGravity(double t) const { return g_.gravity + g_.plateAcceleration(t); }

  // Where the unknowns sit in the state vector.
  int heightIndex(int node) const { return vars_ * node; }
  int velocityIndex(int node) const { return vars_ * node + 1; }
  int temperatureIndex(int cell) const { return vars_ * cell + 2; }
  int rotationIndex(int cell) const { return vars_ * cell + 3; }  // rough particles only

  // The stress of the wall contact at a gap (m) from the wall, approached at `speed` (m/s,
  // > 0 towards the wall), for a wall cell of density rho and sound speed c: the elastic part
  // (above) and the dashpot rho c speed while approaching in contact.
  double contactStress(double gap, double speed, double rho, double c) const;

  // What the closures see of a cell (docs/hydro.md, "Admissible states"): Newton's iterates
  // may tangle nodes or overshoot close packing, so the length is floored smoothly at
  // 1e-6 sigma and the density mapped through rho_eff = rho_max - d s((rho_max - rho)/d),
  // s(x) = (x + sqrt(x^2 + 4))/2, d = 1e-4 of the close-packed density (rho_eff = rho to
  // 1e-8/(nu_max - nu) below close packing and < rho_max always, so such an iterate meets a
  // pressure growing as (nu - nu_max)^2/d^4 instead of an undefined state); the temperature
  // is floored at theta_min = 1e-8 g sigma, which keeps the closures' powers of theta and
  // their derivatives bounded in a layer that has cooled to rest.
  struct CellView {
    double rho, theta;
  };
  CellView cellView(const double* U, int cell) const;
  // The node spacing l whose cell the closures see at density rho_eff (the mapping's exact
  // inverse), and the temperature they see for theta.
  double spacingFor(double rho_eff) const;
  double effectiveTemperature(double theta) const;
  // Velocities below this are noise (1e-4 sqrt(g sigma)): the width of the smooth switches.
  double velocityNoise() const { return reg_.u_width; }

  // dU/dt. Returns 0, or 1 (recoverable: CVODE retries with a smaller step) if the state has
  // a non-finite value.
  int rightHandSide(double t, const double* U, double* dUdt) const;
  // The exact Jacobian d(dU/dt)/dU, banded, written element by element. Same return codes.
  int jacobian(double t, const double* U, const BandWriter& write) const;

  std::string componentName(int k) const;

 private:
  template <class S>
  struct Workspace;
  template <class S>
  int residual(double t, const S* U, S* dUdt, Workspace<S>& w) const;
  template <class S>
  void cellStates(const S* U, Workspace<S>& w) const;
  template <int Colours>
  struct JetWorkspace;
  template <int Colours>
  int jacobianWith(double t, const double* U, const BandWriter& write,
                   JetWorkspace<Colours>& j) const;

  // Scales of the regularisations above, fixed at construction.
  struct Regularisation {
    double rho_max, packing_width, length_floor, theta_min, u_width, contact_scale;
  };
  HydroGeometry g_;
  ConstitutiveModel model_;
  double m_c_;
  int vars_;
  Regularisation reg_;
  std::unique_ptr<Workspace<double>> values_;
  std::unique_ptr<JetWorkspace<15>> smooth_jets_;  // 5 block colours x 3 unknowns
  std::unique_ptr<JetWorkspace<20>> rough_jets_;   // 5 block colours x 4 unknowns
};

}  // namespace granwave::hydro
