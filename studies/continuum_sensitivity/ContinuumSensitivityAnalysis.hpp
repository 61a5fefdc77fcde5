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

// A front's passage between two mass fractions of the layer.
struct SensitivityTransit {
  bool reached = false;   // the track passes both fractions
  bool resolved = false;  // over at least three tracked phases
  double speed = 0;       // m/s (resolved), else the lower bound of its speed
};

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
  // Its transits between consecutive mass fractions of the study's `front_fractions`
  // (coarse_grain/FrontTransit.hpp): what the study compares, since a deep layer's front
  // decelerates and its fitted speed depends on where the track ends.
  std::vector<SensitivityTransit> transits;
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
  double com = 0;  // max(|d low|, |d high|) / (base high - base low)
  // The largest relative change of a matched front's transit speeds (0: both faster than the
  // sampling or both without fronts; inf: a front, or a transit, appeared or vanished, or
  // became faster than the sampling by more than the tolerance; NaN: a transit resolved in one
  // run only, whose bound in the other cannot tell them apart). A front with no transit
  // resolved in either run is compared by its fitted speed.
  double front = 0;
  // The largest relative change of a matched front's fitted speed (the straight line through its
  // whole track), shown beside the transits, and that change in units of its two fits' combined
  // error, sqrt(e_base^2 + e_run^2) (NaN: no resolved front matched, or no errors). A rough
  // guide, not a Gaussian significance: a deterministic run's residuals are the sampling's and
  // the track's curvature, not noise.
  double fit = 0;
  double fit_sigma = std::numeric_limits<double>::quiet_NaN();
  bool within = false;  // same period, com and front (transits) below the tolerance
};

struct SensitivityCaseResult {
  std::vector<SensitivityAnswer> answers;  // [variant], base first
  std::vector<SensitivityChange> changes;  // [variant], base first (zero changes)
  int within = 0, compared = 0;
};

struct ContinuumSensitivityResults {
  std::vector<SensitivityCaseResult> cases;
};

SensitivityAnswer readSensitivityAnswer(const RunRecord& run, double tolerance,
                                        const std::vector<double>& front_fractions);
SensitivityChange sensitivityChange(const SensitivityAnswer& base, const SensitivityAnswer& run,
                                    double tolerance);
ContinuumSensitivityResults analyseContinuumSensitivity(const ContinuumSensitivityConfig& config,
                                                        const RunSet& runs);
void writeContinuumSensitivityResults(h5::File& file, const ContinuumSensitivityConfig& config,
                                      const ContinuumSensitivityResults& results);

}  // namespace granwave
