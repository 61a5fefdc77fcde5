#pragma once
// A run of the paper's scene read back as the wave-fronts study compares it: a particle run's
// fields, or a hydro run's lab frame with its impact fronts, velocity-jump front and collision
// phase, or why the run failed.
#include <optional>
#include <string>
#include <vector>

#include "coarse_grain/FieldsReader.hpp"
#include "studies/contract/Study.hpp"
#include "studies/run_files/HydroRunFile.hpp"
#include "studies/statistics/Measurement.hpp"
#include "studies/wave_analysis/ImpactFronts.hpp"
#include "studies/wave_analysis/VelocityFronts.hpp"

namespace granwave {

// A hydro run's outcome: its fields and fronts, or why it failed.
struct HydroOutcome {
  std::optional<HydroRunContent> fields;
  std::string failure;
  ImpactFronts fronts;
  // The velocity-jump front (VelocityFronts.hpp), which the model hierarchy compares; set by
  // whoever reads the run with the scene's frequency (trackedHydroFronts).
  Measurement tracked;
  double collision_phase = NAN;  // t/T of the lowest centre of mass (mean over cycles)
  double cpu = 0;                // s
};

HydroOutcome hydroOutcome(const RunSet& runs, const std::string& label);
// Its velocity-jump fronts (the time between phases from the window and the drive frequency;
// none without fields).
VelocityFronts trackedHydroFronts(const HydroOutcome& h, double frequency);
// A particle run's fields, if it finished.
std::optional<FieldsRecord> particleFields(const RunSet& runs, const std::string& label);

// Circular mean of phases given in [0, 1), in (0.5, 1.5].
double meanPhase(const std::vector<double>& phases);

}  // namespace granwave
