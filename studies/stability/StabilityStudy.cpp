#include "studies/stability/StabilityStudy.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <set>

#include "studies/stability/StabilityAnalysis.hpp"
#include "studies/stability/StabilityReport.hpp"
#include "studies/statistics/Measurement.hpp"
#include "studies/statistics/SeedResampling.hpp"

namespace granwave {

std::string StabilityConfig::particleRun(int law, double f, double gamma, int seed) {
  return particleLabel(
      law, fmt::format("f={} Gamma={} seed {}", formatCompact(f), formatCompact(gamma), seed));
}

std::string StabilityConfig::hydroRun(int law, double f, double gamma, bool rough) {
  return hydroLabel(law, fmt::format("{}f={} Gamma={}", rough ? "rough " : "", formatCompact(f),
                                     formatCompact(gamma)));
}

void StabilityStudy::readKeys(StudyFile& f) {
  c_.scenes = LawScenes::read(f);
  c_.frequencies = f.numbers("grid", "frequencies", c_.frequencies);
  c_.gammas = f.numbers("grid", "gammas", c_.gammas);
  c_.cycles = f.number("particles", "cycles", c_.cycles);
  c_.seeds = f.integers("particles", "seeds", c_.seeds);
  c_.max_seeds = f.integer("particles", "max_seeds", std::max<int>(c_.max_seeds, c_.seeds.size()));
  c_.seed_step = f.integer("particles", "seed_step", c_.seed_step);
  c_.window = f.integer("particles", "window_cycles", c_.window);
  c_.blocks = f.integer("particles", "blocks", c_.blocks);
  c_.hydro = f.boolean("hydro", "enabled", c_.hydro);
  c_.hydro_rough = f.boolean("hydro", "rough", c_.hydro_rough) && c_.hydro;
  c_.gallery_per_state = f.integer("gallery", "per_state", c_.gallery_per_state);
  for (double v : c_.frequencies)
    if (!(v > 0)) f.fail("grid", "frequencies", "expected positive frequencies in Hz");
  for (double v : c_.gammas)
    if (!(v > 1)) f.fail("grid", "gammas", "expected Gamma > 1 (the layer must take off)");
  if (std::set<double>(c_.frequencies.begin(), c_.frequencies.end()).size() !=
      c_.frequencies.size())
    f.fail("grid", "frequencies", "expected distinct frequencies");
  if (std::set<double>(c_.gammas.begin(), c_.gammas.end()).size() != c_.gammas.size())
    f.fail("grid", "gammas", "expected distinct Gamma values");
  if (std::set<int>(c_.seeds.begin(), c_.seeds.end()).size() != c_.seeds.size())
    f.fail("particles", "seeds", "expected distinct seeds");
  if (!(c_.cycles >= 30)) f.fail("particles", "cycles", "expected at least 30 cycles");
  if (c_.max_seeds < static_cast<int>(c_.seeds.size()) || c_.max_seeds > 50)
    f.fail("particles", "max_seeds",
           fmt::format("expected from the number of seeds ({}) to 50", c_.seeds.size()));
  if (c_.seed_step < 1) f.fail("particles", "seed_step", "expected a positive integer");
}

std::vector<int> StabilityConfig::extraSeeds() const { return seedsAfter(seeds, max_seeds); }

RunRequest StabilityStudy::particleRequest(StudyFile& f, int law, double fr, double gamma,
                                           int seed) const {
  const std::vector<std::string> o{fmt::format("drive.frequency={}", formatCompact(fr)),
                                   fmt::format("drive.gamma={}", formatCompact(gamma)),
                                   fmt::format("run.duration={:.6g}", c_.cycles / fr),
                                   fmt::format("run.seed={}", seed)};
  RunRequest q = runRequest(RunKind::Particles, StabilityConfig::particleRun(law, fr, gamma, seed),
                            c_.scenes.scene(f, law, o));
  q.window_cycles = c_.window;
  q.blocks = c_.blocks;
  return q;
}

StabilityStudy::StabilityStudy(StudyFile& f) {
  readKeys(f);
  for (int law = 0; law < kLaws; ++law)
    for (double fr : c_.frequencies)
      for (double gamma : c_.gammas) {
        for (int seed : c_.seeds) requests_.push_back(particleRequest(f, law, fr, gamma, seed));
        // The continuum has no seed; the scene names the first one only so that it is
        // complete (the seed does not enter the hydro solver).
        const std::vector<std::string> o{fmt::format("drive.frequency={}", formatCompact(fr)),
                                         fmt::format("drive.gamma={}", formatCompact(gamma)),
                                         fmt::format("run.duration={:.6g}", c_.cycles / fr),
                                         fmt::format("run.seed={}", c_.seeds.front())};
        if (c_.hydro) addHydro(f, law, fr, gamma, o, false);
        if (c_.hydro_rough) addHydro(f, law, fr, gamma, o, true);
      }
  for (double fr : c_.frequencies)
    for (double gamma : c_.gammas) {
      std::vector<RunRequest> point;
      for (int seed : c_.extraSeeds())
        for (int law = 0; law < kLaws; ++law)
          point.push_back(particleRequest(f, law, fr, gamma, seed));
      extra_.push_back(std::move(point));
    }
}

// More seeds where they can change a verdict: while a feature is undecided, at every point
// whose seeds disagree (a point whose seeds agree is the same in every resample), seed_step
// seeds of both laws, until the point has max_seeds.
FollowUp StabilityStudy::followUp(const RunSet& runs) const {
  SeedPatterns seeds;
  const StabilityGrid grid = voteGrid(c_, runs, seeds);
  std::vector<std::string> undecided;
  for (const auto& [key, agreement] : bootstrapOverSeeds(grid, seeds).verdict_agreement)
    if (agreement < kDecidedAgreement)
      undecided.push_back(fmt::format("'{}' ({:.0f} %)", key, 100 * agreement));
  FollowUp more;
  if (undecided.empty()) return more;
  int points = 0;
  for (std::size_t p = 0; p < extra_.size(); ++p) {
    if (grid.verdicts[0][p].seedsAgree() && grid.verdicts[1][p].seedsAgree()) continue;
    const std::size_t have = seeds.patterns[0][p].size() - c_.seeds.size();
    const std::size_t to = std::min(extra_[p].size(), 2 * (have + c_.seed_step));
    more.runs.insert(more.runs.end(), extra_[p].begin() + static_cast<long>(2 * have),
                     extra_[p].begin() + static_cast<long>(to));
    points += to > 2 * have ? 1 : 0;
    const std::size_t left = (extra_[p].size() - to) / 2;  // seeds after this round
    const auto step = static_cast<std::size_t>(c_.seed_step);
    more.rounds_after = std::max(more.rounds_after, static_cast<int>((left + step - 1) / step));
    more.runs_after += 2 * left;
  }
  more.reason = fmt::format(
      "the verdicts {} agree in fewer than {:.0f} % of the seed resamples; {} more seed{} at the "
      "{} points whose seeds disagree (up to {} seeds a point)",
      fmt::join(undecided, ", "), 100 * kDecidedAgreement, c_.seed_step,
      c_.seed_step == 1 ? "" : "s", points, c_.max_seeds);
  return more;
}

void StabilityStudy::addHydro(StudyFile& f, int law, double fr, double gamma,
                              std::vector<std::string> o, bool rough) {
  if (rough) o.emplace_back("hydro.particles=\"rough\"");
  RunRequest q = runRequest(RunKind::Hydro, StabilityConfig::hydroRun(law, fr, gamma, rough),
                            c_.scenes.scene(f, law, o));
  q.failure_note = "failure is a result (the continuum's stability map)";
  requests_.push_back(std::move(q));
}

void StabilityStudy::analyse(const RunSet& runs, h5::File& results, Report& report) const {
  const StabilityResults r = analyseStability(c_, runs);
  writeStabilityResults(results, c_, r);
  reportStability(c_, r, report);
}

std::unique_ptr<Study> makeStabilityStudy(StudyFile& file) {
  return std::make_unique<StabilityStudy>(file);
}

}  // namespace granwave
