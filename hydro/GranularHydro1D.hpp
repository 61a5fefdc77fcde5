#pragma once
// Navier-Stokes-order hydrodynamics of inelastic hard disks (d = 2) for the horizontally
// averaged layer, in the frame of the vibrating plate and in Lagrangian mass coordinates
// (docs/hydro.md, "Model"). The layer of mass M per unit width is cut into N cells of equal
// mass m_c = M/N; nodes j = 0..N at heights z_j with velocities u_j bound the cells, cell i
// (nodes i, i+1) has length l_i = z_{i+1} - z_i, density rho_i = m_c/l_i and temperature
// theta_i, carried as s_i = ln(theta_i / (g sigma)):
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
// With hard walls (WallModel::Hard) there is no contact range: a node that reaches its wall
// stops there (an event; its kinetic energy relative to the wall heats the wall cell) and is
// held while the wall pushes on it, released when the wall would have to pull (an event).
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
// Why ln theta: a granular temperature is positive, and a dense cell cools as theta^(3/2)
// with a rate that diverges at close packing; in ln theta the state is admissible by
// construction (no floor, no solver constraint), the cooling is a bounded rate
// d(ln theta)/dt = -k theta^(1/2), and a cold cell's error is measured relative to its own
// temperature. The equations are the same: d(m_c theta)/dt = m_c theta ds/dt = the cell's
// power, so the energy identities below hold unchanged (docs/hydro.md, "Admissible states").
//
// Unknowns interleaved per block j = [z_j, u_j, s_j (, s_r,j = ln theta_r,j)] (the last block,
// j = N, holds only z_N, u_N), so the Jacobian is banded (half-bandwidth 3 K - 1 for K
// unknowns per block) and computed exactly by forward-mode differentiation of the same code
// (hydro/Scalar.hpp).
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "hydro/ConstitutiveModel.hpp"
#include "hydro/HydroGeometry.hpp"
#include "hydro/LayerCell.hpp"

namespace granwave::hydro {

// Writes one element of a banded Jacobian: (row, column, value).
using BandWriter = std::function<void(int row, int column, double value)>;

class GranularHydro1D {
 public:
  // column_mass = M, kg/m.
  // energy_budget: the state carries the running integrals of the energy rates (EnergyRates,
  // below) as kBudgetTerms quadrature unknowns after the layer's, which nothing else depends on.
  GranularHydro1D(const HydroGeometry& geometry, const ConstitutiveModel& model, double column_mass,
                  const HydroRegularisation& regularisation = {}, bool energy_budget = false);
  ~GranularHydro1D();
  GranularHydro1D(const GranularHydro1D&) = delete;
  GranularHydro1D& operator=(const GranularHydro1D&) = delete;

  int cells() const { return g_.cells; }
  // Unknowns per block: 3 (z, u, theta), 4 with the rotational temperature.
  int variables() const { return vars_; }
  int size() const { return layerSize() + (energy_budget_ ? kBudgetTerms : 0); }
  int layerSize() const { return vars_ * g_.cells + 2; }  // the layer's unknowns
  // The energy-budget quadratures, J/m since the start, in the order of EnergyRates.
  static constexpr int kBudgetTerms = 5;
  bool hasEnergyBudget() const { return energy_budget_; }
  int budgetIndex(int term) const { return layerSize() + term; }
  int halfBand() const { return 3 * vars_ - 1; }
  bool rough() const { return vars_ == 4; }
  double cellMass() const { return m_c_; }
  double columnMass() const { return m_c_ * g_.cells; }
  const HydroGeometry& geometry() const { return g_; }
  const ConstitutiveModel& model() const { return model_; }
  const HydroRegularisation& regularisation() const { return numerics_; }
  double effectiveGravity(double t) const { return g_.gravity + g_.plateAcceleration(t); }

  // Where the unknowns sit in the state vector.
  int heightIndex(int node) const { return vars_ * node; }
  int velocityIndex(int node) const { return vars_ * node + 1; }
  int temperatureIndex(int cell) const { return vars_ * cell + 2; }
  int rotationIndex(int cell) const { return vars_ * cell + 3; }  // rough particles only

  // The temperature unknowns are s = ln(theta / (g sigma)) (see the top of this file).
  double temperatureUnknown(double theta) const { return std::log(theta / theta_unit_); }
  double temperatureOf(double s) const { return theta_unit_ * std::exp(s); }
  // theta and theta_r of a cell in a state U, m^2/s^2, and their rates in dU/dt.
  double temperature(const double* U, int cell) const {
    return temperatureOf(U[temperatureIndex(cell)]);
  }
  double rotationalTemperature(const double* U, int cell) const {
    return temperatureOf(U[rotationIndex(cell)]);
  }
  double temperatureRate(const double* U, const double* dUdt, int cell) const {
    return temperature(U, cell) * dUdt[temperatureIndex(cell)];
  }

  // The stress of the wall contact at a gap (m) from the wall, approached at `speed` (m/s,
  // > 0 towards the wall), for a wall cell of density rho and sound speed c: the elastic part
  // (above) and the dashpot rho c speed while approaching in contact.
  double contactStress(double gap, double speed, double rho, double c) const;

