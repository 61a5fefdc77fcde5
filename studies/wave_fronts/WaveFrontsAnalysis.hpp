#pragma once
// The numbers of the wave-fronts study, section by section (docs/studies.md): the paper's
// scene, the N and wet-law sweeps, cost against accuracy, where each method fails, the model
// hierarchy and the LAMMPS comparison; written under /results/wave_fronts.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "coarse_grain/PeriodDetector.hpp"
#include "h5/File.hpp"
#include "studies/framework/ImpactFronts.hpp"
#include "studies/framework/Measurement.hpp"
#include "studies/framework/StateShare.hpp"
#include "studies/framework/Study.hpp"
#include "studies/framework/VelocityFronts.hpp"
#include "studies/run_files/HydroRunFile.hpp"
#include "studies/wave_fronts/WaveFrontsStudy.hpp"

namespace granwave {

// The paper's numbers (Huang, Sec. IV: Fig. 5 fronts; Fig. 6a collision times).
inline const Measurement kPaperWeakWet{1.61, 0.25}, kPaperStrongWet{1.95, 0.25};
inline constexpr double kPaperCollisionDry = 0.92, kPaperCollisionWet = 0.90;

// A hydro run's outcome: its fields and fronts, or why it failed.
struct HydroOutcome {
  std::optional<HydroRunContent> fields;
  std::string failure;
  ImpactFronts fronts;
  // The velocity-jump front (VelocityFronts.hpp), which the model hierarchy compares; set by
  // readModelInputs and paperLaw (it needs the scene's frequency).
  Measurement tracked;
  double collision_phase = NAN;  // t/T of the lowest centre of mass (mean over cycles)
  double cpu = 0;                // s
};

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
  // N sweep: the velocity-jump tracker over the sweep's seeds and on the hydro run.
  VelocityFronts tracked, hydro_tracked;
  int tracked_seeds = 0;
};

struct ParameterSweep {
  std::string key;  // "St_c", "e_inf"
  std::vector<double> values;
  std::vector<SweepPoint> points;
};

struct CostRow {
  bool particles = true, ok = true, reference = false;
  double duration = 0;  // s (particles)
  int cells = 0, pooled_cycles = 0;
  double rtol = 0, cpu = 0, error = NAN;  // error: statistical (particles) or |v - v_ref|
  Measurement speed;
  std::string failure;
};

struct CostAccuracy {
  std::vector<CostRow> rows;
  std::vector<double> ed_cpu, ed_error;
  std::map<double, std::pair<std::vector<double>, std::vector<double>>> hydro_by_rtol;
  double model_gap = NAN;
};

// Where each method fails: [gamma][law] for the particles without TC, [gamma][case] for hydro
// (cases: law, cells, rtol in that order).
struct FailureCase {
  bool ok = false, periodic = false;
  int period = 0, cycles = 0;
  double collapse_time = NAN;
  std::string failure;
  std::string regime;  // hydro: "at rest", "solid" or "fluidised" (docs/hydro.md)
};

struct FailureMap {
  std::vector<std::vector<FailureCase>> particles, hydro;
  std::vector<std::string> hydro_cases;  // "dry 100 cells rtol 0.01", ...
  int hydro_failures = 0;
};

// Whether a candidate reproduces the reference (docs/studies.md, "The simplest model that
// reproduces the particles"): `yes` when the 95 % intervals of its front speed's and its time
// share's differences lie within the study's tolerances, `no` when either lies wholly outside,
// otherwise `not_yet` (more seeds can decide it) or, for a deterministic (hydro) candidate
// whose own front error alone keeps the interval across the tolerance's edge, `cannot_tell`.
enum class Match { yes, no, not_yet, cannot_tell };
std::string matchText(Match m);
// The two tests (WaveFrontsMethods.cpp): front speeds against a relative tolerance, time
// shares against an absolute one.
Match frontMatch(const Measurement& candidate, const Measurement& reference, double tolerance,
                 bool deterministic);
Match shareMatch(const StateShare& candidate, const StateShare& reference, double tolerance);

struct ModelCandidate {
  std::string description, key;
  bool failed = false;  // every seed, or the hydro run
  std::string failure;
  Measurement speed;
  std::string periods;
  StateShare share;           // time in the period-2 state (hydro: exact from its period)
  ShareDifference share_gap;  // share - the reference's, with its 95 % interval
  double sigma = NAN;         // front speed - the reference's, in combined sigma
  Match match = Match::no;
};

// How stable a verdict is against the choice of seeds (docs/studies.md, "Verdict
// stability"). Decided unless a candidate before the first that reproduces is `not_yet`;
// then seeds are added up to [particles] max_seeds. At the cap a candidate still open has not
// been shown to reproduce (an equivalence test that cannot reject "different" does not claim
// "equal"), so the verdict is the simplest candidate shown to reproduce, or "none", and the
// open ones are named. Beside it, the share of bootstrap resamples of the seeds (same number,
// drawn with replacement) that give the same verdict as all seeds.
struct VerdictStability {
  std::string verdict;  // the full set's: a candidate, "none" or (below the cap) "undecided"
  double agreement = NAN;
  int seeds = 0, resamples = 0;
  bool decided = false;
  std::vector<std::string> open;         // at the cap: candidates before the verdict still open
  std::map<std::string, double> shares;  // every verdict the resamples gave, with its share
};

