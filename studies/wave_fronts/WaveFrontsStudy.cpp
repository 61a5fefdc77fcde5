#include "studies/wave_fronts/WaveFrontsStudy.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <numeric>

#include "studies/hydro_run/HydroModel.hpp"
#include "studies/installation/InstalledFiles.hpp"
#include "studies/method_comparison/MethodRuns.hpp"
#include "studies/statistics/Measurement.hpp"
#include "studies/wave_fronts/WaveFrontsAnalysis.hpp"
#include "studies/wave_fronts/WaveFrontsReport.hpp"

namespace granwave {

std::vector<std::string> WaveFrontsConfig::countOverrides(int law, int count) const {
  const Scene& base = scenes.base[law];
  const double d = base.particles.diameter;
  // Height of N disks close-packed in rows of L_x / d: rows x sqrt(3)/2 d + d.
  const double rows = std::ceil(count * d / base.container.width);
  const double packed = rows * std::sqrt(3.0) / 2 * d + d;
  std::vector<std::string> o{fmt::format("particles.count={}", count)};
  const double height = std::max(base.container.height, packed + sweep_headroom);
  if (height > base.container.height) o.push_back(fmt::format("container.height={:.6g}", height));
  // Random sequential placement jams near an area fraction of 0.55 (Feder, J. Theor. Biol. 87,
  // 237 (1980)); here it placed N = 600 in the paper's box (0.52) and failed for N = 900 (0.64).
  // Denser boxes start from the lattice (the transient is discarded either way).
  const double area_fraction =
      count * std::numbers::pi * d * d / 4 / (base.container.width * height);
  if (area_fraction > 0.53) o.push_back("initial.placement=\"lattice\"");
  return o;
}

std::string WaveFrontsConfig::countTag(int count, int seed, int first_seed) {
  return seed == first_seed ? fmt::format("N={}", count) : fmt::format("N={} seed {}", count, seed);
}

void WaveFrontsStudy::readKeys(StudyFile& f) {
  c_.scenes = LawScenes::read(f);
  c_.duration = f.number("particles", "duration", c_.duration);
  c_.seeds = f.integers("particles", "seeds", c_.seeds);
  c_.max_seeds = f.integer("particles", "max_seeds", c_.max_seeds);
  c_.seed_step = f.integer("particles", "seed_step", c_.seed_step);
  c_.front_tolerance = f.number("verdicts", "front_tolerance", c_.front_tolerance);
  c_.share_tolerance = f.number("verdicts", "share_tolerance", c_.share_tolerance);
  c_.resamples = f.integer("verdicts", "resamples", c_.resamples);
  if (c_.seeds.empty()) f.fail("particles", "seeds", "expected at least one seed");
  if (c_.max_seeds < static_cast<int>(c_.seeds.size()) || c_.max_seeds > 1000)
    f.fail("particles", "max_seeds", "expected from the number of seeds listed up to 1000");
  if (c_.seed_step < 1) f.fail("particles", "seed_step", "expected 1 or more seeds per round");
  if (!(c_.front_tolerance > 0 && c_.front_tolerance < 1))
    f.fail("verdicts", "front_tolerance", "expected a fraction of the front speed in (0, 1)");
  if (!(c_.share_tolerance > 0 && c_.share_tolerance < 1))
    f.fail("verdicts", "share_tolerance", "expected a difference of time shares in (0, 1)");
  if (c_.resamples < 20 || c_.resamples > 100000)
    f.fail("verdicts", "resamples", "expected 20 to 100000 bootstrap resamples");
  c_.window = f.integer("particles", "window_cycles", c_.window);
  c_.blocks = f.integer("particles", "blocks", c_.blocks);
  c_.profile_phases = f.numbers("particles", "profile_phases", c_.profile_phases);
  c_.sweep_duration = f.number("sweep", "duration", c_.sweep_duration);
  c_.counts = f.integers("sweep", "counts", c_.counts);
  c_.sweep_seeds = f.integers("sweep", "seeds", c_.sweep_seeds);
  if (c_.sweep_seeds.empty()) f.fail("sweep", "seeds", "expected at least one seed");
  c_.sweep_phases = f.integer("sweep", "phases_per_cycle", c_.sweep_phases);
  if (c_.sweep_phases < 10 || c_.sweep_phases > 2000)
    f.fail("sweep", "phases_per_cycle", "expected an integer in [10, 2000]");
  c_.sweep_headroom = f.number("sweep", "headroom", c_.sweep_headroom);
  if (!(c_.sweep_headroom >= 0 && c_.sweep_headroom <= 1))
    f.fail("sweep", "headroom", "expected a height in m in [0, 1]");
  c_.answer_cycles = f.number("sweep", "answer_cycles", c_.answer_cycles);
  if (!(c_.answer_cycles >= 1 && c_.answer_cycles <= 1e6))
    f.fail("sweep", "answer_cycles", "expected a number of cycles in [1, 1e6]");
  c_.stokes = f.numbers("sweep", "stokes_critical", c_.stokes);
  c_.e_inf = f.numbers("sweep", "e_inf", c_.e_inf);
  c_.cost_durations = f.numbers("cost", "durations", c_.cost_durations);
  c_.cost_cells = f.integers("cost", "hydro_cells", c_.cost_cells);
  c_.cost_rtol = f.numbers("cost", "hydro_rtol", c_.cost_rtol);
  c_.fail_gammas = f.numbers("failure", "gammas", c_.fail_gammas);
  c_.fail_duration = f.number("failure", "duration", c_.fail_duration);
  c_.fail_cells = f.integers("failure", "hydro_cells", c_.fail_cells);
  c_.fail_rtol = f.numbers("failure", "hydro_rtol", c_.fail_rtol);
  c_.lammps_mode = f.string("lammps", "run", c_.lammps_mode);
  if (c_.lammps_mode != "auto" && c_.lammps_mode != "yes" && c_.lammps_mode != "no")
    f.fail("lammps", "run", "expected \"auto\", \"yes\" or \"no\"");
  c_.lammps_install = f.boolean("lammps", "install", c_.lammps_install);
  c_.lammps_executable = f.string("lammps", "executable", c_.lammps_executable);
  c_.lammps_duration = f.number("lammps", "duration", c_.lammps_duration);
  c_.lammps_seed = f.integer("lammps", "seed", c_.lammps_seed);
  // The deck: given relative to the study file, else the one installed with the program.
  c_.lammps_deck = f.string("lammps", "deck", "");
  if (c_.lammps_mode != "no")
    c_.lammps_deck = c_.lammps_deck.empty() ? installedFile("lammps/paper-scene.lmp")
                                            : f.scenePath("lammps", "deck", "");
  if (c_.lammps_mode != "no" && !std::filesystem::exists(c_.lammps_deck))
    f.fail("lammps", "deck", "the LAMMPS deck " + c_.lammps_deck + " does not exist");
  if (c_.window < 1 || c_.window > 4) f.fail("particles", "window_cycles", "expected 1 to 4");
  if (c_.blocks < 2) f.fail("particles", "blocks", "expected at least 2");
  if (!(c_.duration > 0)) f.fail("particles", "duration", "expected a positive time in s");
}

RunRequest& WaveFrontsStudy::add(const StudyFile& f, RunKind kind, int law,
                                 const std::string& label, std::vector<std::string> overrides,
                                 double duration) {
  if (kind == RunKind::Particles)
    overrides.push_back(fmt::format("run.duration={}", formatCompact(duration)));
  RunRequest q = runRequest(kind, label, c_.scenes.scene(f, law, overrides));
  q.window_cycles = c_.window;
  q.blocks = c_.blocks;
  requests_.push_back(std::move(q));
  return requests_.back();
}

// The runs of one law: the paper's scene over seeds (with the simpler particle models), hydro
// with both closures, the N sweep, and the methods comparison's failure map and hydro models.
void WaveFrontsStudy::planLaw(const StudyFile& f, int law) {
  using C = WaveFrontsConfig;
  const std::string constant_e = fmt::format("contact.e={:.6f}", c_.e_eff[law]);
  for (int seed : c_.seeds) planSeed(f, law, seed, requests_);
  for (int seed : c_.extraSeeds()) planSeed(f, law, seed, extra_[law]);
  // The hydro runs of the paper's scene are sampled as densely as the N sweep: a deterministic
  // candidate's front error is its fit error alone, which more phases narrow.
  const std::string phases = fmt::format("run.phases_per_cycle={}", c_.sweep_phases);
  add(f, RunKind::Hydro, law, C::hydroRun(law, "velocity"), {phases}, 0);
  // The energy budget phase by phase (PhaseEnergyBudget.hpp), smooth and rough, in runs of
  // their own: its quadratures change CVODE's steps slightly and cost about a fifth more, which
  // the cost per answer of the runs above should not carry.
  for (const std::string particles : {"smooth", "rough"})
    add(f, RunKind::Hydro, law, C::hydroRun(law, "budget " + particles),
        {phases, "hydro.energy_budget=true", "hydro.particles=\"" + particles + "\""}, 0);
  add(f, RunKind::Hydro, law, C::hydroRun(law, "constant"),
      {"hydro.restitution_model=\"constant\"", constant_e, phases}, 0);
  for (int n : c_.counts) {
    std::vector<std::string> count = c_.countOverrides(law, n);
    count.push_back(phases);
    for (int sd : c_.sweep_seeds) {
      std::vector<std::string> o = count;
      o.push_back(fmt::format("run.seed={}", sd));
      // With the fields of the period-2 windows aligned on their strong impact: a layer that
      // alternates impacts has no trackable front in the pooled window (docs/studies.md).
      add(f, RunKind::Particles, law,
          C::particleRun(law, C::countTag(n, sd, c_.sweep_seeds.front())), o, c_.sweep_duration)
          .state_fields = true;
    }
    add(f, RunKind::Hydro, law, C::hydroRun(law, fmt::format("N={}", n)), count, 0);
  }
  for (const PlannedRun& r : failureMapRuns(c_, law)) add(f, r);
  for (const PlannedRun& r : modelHydroRuns(c_, law)) add(f, r);
}

RunRequest& WaveFrontsStudy::add(const StudyFile& f, const PlannedRun& r) {
  RunRequest& q = add(f, r.kind, r.law, r.label, r.overrides, r.duration);
  q.failure_note = r.failure_note;
  return q;
}

// The paper's scene on one seed: the full particle model and the simpler particle models,
// with the same seed (the wet layer's period is bistable: one seed would not say which period
// a model gives).
void WaveFrontsStudy::planSeed(const StudyFile& f, int law, int sd, std::vector<RunRequest>& into) {
  const std::string seed = fmt::format("run.seed={}", sd);
  const std::string constant_e = fmt::format("contact.e={:.6f}", c_.e_eff[law]);
  // Only the full model's runs are read state by state (analyseStates).
  auto push = [&](const std::string& tag, std::vector<std::string> overrides) {
    overrides.push_back(fmt::format("run.duration={}", formatCompact(c_.duration)));
    RunRequest q = runRequest(RunKind::Particles,
                              WaveFrontsConfig::particleRun(law, fmt::format("{}seed {}", tag, sd)),
                              c_.scenes.scene(f, law, overrides));
    q.window_cycles = c_.window;
    q.blocks = c_.blocks;
    q.state_fields = tag.empty();
    into.push_back(std::move(q));
  };
  push("", {seed});
  push("no rotation ", {"contact.friction=0", seed});
  push("constant e ", {"contact.restitution=\"constant\"", constant_e, seed});
}

// More seeds of a law whose simplest-model verdict is undecided, seed_step at a time (three
// runs a seed: the full model, no rotation, constant e), until the law has max_seeds.
FollowUp WaveFrontsStudy::followUp(const RunSet& runs) const {
  FollowUp more;
  for (int law = 0; law < kLaws; ++law) {
    const std::size_t have = seedsOf(c_, runs, law).size();
    if (have >= static_cast<std::size_t>(c_.max_seeds)) continue;
    // Decided or not is the verdict of all seeds; the bootstrap beside it is for the report.
    const ModelInputs in = readModelInputs(c_, runs, law);
    std::vector<int> all(in.seeds.size());
    std::iota(all.begin(), all.end(), 0);
    if (!judgeModels(c_, in, law, all).undecided) continue;
    const std::size_t from = 3 * (have - c_.seeds.size());
    const std::size_t to = std::min(extra_[law].size(), from + 3 * c_.seed_step);
    more.runs.insert(more.runs.end(), extra_[law].begin() + static_cast<long>(from),
                     extra_[law].begin() + static_cast<long>(to));
    more.reason += fmt::format("{}the {} law's simplest-model verdict is undecided over {} seeds",
                               more.reason.empty() ? "" : "; ", kLawNames[law], have);
    const std::size_t left = (extra_[law].size() - to) / 3;  // seeds after this round
    const auto step = static_cast<std::size_t>(c_.seed_step);
    more.rounds_after = std::max(more.rounds_after, static_cast<int>((left + step - 1) / step));
    more.runs_after += 3 * left;
  }
  if (!more.runs.empty())
    more.reason +=
        fmt::format(" (seeds are added {} at a time, up to {})", c_.seed_step, c_.max_seeds);
  return more;
}

// The wet law's parameters (Fig. 6b), then the methods comparison's cost against accuracy.
void WaveFrontsStudy::planWetSweeps(const StudyFile& f) {
  using C = WaveFrontsConfig;
  const std::string seed1 = fmt::format("run.seed={}", c_.seeds.front());
  for (const auto& [key, values] : {std::pair{"St_c", c_.stokes}, std::pair{"e_inf", c_.e_inf}})
    for (double v : values) {
      const std::string tag = fmt::format("{}={}", key, formatCompact(v));
      const std::string set =
          fmt::format("contact.{}={}", std::string(key) == "St_c" ? "stokes_critical" : "e_inf",
                      formatCompact(v));
      add(f, RunKind::Particles, 1, C::particleRun(1, tag), {set, seed1}, c_.sweep_duration);
      add(f, RunKind::Hydro, 1, C::hydroRun(1, tag), {set}, 0);
    }
  for (const PlannedRun& r : costRuns(c_)) add(f, r);
}

WaveFrontsStudy::WaveFrontsStudy(StudyFile& f) {
  readKeys(f);
  c_.scenes.loadBase(f);
  for (int law = 0; law < kLaws; ++law) {
    if (!(c_.scenes.base[law].drive.frequency > 0))
      f.fail("scenes", kLawNames[law], "the wave-fronts study needs a driven scene");
    c_.e_eff[law] = effectiveRestitutionAtT0(c_.scenes.base[law]);
  }
  for (int law = 0; law < kLaws; ++law) planLaw(f, law);
  if (std::optional<RunRequest> lammps = lammpsRequest(f, c_)) requests_.push_back(*lammps);
  planWetSweeps(f);
}

void WaveFrontsStudy::analyse(const RunSet& runs, h5::File& results, Report& report) const {
  const WaveFrontsResults r = analyseWaveFronts(c_, runs);
  writeWaveFrontsResults(results, c_, r);
  reportWaveFronts(c_, r, report);
}

std::unique_ptr<Study> makeWaveFrontsStudy(StudyFile& file) {
  return std::make_unique<WaveFrontsStudy>(file);
}

}  // namespace granwave
