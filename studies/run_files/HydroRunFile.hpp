#pragma once
// The hydro run file HYDRO.h5 (layout in docs/hydro.md, "Output"): written by `granwave hydro`
// and read back by the studies, both here, so the format has one owner. Its lab frame is laid
// out as a fields file's profiles (coarse_grain/FieldsLayout.hpp), so the particles and the
// continuum name each quantity alike.
#include <cstdint>
#include <string>
#include <vector>

#include "coarse_grain/PhaseProfiles.hpp"
#include "studies/run_files/EnergyBudgetGroup.hpp"

namespace granwave {

// What one `granwave hydro` run writes. The plate frame is [phase][cell] (`cells` cells, which
// move with the mass); the lab frame is the coarse-graining grid's rows.
struct HydroRunContent {
  std::size_t cells = 0;
  std::vector<double> plate_z;  // m: [phase][cell] cell centres above the plate
  std::vector<double> number_density, velocity_z, temperature, area_fraction, pressure;
  // Profiles on the lab-frame rows (no blocks, no RMS(v_x)), plate, centre of mass, fronts.
  PhaseProfiles lab;
  double rtol = 0;
  std::int64_t cycles = 0, period = 0, steps = 0, rhs_evals = 0, jacobian_evals = 0;
  std::int64_t error_test_failures = 0, nonlinear_failures = 0;
  bool periodic = false;
  std::string regime;  // hydro::regimeName: at rest, solid or fluidised
  double cpu_seconds = 0;
  // The plate-frame centre of mass at every sampled phase of every cycle, ramp included (m),
  // phases_per_cycle per cycle: how the run settled, not only its final window. Empty in files
  // written before it was stored.
  std::vector<double> com_history;
  std::int64_t phases_per_cycle = 0;
  // The energy that crossed the layer over each phase interval of the window (J, the box's
  // width), when the scene asked for it (hydro.energy_budget); empty otherwise.
  RunEnergyBudget budget;
  std::string scene_toml;  // the fully resolved scene
  // Drive cycles in the window: the period, or 2 when none was found (HydroSimulation).
  int windowCycles() const { return periodic ? static_cast<int>(period) : 2; }
};

// The file's root attribute "format": its name and layout version.
inline constexpr const char* kHydroRunFormat = "granwave-hydro-1";

// Atomic: the file appears complete or not at all.
void writeHydroRunFile(const std::string& path, const HydroRunContent& content);

// Everything but the plate frame (the studies compare in the lab frame). Reads files written
// before the lab frame took the fields file's names too.
HydroRunContent readHydroRunFile(const std::string& hydro_path);

}  // namespace granwave
