#pragma once
// The numbers of the continuum-sensitivity study: per case, each run's answers (period,
// centre-of-mass range, impact fronts) and how far each moved from the base run's when one
// parameter was scaled; written under /results/continuum_sensitivity (docs/studies.md).
#include <limits>
#include <string>
#include <vector>

#include "h5/File.hpp"
#include "studies/continuum_sensitivity/ContinuumSensitivityStudy.hpp"

namespace granwave {

// One impact front of a run's window (the velocity-jump tracker, coarse_grain/
// ImpactFrontTracker.hpp).
struct SensitivityFront {
  double start = 0;  // t/T of its first phase within the window
  bool resolved = false;
  double speed = 0;  // m/s (resolved), else the lower bound of its speed
  // m/s, the standard error of the straight-line fit through its heights (resolved fronts):
  // how well the window's sampling of a deterministic run fixes its speed.
  double fit_error = 0;
  // It crossed a packed bottom within one phase before it was tracked: the speed that takes
  // is above bulk_speed (m/s), a bound set by the sampling, so it is compared as present or
  // absent, not by value.
  bool bulk = false;
  double bulk_speed = 0;
};

// What one run answered.
struct SensitivityAnswer {
  bool ok = false;
  std::string failure;
  int period = 0;         // at the study's tolerance (0: none up to 4 cycles)
  int solver_period = 0;  // the solver's, at its stricter 2 % (0: not periodic)
  std::string regime;
  // The centre of mass's lowest and highest point above the plate per cycle (m), averaged
  // over the run's settled cycles (its second half, at least its window).
  double com_low = 0, com_high = 0;
  std::vector<SensitivityFront> fronts;
  double cpu_seconds = 0;
};

// How far a variant moved from its case's base run.
struct SensitivityChange {
  bool same_period = false;
  double com = 0;    // max(|d low|, |d high|) / (base high - base low)
  double front = 0;  // largest relative change of a matched front (0: both faster than the
                     // sampling or both without fronts; inf: a front appeared or vanished)
  // The change of the front with the largest relative change in units of its two fits'
  // combined error, sqrt(e_base^2 + e_run^2) (NaN: no resolved front matched, or no errors).
  // A rough guide, not a Gaussian significance: a fit through 3-4 phases has 1-2 degrees of
  // freedom, and a deterministic run's residuals are the sampling's, not noise; of order 1 or
  // below, the change is within what the fits fix.
  double front_sigma = std::numeric_limits<double>::quiet_NaN();
  bool within = false;  // same period, com and front below the tolerance
};

struct SensitivityCaseResult {
  std::vector<SensitivityAnswer> answers;  // [variant], base first
  std::vector<SensitivityChange> changes;  // [variant], base first (zero changes)
  int within = 0, compared = 0;
};

struct ContinuumSensitivityResults {
  std::vector<SensitivityCaseResult> cases;
};

SensitivityAnswer readSensitivityAnswer(const RunRecord& run, double tolerance);
SensitivityChange sensitivityChange(const SensitivityAnswer& base, const SensitivityAnswer& run,
                                    double tolerance);
ContinuumSensitivityResults analyseContinuumSensitivity(const ContinuumSensitivityConfig& config,
                                                        const RunSet& runs);
void writeContinuumSensitivityResults(h5::File& file, const ContinuumSensitivityConfig& config,
                                      const ContinuumSensitivityResults& results);

}  // namespace granwave
