#pragma once
// Integrates GranularHydro2D with CVODE (BDF, Newton-Krylov with the column preconditioner,
// hydro/ColumnPreconditioner.hpp) from every column started as the 1D layer starts (settled or
// spread, hydro/Layer2DStart.hpp) with the seeded perturbation of the column masses, the drive
// ramped up as in 1D, for a fixed number of drive cycles: surface waves are a state the layer
// grows into, not a periodic orbit to detect. Every recorded phase (M per cycle) is handed to
// an observer (the surface and its spectrum are measured outside hydro/), and the last
// `window_cycles` cycles are kept whole for the run file (docs/hydro.md, "The 2D model").
//
// With remap_share > 0 the layers are remapped vertically whenever one empties (hydro/
// Layer2DRemap.hpp), as an event inside the integration.
//
// It fails fast as the 1D run does (HydroFailure): a CVODE failure or a cycle over its step
// budget ends the run with one line saying where.
#include <functional>
#include <vector>

#include "hydro/CvodeIntegrator.hpp"
#include "hydro/GranularHydro2D.hpp"
#include "hydro/HydroSimulation.hpp"

namespace granwave::hydro {

struct Hydro2DRunOptions {
  int samples_per_cycle = 100;  // M
  int cycles = 40;              // in all, ramp included
  int window_cycles = 2;        // the newest cycles kept whole
  double rtol = 1e-4;
  // atol as HydroRunOptions (heights, velocities, ln theta), and for the mass fluxes
  // 100 atol_scale of a cell's mass times dx.
  double atol_scale = 1e-8;
  double initial_theta = 0;  // m^2/s^2; 0 = 1e-3 g sigma
  bool spread = true;        // start spread over the box (else settled on the plate)
  long max_steps_per_cycle = 20000;
  int krylov_dimension = 0;  // GMRES subspace (0 = CVODE's 5)
  // The vertical remap (hydro/Layer2DRemap.hpp): when a cell's mass falls to this share of
  // its column's and layer's (CVODE root finding on thinnestLayerShare), every column is
  // remapped to its shares and the integration restarts. 0 = never.
  double remap_share = 0;
};

// One recorded phase, plate frame. Nodes [i (N + 1) + j], cells [i N + k].
struct Hydro2DPhase {
  double time = 0, plate_height = 0, plate_velocity = 0;
  double center_of_mass_height = 0;  // plate frame, m
  std::vector<double> node_z;        // m
  std::vector<double> area_fraction, theta, velocity_x, velocity_z, pressure, mass;
  std::vector<double> rotation;  // theta_r (rough particles)
  PhaseBudget budget;            // over the interval ending here (energy budget on)
};

// Called with every recorded phase: the phase, its cycle (from 0) and its index in the cycle.
using Hydro2DObserver = std::function<void(const Hydro2DPhase&, int cycle, int phase)>;

struct Hydro2DResult {
  int cycles = 0;
  std::vector<Hydro2DPhase> window;   // the last window_cycles x M phases
  std::vector<double> com_per_phase;  // every phase, plate frame
  std::vector<long> steps_per_cycle;
  double mass_drift = 0;  // max over phases of |total mass / initial - 1|
  CvodeStats stats;
  long preconditioner_jacobians = 0;
  long remaps = 0;         // vertical remaps (Hydro2DRunOptions::remap_share)
  double remap_heat = 0;   // J per unit depth the remaps moved into heat, summed
  double cpu_seconds = 0;  // of this thread
};

class HydroSimulation2D {
 public:
  HydroSimulation2D(const GranularHydro2D& op, const Hydro2DRunOptions& options);
  Hydro2DResult run(const Hydro2DObserver& observe = {});
  std::vector<double> initialState() const;
  Hydro2DPhase snapshot(double t, const std::vector<double>& U) const;
  CvodeOptions solverOptions() const;

 private:
  const GranularHydro2D& op_;
  Hydro2DRunOptions opt_;
};

}  // namespace granwave::hydro
