// The alternative a user would run, soft-sphere DEM (LAMMPS), on the paper's dry scene beside
// the event-driven engine (seed 1) and the continuum: cost per simulated second, the centre
// of mass's period and mean height, folded onto two cycles.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "studies/contract/StudyResults.hpp"
#include "studies/method_comparison/MethodComparison.hpp"
#include "studies/run_files/RunOutputs.hpp"

namespace granwave {

LammpsComparison analyseLammps(const MethodComparisonConfig& c, const RunSet& runs,
                               const std::optional<FieldsRecord>& dry_seed1,
                               const HydroOutcome& dry_hydro) {
  LammpsComparison out;
  const double d = c.scenes.base[0].particles.diameter;
  const RunRecord& ed_run =
      runs.get(MethodComparisonConfig::particleRun(0, fmt::format("seed {}", c.seeds.front())));
  out.ed_rate = ed_run.ok ? ed_run.cpu / c.duration : NAN;
  if (dry_seed1) {
    double mean = 0;
    const PhaseProfiles& p = dry_seed1->profiles;
    for (double z : p.pooled.center_of_mass_height) mean += z / d / p.phases();
    out.ed = {true, out.ed_rate, mean, dry_seed1->context.layer_period, impactFronts(p).all};
  }
  if (const HydroOutcome& h = dry_hydro; h.fields) {
    double mean = 0;
    for (double z : h.fields->lab.pooled.center_of_mass_height)
      mean += z / d / h.fields->lab.phases();
    out.hydro = {true, h.cpu / (h.fields->cycles / c.scenes.base[0].drive.frequency), mean,
                 static_cast<int>(h.fields->period), h.fronts.all};
  }
  const RunRecord& r = runs.get(c.lammpsRun());
  out.ok = r.ok;
  if (!r.ok) {
    out.failure = r.message;
    return out;
  }
  const LammpsTrajectory l = readLammpsTrajectory(r.lammpsPath());
  const int M = 100;  // the deck's samples per cycle (its default, used by the study)
  PeriodOptions po;
  po.samples_per_cycle = M;
  const int cycles = static_cast<int>(l.com.size()) / M;
  out.period = detectPeriod(l.com, std::max(3, cycles / 5), po);
  out.lammps_rate = r.cpu / c.lammps_duration;
  double mean = 0;
  for (double z : l.com) mean += z / d / static_cast<double>(l.com.size());
  out.mean_height = mean;
  out.ratio = out.lammps_rate / out.ed_rate;
  // Centre of mass folded onto two cycles over the steady part (the last 80 % of cycles).
  std::vector<double> y(2 * M, 0.0);
  std::vector<int> n(2 * M, 0);
  const int first = std::max(3, cycles / 5) * M;
  for (std::size_t i = static_cast<std::size_t>(first); i < l.com.size(); ++i) {
    const double phase = l.time[i] * c.scenes.base[0].drive.frequency;
    const int k = static_cast<int>(std::lround(phase * M)) % (2 * M);
    y[k] += l.com[i] / d;
    ++n[k];
  }
  for (int k = 0; k < 2 * M; ++k) {
    out.folded_phase.push_back(static_cast<double>(k) / M);
    out.folded_height.push_back(n[k] ? y[k] / n[k] : NAN);
  }
  return out;
}

void writeLammps(h5::File& f, const std::string& root, const LammpsComparison& l) {
  if (!l.ok) return;
  putValue(f, root + "/lammps", "cpu_per_simulated_second", l.lammps_rate);
  putValue(f, root + "/lammps", "event_driven_cpu_per_simulated_second", l.ed_rate);
  putValue(f, root + "/lammps", "speed_ratio", l.ratio);
  putValue(f, root + "/lammps", "period", l.period.period);
}

}  // namespace granwave