  // What the closures see of a cell (docs/hydro.md, "Admissible states"): Newton's iterates
  // may tangle nodes or overshoot close packing, so the length is floored smoothly at
  // 1e-6 sigma and the density mapped through rho_eff = rho_max - d s((rho_max - rho)/d),
  // s(x) = (x + sqrt(x^2 + 4))/2, d = packing_width of the close-packed density (rho_eff = rho
  // to d^2/(rho_max - rho) below close packing and < rho_max always, so a packing past it meets
  // a pressure growing as (rho - rho_max)/d^2: close packing acts as a constraint, stiffer as
  // d shrinks); the temperature is theta + temperature_floor.
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

  // Hard walls (WallModel::Hard): which boundary nodes the plate and the lid hold. A held node
  // rests at its wall (dz/dt = du/dt = 0) while the wall pushes on it with the reaction that
  // balances the cell's stress and the node's weight; with the spring both are always free.
  struct WallHold {
    bool plate, lid;  // no member initialisers: WallHold{} (both free) is a default argument
  };
  bool hardWalls() const { return numerics_.walls == WallModel::Hard; }
  // The event functions of the hard walls (CvodeOptions::events = 2): g[0] for the plate, g[1]
  // for the lid; a free node's gap to its wall (a root is a landing), a held node's reaction
  // (N/m, wallReactions; a root is a release, the wall would have to pull).
  void wallEvents(double t, const double* U, WallHold hold, double* g) const;
  // At events `found` (t, U): a landing node stops, its kinetic energy heating the wall cell,
  // and is held if the wall pushes on it; a released node goes free. Returns the new hold.
  WallHold wallEvent(double t, std::vector<double>& U, WallHold hold,
                     const std::vector<int>& found) const;
  // Hard walls: whether the boundary nodes are within the walls (to 1e-6 sigma): a node past
  // its wall is a landing the event detection missed. Always true for the spring, whose
  // contact lets a node press into its range.
  bool withinWalls(const double* U) const;
  // The hold of a start: a node at its wall (within round-off) that the wall pushes on.
  WallHold startingHold(double t, const double* U) const;

  // dU/dt. Returns 0, or 1 (recoverable: CVODE retries with a smaller step) if the state has
  // a non-finite value. With hard walls the caller passes the hold its events keep (the
  // default, both free, is the spring's and a hard wall's free flight). Like every method
  // here it uses the operator's one workspace: one operator serves one thread.
  int rightHandSide(double t, const double* U, double* dUdt, WallHold hold = {}) const;
  // The exact Jacobian d(dU/dt)/dU, banded, written element by element. Same return codes.
  int jacobian(double t, const double* U, const BandWriter& write, WallHold hold = {}) const;

  std::string componentName(int k) const;

  // The powers that change the layer's energy in the lab frame (per unit width, W/m) at (t, U):
  // dE/dt = plate_work - collisional_loss - friction_loss - wall_loss - side_wall_loss, E the
  // lab-frame kinetic, potential, internal (m theta per particle), rotational (m theta_r / 2)
  // and wall-contact elastic energy. The artificial viscosity and the walls' dashpots turn
  // kinetic energy into heat: they move energy inside the layer and are not losses.
  struct EnergyRates {
    double plate_work = 0;        // the plate's and the lid's contact force times their velocity
    double collisional_loss = 0;  // sum of D_c l: the normal inelasticity of pair collisions
    double friction_loss = 0;     // rough particles: the tangential (friction) part
    double wall_loss = 0;         // the particles' collisions with the plate and the lid
    double side_wall_loss = 0;    // the side walls' sink
  };
  EnergyRates energyRates(double t, const double* U, WallHold hold = {}) const;
  // E of the state U at time t (J/m), the energy the rates above change.
  double labEnergy(double t, const double* U) const;
  // The elastic energy stored in a wall contact at this gap (J/m).
  double contactEnergy(double gap) const;

 private:
  template <class S>
  struct Workspace;
  template <class S>
  int residual(double t, const S* U, S* dUdt, Workspace<S>& w, WallHold hold) const;
  // The exchanges with the plate and the lid of a state whose cells `w` holds.
  template <class S>
  std::pair<WallExchange<S>, WallExchange<S>> wallExchanges(double t, const S* U,
                                                            const Workspace<S>& w,
                                                            WallHold hold) const;
  // The reactions (N/m, > 0 pushing) the plate and the lid need to hold their nodes.
  template <class S>
  std::pair<S, S> wallReactions(double t, const Workspace<S>& w) const;
  template <class S>
  void cellStates(const S* U, Workspace<S>& w) const;
  template <class S>
  void cellState(const S* U, int cell, Workspace<S>& w) const;  // one cell of cellStates
  template <int Colours>
  struct JetWorkspace;
  template <int Colours>
  int jacobianWith(double t, const double* U, const BandWriter& write, JetWorkspace<Colours>& j,
                   WallHold hold) const;

  // Scales of the regularisations above, fixed at construction.
  using Regularisation = CellRegularisation;
  HydroGeometry g_;
  ConstitutiveModel model_;
  HydroRegularisation numerics_;
  double m_c_;
  int vars_;
  double theta_unit_;  // g sigma: the unit of the temperature unknowns
  bool energy_budget_;
  Regularisation reg_;
  std::unique_ptr<Workspace<double>> values_;
  std::unique_ptr<JetWorkspace<15>> smooth_jets_;  // 5 block colours x 3 unknowns
  std::unique_ptr<JetWorkspace<20>> rough_jets_;   // 5 block colours x 4 unknowns
};

}  // namespace granwave::hydro
