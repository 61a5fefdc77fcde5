#pragma once
// The numbers of the wave-fronts study, section by section (docs/studies.md): the paper's
// scene, the N and wet-law sweeps and the layer's states (this folder), and the methods
// comparison (studies/method_comparison/MethodComparison.hpp); written under
// /results/wave_fronts.
#include <optional>
#include <string>
#include <vector>

#include "h5/File.hpp"
#include "studies/contract/Study.hpp"
#include "studies/method_comparison/MethodComparison.hpp"
#include "studies/method_comparison/RunOutcomes.hpp"
#include "studies/statistics/Measurement.hpp"
#include "studies/wave_analysis/ImpactFronts.hpp"
#include "studies/wave_analysis/VelocityFronts.hpp"
#include "studies/wave_fronts/CheapestModel.hpp"
#include "studies/wave_fronts/PhaseEnergyBudget.hpp"
#include "studies/wave_fronts/WaveFrontsStudy.hpp"

namespace granwave {

// The paper's numbers (Huang, Sec. IV: Fig. 5 fronts; Fig. 6a collision times).
inline const Measurement kPaperWeakWet{1.61, 0.25}, kPaperStrongWet{1.95, 0.25};
inline constexpr double kPaperCollisionDry = 0.92, kPaperCollisionWet = 0.90;

// Section 1 and the profiles: one law on the paper's scene.
struct PaperLaw {
  ImpactFronts ed;  // combined over the finished seeds
  int seeds_used = 0;
  std::vector<int> periods;  // layer period of each finished seed
  double collision_phase = NAN;
  std::optional<FieldsRecord> first;  // the first finished seed (fronts, centre of mass)
  std::optional<FieldsRecord> seed1;  // the first seed listed, if finished (profiles)
  HydroOutcome hydro[2];              // velocity-dependent closure, constant e_eff
  VelocityFronts tracked;             // velocity-jump fronts, combined over the seeds
  // Impact fronts of the T~g peak over the seeds, and those whose peak rises between two
  // phases faster than kPeakJumpSpeed (2.5 times the fastest front the paper reports): a jump
  // to another maximum, not a travelling front.
  int peak_fronts = 0, peak_jumps = 0;
  static constexpr double kPeakJumpSpeed = 5.0;  // m/s
};

// One point of a sweep: particles (seed 1) and hydro.
struct SweepPoint {
  Measurement ed, hydro;
  double collision_phase = NAN;
  int layer_period = -1;  // -1: the particle run failed
  bool hydro_ok = false;
  std::string hydro_failure;
  double ed_cpu_per_cycle = NAN;  // CPU-s per drive cycle of the particle run
  double hydro_cpu = NAN;         // CPU-s of the hydro run, settled layer to periodic state
  // N sweep: the velocity-jump tracker over the sweep's seeds and on the hydro run, and the
  // layer's period of each seed's run and of the hydro run (0: not periodic or failed).
  VelocityFronts tracked, hydro_tracked;
  int tracked_seeds = 0;
  // The same tracker on the fields of each seed's period-2 windows, aligned on their strong
  // impact (simulate --state-fields), combined over the seeds that have them.
  VelocityFronts tracked_period2;
  int period2_seeds = 0;
  std::vector<int> seed_periods;
  int hydro_period = 0;
};

// The particles' transit `i` (0: mass 0.1-0.5, 1: 0.5-0.9) a continuum's is compared with: the
// whole run's, or where it has neither a speed nor a bound (a layer alternating its impacts,
// whose pooled 2-cycle window does not track the jump), the period-2 windows'.
const TransitSpeeds& particleTransit(const SweepPoint& p, int i);

struct ParameterSweep {
  std::string key;  // "St_c", "e_inf"
  std::vector<double> values;
  std::vector<SweepPoint> points;
};

// The paper's scene of one law, resolved by state (docs/studies.md, "State-resolved
// statistics"): the share of seeds whose run has period 2 and the share of time in the
// period-2 state, each with a 95 % Wilson interval (seeds: n = seeds; time: n = the sum of
// the seeds' effective windows, seeds being independent); the velocity-jump fronts of the
// period-1 and period-2 episodes combined over seeds, and (wet law) r_x of each state's episodes
// against the whole dry run of the same seed (mean over seeds, error: their standard error).
struct StateShares {
  int seeds = 0, seeds_period2 = 0;
  double seed_share = NAN, seed_low = NAN, seed_high = NAN;
  int windows = 0, windows_period2 = 0;
  double effective_windows = 0;
  double time_share = NAN, time_low = NAN, time_high = NAN;
  double max_threshold = 0;  // largest window threshold met (floor 0.1)
  Measurement front[2];      // period 1, period 2
  int front_seeds[2] = {0, 0};
  int state_windows[2] = {0, 0};  // windows pooled into each state's fields
  Measurement r_x[2];
  int r_x_seeds[2] = {0, 0};
  // The period-2 state's two impacts, weak and strong, from its windows aligned on their
  // strong impact (StatePhaseAverager): the whole run's 2-cycle average mixes episodes of both
  // parities, the state's does not. Combined over the seeds with such fields.
  Measurement period2_weak, period2_strong;
};

struct WaveFrontsResults {
  PaperLaw paper[2];
  std::vector<SweepPoint> n_sweep[2];
  ParameterSweep wet_sweeps[2];  // St_c, e_inf
  CostAccuracy cost;
  FailureMap failures;
  ModelHierarchy models[2];
  StateShares states[2];
  std::optional<LammpsComparison> lammps;
  std::vector<SceneCost> cheapest;  // per scene: the paper's dry and wet, then the N sweep
  LawBudgets budgets[2];            // the paper's scene, phase by phase
};

WaveFrontsResults analyseWaveFronts(const WaveFrontsConfig& config, const RunSet& runs);
void writeWaveFrontsResults(h5::File& file, const WaveFrontsConfig& config,
                            const WaveFrontsResults& results);

// Does the T~g peak of front `f` rise by more than `limit` (m) between two of its phases?
bool peakJumps(const PhaseProfiles& p, const FrontEpisode& f, double limit);
// The paper's scene resolved by the layer's state (WaveFrontsStates.cpp).
StateShares analyseStates(const WaveFrontsConfig& config, const RunSet& runs, int law);
void writeStates(h5::File& file, const std::string& root, int law, const StateShares& states);

}  // namespace granwave
