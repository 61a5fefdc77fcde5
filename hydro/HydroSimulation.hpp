#pragma once
// Integrates GranularHydro1D with CVODE from a resting layer to the periodic state and
// records the fields at M phases per drive cycle over the final window of P cycles (P = the
// detected period, 1 or 2, of the centre of mass), in the plate frame.
// Periodic state: the centre-of-mass trajectory of the last cycle repeats that of P cycles
// earlier to `periodic_tolerance` of its oscillation amplitude.
#include <vector>

#include "hydro/CvodeIntegrator.hpp"
#include "hydro/GranularHydro1D.hpp"

namespace granwave::hydro {

struct HydroRunOptions {
  int samples_per_cycle = 100;  // M
  int min_cycles = 8;
  int max_cycles = 60;
  double periodic_tolerance = 0.02;
  CvodeOptions cvode;  // tolerances, method; atol and band filled in if empty
  // atol = atol_scale x (rho_cp, rho_cp sqrt(g sigma), rho_cp g sigma) per cell when
  // cvode.atol is empty: per-variable noise levels (physics-hydro.md 5.3).
  double atol_scale = 1e-8;
  bool positivity = true;  // CVODE constraints rho > 0, E > 0
  double initial_area_fraction = 0.5;
  double initial_theta = 0.01;  // m^2/s^2
};

// Fields of one recorded phase, plate frame, one value per cell.
struct HydroPhase {
  double time = 0;                   // s (absolute)
  double plate_height = 0;           // z_b(t), m
  double center_of_mass_height = 0;  // plate frame, m
  std::vector<double> n, u, theta, area_fraction, pressure;
};

struct HydroResult {
  int period = 0;  // detected period of the centre of mass (0 = not periodic)
  int cycles = 0;  // cycles integrated
  bool periodic = false;
  std::vector<HydroPhase> window;     // P x M phases of the final window
  std::vector<double> com_per_phase;  // all cycles, M per cycle, plate frame
  CvodeStats stats;
  double wall_seconds = 0;
  double initial_mass = 0, final_mass = 0;  // per unit width, kg/m
};

class HydroSimulation {
 public:
  HydroSimulation(const GranularHydro1D& pde, int particles, double width,
                  const HydroRunOptions& options);
  HydroResult run();
  // The initial state: a layer of uniform area fraction with smooth edges, at rest.
  std::vector<double> initialState() const;

 private:
  HydroPhase snapshot(double t, const std::vector<double>& U) const;
  const GranularHydro1D& pde_;
  double column_mass_;  // total mass per unit width, kg/m: N m / L_x
  HydroRunOptions opt_;
};

}  // namespace granwave::hydro
