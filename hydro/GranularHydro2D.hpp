#pragma once
// Navier-Stokes-order hydrodynamics of inelastic hard disks in the x-z plane, in the frame of
// the vibrating plate, periodic in x or between smooth side walls (docs/hydro.md, "The 2D
// model"). Columns i = 0..Nx-1 of width dx = L_x/Nx each hold the 1D operator's Lagrangian
// layout (GranularHydro1D): nodes j = 0..N at heights z_ij with vertical velocities w_ij
// bound cells (i, k) of length l_ik = z_i,k+1 - z_ik and temperature theta_ik, carried as
// s = ln(theta/(g sigma)). The layers k are material surfaces: mass moves only horizontally,
// inside its layer, through the face between cells (i, k) and (i+1, k), where the horizontal
// velocity u_ik sits (a vertically Lagrangian, horizontally Eulerian grid):
//
//   cell mass per unit width  mu_ik = mu0_ik + (Phi_i-1,k - Phi_ik)/dx,  dPhi_ik/dt = F_ik
//   dz_ij/dt = w_ij - (u dz_j/dx)_ij              (the layer interfaces are material; the
//                                                  drift weighted by the mass fluxes)
//   M_node dw/dt = F_z - M_node g_eff(t) + advection along the layer
//   M_face du/dt = F_x + advection along the layer
//   M_cell theta ds/dt = heating - cooling - div q + advection along the layer
//
// F_ik = h u rho* is the mass flux (rho* the upwinded, van Leer-limited density: positive, so
// no cell mass can go negative); Phi, its time integral, is the unknown, so that mass is
// conserved exactly whatever the solver's iterates. The stresses act through one discrete
// velocity gradient G per cell (normal strains) and per corner (shear strain at the face
// column and the interface): the forces on the velocities are minus the gradient of the
// stress power, and the heating of the cells is that power, so the stresses exchange energy
// between flow and heat exactly (the compatible discretisation of Caramana, Burton, Shashkov
// & Whalen, J. Comput. Phys. 146, 227 (1998)). Upwinded momentum advection dissipates
// kinetic energy; that energy heats the cell it is lost in. For a layer uniform in x every
// horizontal term vanishes and each column is GranularHydro1D exactly (tested).
//
// Unknowns per block j of column i: [z, w, s, Phi, u (, s_r)], the last block of a column
// (j = N) only [z, w]; columns one after the other. Within a column the Jacobian is banded as
// in 1D (half-bandwidth 3 K - 1); across columns it reaches three columns each way.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "hydro/ConstitutiveModel.hpp"
#include "hydro/HydroGeometry.hpp"
#include "hydro/LayerCell.hpp"

namespace granwave::hydro {

// The horizontal grid: Nx columns over the width, periodic or between smooth side walls.
struct HydroColumns {
  int columns = 30;     // Nx
  double width = 0.06;  // L_x, m
  bool periodic = true;
};

// Writes one element of a sparse matrix: (row, column, value).
using SparseWriter = std::function<void(int row, int column, double value)>;

class GranularHydro2D {
 public:
  // cell_mass: mu0 of every cell, [i * N + k], kg/m (mass per unit width of its column, as the
  // 1D operator's m_c). energy_budget: the state carries kBudgetTerms quadratures after the layer.
  GranularHydro2D(const HydroGeometry& geometry, const HydroColumns& columns,
                  const ConstitutiveModel& model, std::vector<double> cell_mass,
                  const HydroRegularisation& regularisation = {}, bool energy_budget = false);
  ~GranularHydro2D();
  GranularHydro2D(const GranularHydro2D&) = delete;
  GranularHydro2D& operator=(const GranularHydro2D&) = delete;

  int columns() const { return x_.columns; }
  int cells() const { return g_.cells; }  // per column
  int variables() const { return vars_; }
  bool rough() const { return vars_ == 6; }
  bool periodic() const { return x_.periodic; }
  double dx() const { return x_.width / x_.columns; }
  int columnSize() const { return vars_ * g_.cells + 2; }
  int layerSize() const { return columnSize() * x_.columns; }
  int size() const { return layerSize() + (energy_budget_ ? kBudgetTerms : 0); }
  static constexpr int kBudgetTerms = 5;  // as GranularHydro1D::EnergyRates
  bool hasEnergyBudget() const { return energy_budget_; }
  int budgetIndex(int term) const { return layerSize() + term; }
  int halfBand() const { return 3 * vars_ - 1; }  // within a column
  static constexpr int kColumnReach = 3;          // columns each way a row depends on

