// The paper's scene resolved by the layer's state (docs/studies.md, "State-resolved
// statistics"): state shares over seeds with their intervals, fronts and r_x of each state's
// episodes.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "coarse_grain/PeriodDoublingSeries.hpp"
#include "studies/contract/StudyResults.hpp"
#include "studies/wave_analysis/WaveMomentumRatio.hpp"
#include "studies/wave_fronts/WaveFrontsAnalysis.hpp"

namespace granwave {

namespace {

// Mean over seeds of per-seed values, error the standard error (or the one run's spread).
Measurement overSeedRuns(const std::vector<Measurement>& v) {
  if (v.size() == 1) return v.front();
  std::vector<double> values;
  for (const Measurement& m : v) values.push_back(m.value);
  return meanAndStandardError(values);
}

void addSeed(StateShares& s, const FieldsRecord& run) {
  const PeriodDoublingSeries& series = run.context.period_doubling;
  ++s.seeds;
  s.seeds_period2 += run.context.layer_period == 2;
  s.windows += static_cast<int>(series.f2_strength.size());
  s.windows_period2 += period2Windows(series);
  s.effective_windows += series.effective_windows;
  for (double t : series.threshold) s.max_threshold = std::max(s.max_threshold, t);
  for (int k = 0; k < 2; ++k) s.state_windows[k] += std::max(0, run.state_windows[k]);
}

}  // namespace

StateShares analyseStates(const WaveFrontsConfig& c, const RunSet& runs, int law) {
  StateShares s;
  std::vector<Measurement> fronts[2];  // velocity-jump fronts (VelocityFronts.hpp)
  std::vector<Measurement> ratios[2];
  std::vector<Measurement> weak, strong;  // the period-2 state's impacts
  for (int sd : seedsOf(c, runs, law)) {
    const RunRecord& r = runs.get(WaveFrontsConfig::particleRun(law, fmt::format("seed {}", sd)));
    if (!r.ok) continue;
    const FieldsRecord run = readFieldsFile(r.fieldsPath());
    if (run.context.period_doubling.f2_strength.empty()) continue;  // no whole window
    addSeed(s, run);
    const std::string dry_label = WaveFrontsConfig::particleRun(0, fmt::format("seed {}", sd));
    std::optional<FieldsRecord> dry;
    if (law == 1 && runs.has(dry_label)) dry = particleFields(runs, dry_label);
    for (int k = 0; k < 2; ++k) {
      const auto state = readStateFields(r.fieldsPath(), k + 1);
      if (!state) continue;
      const VelocityFronts v = velocityFronts(*state);
      fronts[k].push_back(v.speed);
      if (k == 1) weak.push_back(v.weak);
      if (k == 1) strong.push_back(v.strong);
      if (!dry) continue;
      const Measurement ratio = waveMomentumRatio(*dry, *state, {});
      if (ratio.valid()) ratios[k].push_back(ratio);
    }
  }
  if (s.seeds > 0) {
    s.seed_share = static_cast<double>(s.seeds_period2) / s.seeds;
    wilsonInterval(s.seed_share, s.seeds, s.seed_low, s.seed_high);
  }
  // The same pooled share as the model hierarchy's reference (StateShare.hpp).
  const StateShare time = pooledStateShare(s.windows, s.windows_period2, s.effective_windows);
  s.time_share = time.share;
  s.time_low = time.low;
  s.time_high = time.high;
  s.period2_weak = combine(weak);
  s.period2_strong = combine(strong);
  for (int k = 0; k < 2; ++k) {
    s.front[k] = combine(fronts[k]);
    s.front_seeds[k] = static_cast<int>(fronts[k].size());
    if (!ratios[k].empty()) s.r_x[k] = overSeedRuns(ratios[k]);
    s.r_x_seeds[k] = static_cast<int>(ratios[k].size());
  }
  return s;
}

void writeStates(h5::File& f, const std::string& root, int law, const StateShares& s) {
  const std::string g = fmt::format("{}/states/{}", root, kLawNames[law]);
  f.createGroup(g);
  putValue(f, g, "seeds", s.seeds);
  putValue(f, g, "seeds_period2", s.seeds_period2);
  putValue(f, g, "seed_share", s.seed_share);
  putValue(f, g, "seed_share_low", s.seed_low);
  putValue(f, g, "seed_share_high", s.seed_high);
  putValue(f, g, "windows", s.windows);
  putValue(f, g, "windows_period2", s.windows_period2);
  putValue(f, g, "effective_windows", s.effective_windows);
  putValue(f, g, "time_share", s.time_share);
  putValue(f, g, "time_share_low", s.time_low);
  putValue(f, g, "time_share_high", s.time_high);
  putValue(f, g, "max_threshold", s.max_threshold);
  for (int k = 0; k < 2; ++k) {
    const std::string p = fmt::format("period{}", k + 1);
    putMeasurement(f, g, p + "_front", s.front[k]);
    putValue(f, g, p + "_front_seeds", s.front_seeds[k]);
    putValue(f, g, p + "_windows", s.state_windows[k]);
    if (law == 1) putMeasurement(f, g, p + "_r_x", s.r_x[k]);
    if (law == 1) putValue(f, g, p + "_r_x_seeds", s.r_x_seeds[k]);
  }
  putMeasurement(f, g, "period2_weak_front", s.period2_weak);
  putMeasurement(f, g, "period2_strong_front", s.period2_strong);
}

}  // namespace granwave
