#include "studies/wave_analysis/ImpactFronts.hpp"

#include <algorithm>
#include <cmath>

namespace granwave {

ImpactFronts impactFronts(const PhaseProfiles& p) {
  std::vector<const FrontEpisode*> impact;
  for (const FrontEpisode& f : p.fronts)
    if (f.from_impact && std::isfinite(f.speed)) impact.push_back(&f);
  ImpactFronts r;
  r.count = static_cast<int>(impact.size());
  if (impact.empty()) return r;
  std::sort(impact.begin(), impact.end(), [](const FrontEpisode* a, const FrontEpisode* b) {
    return a->peak_temperature < b->peak_temperature;
  });
  const FrontEpisode& weak = *impact.front();
  const FrontEpisode& strong = *impact.back();
  r.weak = {weak.speed, weak.speed_error};
  r.strong = {strong.speed, strong.speed_error};
  r.weak_start = p.start(weak);
  r.strong_start = p.start(strong);
  r.weak_phase = weak.first_phase;
  r.strong_phase = strong.first_phase;
  std::vector<Measurement> all;
  for (const FrontEpisode* f : impact) all.push_back({f->speed, f->speed_error});
  r.all = combine(all);
  return r;
}

ImpactFronts combineImpactFronts(const std::vector<ImpactFronts>& runs) {
  std::vector<Measurement> weak, strong, all;
  ImpactFronts r;
  for (const ImpactFronts& x : runs) {
    weak.push_back(x.weak);
    strong.push_back(x.strong);
    all.push_back(x.all);
    r.count += x.count;
    if (r.weak_start < 0) r.weak_start = x.weak_start;
    if (r.strong_start < 0) r.strong_start = x.strong_start;
  }
  r.weak = combine(weak);
  r.strong = combine(strong);
  r.all = combine(all);
  return r;
}

std::vector<double> centerOfMassMinimumPhases(const PhaseProfiles& p, int cycles) {
  std::vector<double> out;
  if (cycles <= 0 || p.phases() < cycles) return out;
  const int per = p.phases() / cycles;
  const std::vector<double>& com = p.pooled.center_of_mass_height;
  for (int c = 0; c < cycles; ++c) {
    int best = c * per;
    for (int k = c * per; k < (c + 1) * per; ++k)
      if (com[k] < com[best]) best = k;
    out.push_back(p.phase[best] - std::floor(p.phase[best]));
  }
  return out;
}

}  // namespace granwave