  const HydroGeometry& geometry() const { return g_; }
  const HydroColumns& columnGrid() const { return x_; }
  const ConstitutiveModel& model() const { return model_; }
  const HydroRegularisation& regularisation() const { return numerics_; }
  double effectiveGravity(double t) const { return g_.gravity + g_.plateAcceleration(t); }
  const std::vector<double>& initialCellMass() const { return mu0_; }
  double totalMass() const;  // kg per unit depth: sum of mu0 dx

  int columnOffset(int i) const { return columnSize() * i; }
  int heightIndex(int i, int node) const { return columnOffset(i) + vars_ * node; }
  int velocityIndex(int i, int node) const { return heightIndex(i, node) + 1; }
  int temperatureIndex(int i, int cell) const { return heightIndex(i, cell) + 2; }
  int fluxIndex(int i, int cell) const { return heightIndex(i, cell) + 3; }
  int horizontalVelocityIndex(int i, int cell) const { return heightIndex(i, cell) + 4; }
  int rotationIndex(int i, int cell) const { return heightIndex(i, cell) + 5; }

  double temperatureUnknown(double theta) const;
  double temperatureOf(double s) const;
  // The cell mass per unit width mu_ik of the state (kg/m), before the floor the closures see.
  double cellMass(const double* U, int i, int cell) const;
  // Whether face (i, k) (the right face of column i) is a side wall.
  bool wallFace(int i) const { return !x_.periodic && i == x_.columns - 1; }

  // What the closures see of cell (i, k), and its geometry.
  struct CellView {
    double rho, theta, length, mass, centre;
  };
  CellView cellView(const double* U, int i, int cell) const;

  // dU/dt: 0, or 1 (recoverable) for a non-finite state.
  int rightHandSide(double t, const double* U, double* dUdt) const;
  // The exact Jacobian of the layer's rows, every non-zero element written once (the
  // quadratures' rows left out). in_column_only: only the elements whose row and column lie in
  // the same column of the grid (the column blocks the preconditioner factors).
  int jacobian(double t, const double* U, const SparseWriter& write, bool in_column_only) const;

  // The powers that change the layer's lab-frame energy, per unit depth (W/m), as
  // GranularHydro1D::EnergyRates; side_wall_loss is the loss at explicit side walls.
  // contact_drift is the rate at which the boundary nodes' drift (dz/dt = w - drift) changes
  // the plate's and the lid's elastic energy, sum dx (s_plate drift_i0 - s_lid drift_iN), s
  // the walls' elastic stress: no force answers it (the walls act on w alone; docs/hydro.md,
  // "Interfaces between columns"), so dE/dt = plate_work - losses + contact_drift (up to the
  // smooth switches). Not one of the budget's quadratures: it lies in a phase budget's closure.
  struct EnergyRates {
    double plate_work = 0, collisional_loss = 0, friction_loss = 0, wall_loss = 0;
    double side_wall_loss = 0, contact_drift = 0;
  };
  EnergyRates energyRates(double t, const double* U) const;
  // The lab-frame energy (J per unit depth): kinetic (nodes w, faces u), potential, internal,
  // rotational and wall-contact elastic.
  double labEnergy(double t, const double* U) const;

  std::string componentName(int k) const;

  // The scales of the regularisations (LayerCell.hpp), the unit of the temperature unknowns
  // (g sigma) and the cell-mass floor, for the residual's parts (Layer2D*.hpp).
  const CellRegularisation& cellRegularisation() const { return reg_; }
  double thetaUnit() const { return theta_unit_; }
  double massFloor() const { return mass_floor_; }

  template <class S>
  struct Workspace;

 private:
  template <class S>
  int residual(double t, const S* U, S* dU, Workspace<S>& w) const;
  EnergyRates ratesOf(double t, const Workspace<double>& filled) const;

 public:
  template <int Colours>
  struct JetWorkspace;

 private:
  template <int Colours>
  int jacobianWith(double t, const double* U, const SparseWriter& write, bool in_column_only,
                   JetWorkspace<Colours>& j) const;

  HydroGeometry g_;
  HydroColumns x_;
  ConstitutiveModel model_;
  HydroRegularisation numerics_;
  std::vector<double> mu0_;
  int vars_;
  double theta_unit_;
  bool energy_budget_;
  CellRegularisation reg_;
  double mass_floor_;  // kg/m: the cell masses the closures see are floored smoothly here
  std::unique_ptr<Workspace<double>> values_;
  // Made at the first Jacobian: 6 block colours x 5 (smooth) or 6 (rough) unknowns.
  mutable std::unique_ptr<JetWorkspace<30>> smooth_jets_;
  mutable std::unique_ptr<JetWorkspace<36>> rough_jets_;
};

}  // namespace granwave::hydro
