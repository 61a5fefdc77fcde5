#pragma once
// Everything `granwave fields` derives from a phase-averaged run: pooled and per-block
// fields, profiles, fronts with speeds, and what was pooled. One value, written to a file by
// FieldsFile and read by the studies.
#include <string>
#include <vector>

#include "coarse_grain/PatternSampler.hpp"
#include "coarse_grain/PeriodDoublingSeries.hpp"
#include "coarse_grain/PhaseAverager.hpp"
#include "coarse_grain/PhaseFields.hpp"
#include "coarse_grain/WaveFront.hpp"

namespace granwave {

struct FieldsContext {
  double diameter = 0, mass = 0, inertia = 0;
  double frequency = 0, amplitude = 0, T0 = 0;
  int layer_period = 0;                  // detected period of the centre of mass (0 = unknown)
  PeriodDoublingSeries period_doubling;  // the period-2 state window by window (may be empty)
  std::string source;                    // run file or "live"
  std::string scene_toml;
};

struct FieldsAnalysis {
  FieldsContext context;
  FieldGrid grid;
  int samples_per_cycle = 0, cycles_per_window = 0, blocks = 0;
  int discarded_cycles = -1, pooled_cycles = 0;
  FieldParams params;
  FrontOptions front_options;
  PhaseFields pooled;
  std::vector<PhaseFields> per_block;
  std::vector<double> front_height, front_peak;  // [phase]
  std::vector<FrontEpisode> fronts;
  PatternResult patterns;  // filled by the caller from a PatternSampler (may be unavailable)
  double phaseTime(int phase) const { return phase / (samples_per_cycle * context.frequency); }
  double plateHeight(int phase) const;
};

// Throws std::runtime_error if nothing was pooled (the run never became steady or was too
// short).
FieldsAnalysis analyseFields(const PhaseAverager& averager, const FieldsContext& context,
                             const FrontOptions& front_options = {}, int min_count = 3);

}  // namespace granwave
