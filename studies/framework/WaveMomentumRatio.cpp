#include "studies/framework/WaveMomentumRatio.hpp"

#include <cmath>
#include <vector>

#include "coarse_grain/MomentumDeficiency.hpp"
#include "studies/framework/ImpactFronts.hpp"

namespace granwave {

namespace {

int wrapPhase(int k, int n) { return ((k % n) + n) % n; }

// The pooled RMS(v_x) profile of one layer where both layers are dense enough, else NaN.
PhaseFields rmsProfile(const ParticleFields& layer, const ParticleFields& other, double min_af) {
  PhaseFields p;
  p.phases = layer.phases;
  p.nz = layer.nz;
  p.profile_rms_velocity_x.assign(static_cast<std::size_t>(p.phases) * p.nz, kNaN);
  for (int k = 0; k < p.phases; ++k)
    for (int j = 0; j < p.nz; ++j)
      if (layer.at(layer.area_fraction, k, j) >= min_af &&
          other.at(other.area_fraction, k, j) >= min_af)
        p.profile_rms_velocity_x[p.row(k, j)] = layer.at(layer.rms_velocity_x, k, j);
  return p;
}

}  // namespace

Measurement waveMomentumRatio(const ParticleFields& dry, const ParticleFields& wet,
                              const WaveRatioOptions& o) {
  if (dry.phases != wet.phases || dry.nz != wet.nz || wet.phases == 0) return {};
  const ImpactFronts fronts = impactFronts(wet.fronts);
  const double onset = fronts.strong_start >= 0 ? fronts.strong_start : o.fallback_onset;
  const int per_cycle = wet.cycles_per_window > 0 ? wet.phases / wet.cycles_per_window : wet.phases;
  const int first = wet.phaseIndex(onset);
  const int n_wave = std::max(1, static_cast<int>(std::lround(o.wave_duration * per_cycle)));
  std::vector<bool> select(static_cast<std::size_t>(wet.phases), false);
  for (int i = 0; i < n_wave; ++i) select[wrapPhase(first + i, wet.phases)] = true;
  const Deficiency d =
      momentumDeficiency(rmsProfile(dry, wet, o.min_area_fraction),
                         rmsProfile(wet, dry, o.min_area_fraction), select, o.min_rms);
  if (d.phases_used == 0) return {};
  return {d.mean, d.std_dev};
}

}  // namespace granwave
