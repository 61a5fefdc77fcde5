#pragma once
// Everything `granwave fields` derives from a phase-averaged run: pooled and per-block
// fields, profiles, fronts with speeds, and what was pooled. One value, written to a file by
// FieldsFile; the studies read the file back through FieldsReader.
#include <string>
#include <vector>

#include "coarse_grain/PatternSampler.hpp"
#include "coarse_grain/PeriodDoublingSeries.hpp"
#include "coarse_grain/PhaseAverager.hpp"
#include "coarse_grain/PhaseFields.hpp"
#include "coarse_grain/PhaseProfiles.hpp"
#include "coarse_grain/StatePhaseAverager.hpp"
#include "coarse_grain/SurfaceWaveSpectrum.hpp"
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
  PatternResult patterns;       // filled by the caller from a PatternSampler (may be unavailable)
  SurfaceWaveAnalysis surface;  // filled by the caller from a SurfaceRecorder (may be unavailable)
  // Conditioned on the layer's state (StatePhaseAverager): windows of 12 cycles counted in
  // each state (-1: not measured), and the fields of each state that has at least as many
  // windows as blocks (state_period 1 or 2; 0 in the whole-run analysis).
  int state_windows[2] = {-1, -1};
  int state_period = 0;
  std::vector<FieldsAnalysis> states;
  double phaseTime(int phase) const { return phase / (samples_per_cycle * context.frequency); }
  double plateHeight(int phase) const;
  // The window's profiles, phases and fronts, as the fields file stores them.
  PhaseProfiles profiles() const;
};

// Throws std::runtime_error if nothing was pooled (the run never became steady or was too
// short).
FieldsAnalysis analyseFields(const PhaseAverager& averager, const FieldsContext& context,
                             const FrontOptions& front_options = {}, int min_count = 3);

// The same from any set of sums laid out as `config` says.
FieldsAnalysis analyseAccumulated(const PhaseAccumulator& sums, const PhaseAveragerConfig& config,
                                  int discarded, int pooled, const FieldsContext& context,
                                  const FrontOptions& front_options = {}, int min_count = 3);

// Fills a.state_windows and a.states from a state-conditioned averager.
void addStateFields(FieldsAnalysis& a, const StatePhaseAverager& states);

}  // namespace granwave
