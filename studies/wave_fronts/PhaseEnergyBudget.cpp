// The layer's energy budget phase by phase on the paper's scene (docs/studies.md).
#include "studies/wave_fronts/PhaseEnergyBudget.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numeric>

#include "studies/contract/StudyResults.hpp"
#include "studies/method_comparison/RunOutcomes.hpp"
#include "studies/wave_fronts/WaveFrontsStudy.hpp"

namespace granwave {

namespace {

double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

// The full particle model over the seeds: per phase the mean of the seeds' fields, per cycle
// the mean and standard error of the seeds' window totals.
BudgetSeries particleBudget(const WaveFrontsConfig& c, const RunSet& runs, int law) {
  BudgetSeries b;
  b.model = "particles";
  std::vector<double> work, pair, wall;
  for (int sd : seedsOf(c, runs, law)) {
    const auto p =
        particleFields(runs, WaveFrontsConfig::particleRun(law, fmt::format("seed {}", sd)));
    if (!p || p->profiles.pooled.plate_work.empty()) continue;
    const PhaseFields& f = p->profiles.pooled;
    if (b.phase.empty()) {
      b.phase = p->profiles.phase;  // each record ends the interval it is pooled with
      b.work.assign(b.phase.size(), 0.0);
      b.pair_loss.assign(b.phase.size(), 0.0);
      b.wall_loss.assign(b.phase.size(), 0.0);
    }
    if (f.plate_work.size() != b.work.size()) continue;  // another phase grid: not pooled
    for (std::size_t k = 0; k < b.work.size(); ++k) {
      b.work[k] += f.plate_work[k];
      b.pair_loss[k] += f.pair_loss[k];
      b.wall_loss[k] += f.wall_loss[k];
    }
    const double cycles = p->cycles_per_window;
    work.push_back(sum(f.plate_work) / cycles);
    pair.push_back(sum(f.pair_loss) / cycles);
    wall.push_back(sum(f.wall_loss) / cycles);
    ++b.seeds;
  }
  if (b.seeds == 0) {
    b.why = "no particle run of this law recorded its budget";
    return b;
  }
  for (auto* v : {&b.work, &b.pair_loss, &b.wall_loss})
    for (double& x : *v) x /= b.seeds;
  b.work_per_cycle = meanAndStandardError(work);
  b.pair_per_cycle = meanAndStandardError(pair);
  b.wall_per_cycle = meanAndStandardError(wall);
  return b;
}

// A continuum run's budget over its window (rough particles: friction and rotation count with
// the pair collisions, as the particles' pair loss holds both parts of an impact).
BudgetSeries continuumBudget(const RunSet& runs, const std::string& label,
                             const std::string& model) {
  BudgetSeries b;
  b.model = model;
  const HydroOutcome h = hydroOutcome(runs, label);
  if (!h.fields) {
    b.why = "the run failed";
    return b;
  }
  const RunEnergyBudget& e = h.fields->budget;
  if (e.empty()) {
    b.why = "the run did not record its budget";
    return b;
  }
  b.phase = h.fields->lab.phase;  // each phase ends the interval its budget covers
  b.work = e.plate_work;
  b.wall_loss = e.wall_loss;
  for (std::size_t k = 0; k < e.plate_work.size(); ++k)
    b.pair_loss.push_back(e.collisional_loss[k] + e.friction_loss[k]);
  const double cycles = h.fields->windowCycles();
  b.work_per_cycle = {sum(b.work) / cycles, 0.0};
  b.pair_per_cycle = {sum(b.pair_loss) / cycles, 0.0};
  b.wall_per_cycle = {sum(b.wall_loss) / cycles, 0.0};
  return b;
}

void writeSeries(h5::File& f, const std::string& g, const BudgetSeries& b) {
  f.createGroup(g);
  f.writeStringAttribute(g, "why_none", b.why);
  if (!b.valid()) return;
  putSeries(f, g + "/phase", b.phase, "1");
  putSeries(f, g + "/plate_work", b.work, "J");
  putSeries(f, g + "/pair_loss", b.pair_loss, "J");
  putSeries(f, g + "/wall_loss", b.wall_loss, "J");
  putMeasurement(f, g, "plate_work_per_cycle", b.work_per_cycle);
  putMeasurement(f, g, "pair_loss_per_cycle", b.pair_per_cycle);
  putMeasurement(f, g, "wall_loss_per_cycle", b.wall_per_cycle);
}

}  // namespace

LawBudgets analyseBudgets(const WaveFrontsConfig& c, const RunSet& runs, int law) {
  return {particleBudget(c, runs, law),
          continuumBudget(runs, WaveFrontsConfig::hydroRun(law, "budget smooth"),
                          "continuum, smooth disks"),
          continuumBudget(runs, WaveFrontsConfig::hydroRun(law, "budget rough"),
                          "continuum, rough particles")};
}

void writeBudgets(h5::File& f, const std::string& root, int law, const LawBudgets& b) {
  const std::string g = fmt::format("{}/energy_budget/{}", root, kLawNames[law]);
  writeSeries(f, g + "/particles", b.particles);
  writeSeries(f, g + "/continuum_smooth", b.smooth);
  writeSeries(f, g + "/continuum_rough", b.rough);
}

}  // namespace granwave
