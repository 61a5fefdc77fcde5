#pragma once
// The phase-averaged fields of a recorded particle run (`granwave fields`, docs/fields.md): the
// run file's every record replayed through the averager, the pattern sampler, the surface
// recorder and, if asked, the state-conditioned averager; the layer's period and its period-2
// series by the rule every command uses (coarse_grain/PeriodDetector.hpp, runPeriod), so a run
// has one period.
#include <string>

#include "coarse_grain/FieldsAnalysis.hpp"

namespace granwave {

struct RunFileFieldsOptions {
  int period = -1;               // cycles per phase window; -1: the layer's period (1-4), else 2
  int discard = -1;              // transient cycles left out; -1: the steady-state detector's
  int blocks = 5;                // independent blocks of cycles for the errors
  double front_threshold = 0.5;  // T~_g / T0 of a front (paper: 0.5)
  bool state_fields = false;     // also average the fields per layer state (/states)
};

// Throws std::runtime_error naming the run file if its scene is not driven, if it lacks a
// trajectory frame at some record, or if the layer never became steady.
FieldsAnalysis fieldsOfRunFile(const std::string& run_path, const RunFileFieldsOptions& options);

}  // namespace granwave
