#pragma once
// The numbers of the wave-fronts study's methods comparison (docs/studies.md): the cost of each
// method against its accuracy, where each fails, the simplest model that reproduces the
// particles with the stability of that verdict over seeds, and soft-sphere DEM (LAMMPS) beside
// the event-driven engine and the continuum; written under /results/wave_fronts.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "coarse_grain/PeriodDetector.hpp"
#include "h5/File.hpp"
#include "studies/contract/Study.hpp"
#include "studies/method_comparison/MethodComparisonConfig.hpp"
#include "studies/method_comparison/RunOutcomes.hpp"
#include "studies/statistics/Measurement.hpp"
#include "studies/statistics/StateShare.hpp"

namespace granwave {

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
// The two tests (ModelHierarchy.cpp): front speeds against a relative tolerance, time
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
  // What the answer cost: particles, CPU-s per drive cycle (mean over the seeds' runs); hydro,
  // CPU-s of the whole run (the start to the periodic state).
  double cpu_per_cycle = NAN, run_cpu = NAN;
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
  double reference_cpu_per_cycle = NAN;  // CPU-s per drive cycle, mean over the seeds' runs
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
  double cpu_per_cycle = NAN;  // CPU-s per drive cycle of the run
};

// What the model hierarchy is judged from, read once: per particle model tag ("", "constant
// e ", "no rotation ") the runs of each seed in `seeds`, and the hydro candidates by run label.
struct ModelInputs {
  std::vector<int> seeds;
  std::map<std::string, std::vector<SeedRun>> particles;
  std::map<std::string, HydroOutcome> hydro;
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

// Cost against accuracy, wet layer; `particles_front` is the full particle model's combined
// impact-front speed on the paper's scene (the model gap is measured against it).
CostAccuracy costAccuracy(const MethodComparisonConfig& config, const RunSet& runs,
                          const Measurement& particles_front);
void writeCostAccuracy(h5::File& file, const std::string& group, const CostAccuracy& cost);

FailureMap analyseFailures(const MethodComparisonConfig& config, const RunSet& runs);
void writeFailures(h5::File& file, const std::string& root, const MethodComparisonConfig& config,
                   const FailureMap& failures);

ModelInputs readModelInputs(const MethodComparisonConfig& config, const RunSet& runs, int law);
// The hierarchy over the picked seeds (indices into inputs.seeds).
ModelHierarchy judgeModels(const MethodComparisonConfig& config, const ModelInputs& inputs, int law,
                           const std::vector<int>& pick);
// judgeModels over every seed, with its stability.
ModelHierarchy analyseModels(const MethodComparisonConfig& config, const RunSet& runs, int law);
VerdictStability modelVerdictStability(const MethodComparisonConfig& config,
                                       const ModelInputs& inputs, int law);
void writeModels(h5::File& file, const std::string& root, int law, const ModelHierarchy& models);

// `dry_seed1`: the dry particle run of the first seed (if it finished); `dry_hydro`: the dry
// hydro run with the velocity-dependent closure.
LammpsComparison analyseLammps(const MethodComparisonConfig& config, const RunSet& runs,
                               const std::optional<FieldsRecord>& dry_seed1,
                               const HydroOutcome& dry_hydro);
void writeLammps(h5::File& file, const std::string& root, const LammpsComparison& lammps);

}  // namespace granwave
