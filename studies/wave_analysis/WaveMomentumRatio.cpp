#include "studies/wave_analysis/WaveMomentumRatio.hpp"

#include <cmath>
#include <vector>

#include "coarse_grain/MomentumDeficiency.hpp"
#include "studies/wave_analysis/ImpactFronts.hpp"

namespace granwave {

namespace {

int wrapPhase(int k, int n) { return ((k % n) + n) % n; }

}  // namespace

Measurement waveMomentumRatio(const FieldsRecord& dry_run, const FieldsRecord& wet_run,
                              const WaveRatioOptions& o) {
  const PhaseProfiles& dry = dry_run.profiles;
  const PhaseProfiles& wet = wet_run.profiles;
  if (dry.phases() != wet.phases() || dry.rows() != wet.rows() || wet.phases() == 0) return {};
  const ImpactFronts fronts = impactFronts(wet);
  const double onset = fronts.strong_start >= 0 ? fronts.strong_start : o.fallback_onset;
  const int per_cycle =
      wet_run.cycles_per_window > 0 ? wet.phases() / wet_run.cycles_per_window : wet.phases();
  const int first = wet.phaseIndex(onset);
  const int n_wave = std::max(1, static_cast<int>(std::lround(o.wave_duration * per_cycle)));
  DeficiencyOptions d;
  d.select.assign(static_cast<std::size_t>(wet.phases()), false);
  for (int i = 0; i < n_wave; ++i) d.select[wrapPhase(first + i, wet.phases())] = true;
  d.min_rms = o.min_rms;
  d.min_area_fraction = o.min_area_fraction;
  const Deficiency r = momentumDeficiency(dry.pooled, wet.pooled, d);
  if (r.phases_used == 0) return {};
  return {r.mean, r.std_dev};
}

}  // namespace granwave