struct ModelHierarchy {
  Measurement reference;
  std::string reference_periods;
  int reference_period = 0;
  StateShare reference_share;
  std::vector<ModelCandidate> candidates;
  std::string simplest;    // empty: none reproduces the particles (or undecided)
  bool undecided = false;  // a candidate before `simplest` (or any, if none) is not_yet
  // Passing over open candidates: the simplest shown to reproduce (empty: none), and the open
  // ones before it. The verdict at the cap of seeds.
  std::string shown;
  std::vector<std::string> open;
  double front_tolerance = NAN, share_tolerance = NAN;  // the study's, judged with
  VerdictStability stability;
};

// One particle run of a model on one seed: its velocity-jump front (what the model hierarchy
// compares), layer period and state windows (all, in the period-2 state, effective).
struct SeedRun {
  bool ok = false;
  Measurement tracked;  // m/s, velocity-jump front (VelocityFronts.hpp)
  int period = 0;
  int windows = 0, period2_windows = 0;
  double effective_windows = 0;
};

// What the model hierarchy is judged from, read once: per particle model tag ("", "constant
// e ", "no rotation ") the runs of each seed in `seeds`, and the hydro candidates by run label.
struct ModelInputs {
  std::vector<int> seeds;
  std::map<std::string, std::vector<SeedRun>> particles;
  std::map<std::string, HydroOutcome> hydro;
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
};

// The dry layer with LAMMPS beside the event-driven engine (seed 1) and hydro (velocity-
// dependent closure): cost per simulated second, centre-of-mass period and mean height.
struct MethodOnDryScene {
  bool ran = false;                          // finished
  double cpu_rate = NAN, mean_height = NAN;  // CPU s per simulated s; centre of mass / d
  int period = 0;
  Measurement front;
};

struct LammpsComparison {
  MethodOnDryScene ed, hydro;
  bool ok = false;  // the LAMMPS run
  std::string failure;
  double ed_rate = NAN, lammps_rate = NAN, ratio = NAN;  // CPU s per simulated s
  double mean_height = NAN;                              // centre of mass / d
  PeriodResult period;
  std::vector<double> folded_phase, folded_height;  // two cycles, / d
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
};

WaveFrontsResults analyseWaveFronts(const WaveFrontsConfig& config, const RunSet& runs);
void writeWaveFrontsResults(h5::File& file, const WaveFrontsConfig& config,
                            const WaveFrontsResults& results);

// Circular mean of phases given in [0, 1), in (0.5, 1.5].
double meanPhase(const std::vector<double>& phases);

// Parts of the analysis by section; WaveFrontsMethods.cpp: where methods fail, the model
// hierarchy, LAMMPS.
HydroOutcome hydroOutcome(const RunSet& runs, const std::string& label);
// Its velocity-jump fronts (the time between phases from the window and the drive frequency;
// none without fields).
VelocityFronts trackedHydroFronts(const HydroOutcome& h, double frequency);
// Does the T~g peak of front `f` rise by more than `limit` (m) between two of its phases?
bool peakJumps(const PhaseProfiles& p, const FrontEpisode& f, double limit);
std::optional<FieldsRecord> particleFields(const RunSet& runs, const std::string& label);
FailureMap analyseFailures(const WaveFrontsConfig& config, const RunSet& runs);
// The seeds of the paper's scene that ran: the study's, then any added for an undecided
// verdict (WaveFrontsVerdicts.cpp).
std::vector<int> seedsOf(const WaveFrontsConfig& config, const RunSet& runs, int law);
ModelInputs readModelInputs(const WaveFrontsConfig& config, const RunSet& runs, int law);
// The hierarchy over the picked seeds (indices into inputs.seeds).
ModelHierarchy judgeModels(const WaveFrontsConfig& config, const ModelInputs& inputs, int law,
                           const std::vector<int>& pick);
// judgeModels over every seed, with its stability.
ModelHierarchy analyseModels(const WaveFrontsConfig& config, const RunSet& runs, int law);
VerdictStability modelVerdictStability(const WaveFrontsConfig& config, const ModelInputs& inputs,
                                       int law);
StateShares analyseStates(const WaveFrontsConfig& config, const RunSet& runs, int law);
void writeStates(h5::File& file, const std::string& root, int law, const StateShares& states);
LammpsComparison analyseLammps(const WaveFrontsConfig& config, const RunSet& runs,
                               const PaperLaw& dry);
void writeFailures(h5::File& file, const std::string& root, const WaveFrontsConfig& config,
                   const FailureMap& failures);
void writeModels(h5::File& file, const std::string& root, int law, const ModelHierarchy& models);
void writeLammps(h5::File& file, const std::string& root, const LammpsComparison& lammps);

}  // namespace granwave
