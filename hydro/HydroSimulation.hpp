#pragma once
// Integrates GranularHydro1D with CVODE from the layer settled on the plate, the drive ramped
// up over the first cycles (HydroGeometry::ramp_time), to the periodic state, and records the
// fields at M phases per drive cycle over the final window of P cycles (P the period of the centre
// of mass, 1 to `max_period`), in the plate frame (docs/hydro.md, "Runs").
//
// Periodic state: the centre-of-mass trajectory of the last P cycles repeats that of the P
// cycles before to `periodic_tolerance` of its oscillation amplitude; the smallest such P.
// A run that is not periodic after `max_cycles` ends normally with period 0 (aperiodic or
// slower than the budget: said as such, not a failure).
//
// It fails fast, with one line saying why, instead of grinding: a cycle that needs more than
// `max_steps_per_cycle` steps, or any CVODE failure, ends the run (HydroFailure).
#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include "hydro/CvodeIntegrator.hpp"
#include "hydro/GranularHydro1D.hpp"

namespace granwave::hydro {

struct HydroRunOptions {
  int samples_per_cycle = 100;  // M
  int min_cycles = 6;           // after the ramp, before the periodicity test
  int max_cycles = 60;          // in all, ramp included
  int max_period = 4;
  double periodic_tolerance = 0.02;
  CvodeOptions cvode;  // tolerances, method; atol, band, Jacobian filled in if empty
  // atol = 100 atol_scale x (sigma, sqrt(g sigma)) for node heights and velocities and
  // 1e4 atol_scale for the temperature unknowns ln theta (a relative error of theta) when
  // cvode.atol is empty: per-variable noise levels.
  double atol_scale = 1e-8;
  bool exact_jacobian = true;  // false: CVODE's difference quotients (for comparison)
  double initial_theta = 0;    // m^2/s^2 of the starting layer; 0 = 1e-3 g sigma
  // The starting layer: settled on the plate (hydro/SettledLayer.hpp, settledLayer), or spread
  // evenly over the container as the particle engine places its grains (spreadLayer).
  enum class Start { Settled, Spread } start = Start::Settled;
  // The steps a cycle may take beyond the 2 per phase that max_step forces (solverOptions);
  // more means the solver makes no progress.
  long max_steps_per_cycle = 10000;
  // Polled after every phase (nullptr: never): set, the run ends with HydroInterrupted.
  const std::atomic<bool>* interrupt = nullptr;
};

// The energy that crossed the layer's budget over one phase interval (J/m), and its closure;
// filled when the operator carries its energy-budget quadratures (GranularHydro1D,
// energy_budget), which CVODE integrates with the layer.
struct PhaseBudget {
  double plate_work = 0, collisional_loss = 0, friction_loss = 0, wall_loss = 0, side_wall_loss = 0;
  double energy_change = 0;  // E(end) - E(start) of the interval, lab frame
  // energy_change - (plate_work - losses): the integration error of the budget.
  double closure() const {
    return energy_change -
           (plate_work - collisional_loss - friction_loss - wall_loss - side_wall_loss);
  }
};

// Advances cv to t; when the operator carries its energy-budget quadratures, returns what
// crossed each over the interval and the change of the lab-frame energy. One definition for
// the 1D and the 2D operator, whose budget terms come in PhaseBudget's order (plate work,
// collisional, friction, wall, side-wall loss).
template <class Operator>
PhaseBudget advanceWithBudget(const Operator& op, CvodeIntegrator& cv, double t) {
  static_assert(Operator::kBudgetTerms == 5, "the terms of PhaseBudget");
  PhaseBudget b;
  if (!op.hasEnergyBudget()) {
    cv.advanceTo(t);
    return b;
  }
  const double t0 = cv.time();
  const std::vector<double> before = cv.state();
  cv.advanceTo(t);
  const std::vector<double>& after = cv.state();
  double crossed[Operator::kBudgetTerms];
  for (int k = 0; k < Operator::kBudgetTerms; ++k)
    crossed[k] = after[op.budgetIndex(k)] - before[op.budgetIndex(k)];
  b = {crossed[0], crossed[1], crossed[2], crossed[3], crossed[4], 0};
  b.energy_change = op.labEnergy(t, after.data()) - op.labEnergy(t0, before.data());
  return b;
}

// What the layer does over the final window.
enum class HydroRegime {
  Fluidised,  // part of the layer dilates below the contact onset during the cycle
  Solid,      // it never does: the layer moves as a block (no fluidised region)
  AtRest,     // it does not leave the plate
};
std::string regimeName(HydroRegime r);

// Fields of one recorded phase, plate frame, one value per cell (cells follow the mass, so
// their centres z move).
struct HydroPhase {
  double time = 0;                         // s (absolute)
  double plate_height = 0;                 // z_b(t), m
  double plate_velocity = 0;               // dz_b/dt, m/s
  double center_of_mass_height = 0;        // plate frame, m
  double layer_bottom = 0, layer_top = 0;  // the boundary nodes, plate frame, m
  std::vector<double> z, n, u, theta, area_fraction, pressure;
  std::vector<double> rotation;  // theta_r, m^2/s^2 (rough particles; empty otherwise)
  PhaseBudget budget;            // over the interval ending at this phase (energy budget on)
};

struct HydroResult {
  int period = 0;  // period of the centre of mass in cycles (0 = not periodic)
  int cycles = 0;  // cycles integrated, ramp included
  bool periodic = false;
  HydroRegime regime = HydroRegime::Fluidised;
  std::vector<HydroPhase> window;     // P x M phases of the final window
  std::vector<double> com_per_phase;  // all cycles, M per cycle, plate frame
  std::vector<long> steps_per_cycle;
  CvodeStats stats;
  double cpu_seconds = 0;  // of this thread
};

// A run that cannot go on: CVODE failed or a cycle exhausted its step budget.
class HydroFailure : public std::runtime_error {
 public:
  HydroFailure(const std::string& what, double time, int cycle)
      : std::runtime_error(what), time_(time), cycle_(cycle) {}
  double time() const { return time_; }
  int cycle() const { return cycle_; }

 private:
  double time_;
  int cycle_;
};

// A run stopped by its interrupt flag (HydroRunOptions::interrupt): nothing to keep.
class HydroInterrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class HydroSimulation {
 public:
  HydroSimulation(const GranularHydro1D& pde, const HydroRunOptions& options);
  HydroResult run();
  // The initial state: the settled layer (hydro/SettledLayer.hpp).
  std::vector<double> initialState() const;

 private:
  HydroPhase snapshot(double t, const std::vector<double>& U) const;
  CvodeOptions solverOptions();  // non-const: its event handler changes hold_
  int detectPeriod(const std::vector<double>& com) const;
  long stepBudget() const;
  HydroRegime classify(const std::vector<HydroPhase>& window) const;
  const GranularHydro1D& pde_;
  HydroRunOptions opt_;
  // Hard walls: the nodes held now; changed only at the integrator's events.
  GranularHydro1D::WallHold hold_{};
};

}  // namespace granwave::hydro
