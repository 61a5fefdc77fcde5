#include "studies/wave_analysis/VelocityFronts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "coarse_grain/ImpactFrontTracker.hpp"
#include "studies/wave_analysis/ImpactFronts.hpp"

namespace granwave {

namespace {

// An episode counts when the bootstrap (if any) finds it in at least half of its resamples;
// `counted[k]` gets episode k's speed, or stays invalid.
VelocityFronts summarise(const std::vector<TrackedFront>& fronts,
                         std::vector<Measurement>* counted = nullptr) {
  VelocityFronts v;
  std::vector<Measurement> speeds, jumps;
  if (counted) counted->assign(fronts.size(), Measurement{});
  for (std::size_t k = 0; k < fronts.size(); ++k) {
    const TrackedFront& f = fronts[k];
    ++v.episodes;
    if (!f.resolved) {
      v.lower_bound = std::isfinite(v.lower_bound) ? std::min(v.lower_bound, f.speed_lower_bound)
                                                   : f.speed_lower_bound;
      continue;
    }
    if (std::isfinite(f.bootstrap_found) && f.bootstrap_found < 0.5) continue;
    ++v.resolved;
    const double boot = std::isfinite(f.bootstrap_error) ? f.bootstrap_error : 0.0;
    const double fit = std::isfinite(f.fit_error) ? f.fit_error : 0.0;
    speeds.push_back({f.speed, std::hypot(boot, fit)});
    if (counted) (*counted)[k] = speeds.back();
    if (std::isfinite(f.jump_speed)) jumps.push_back({f.jump_speed, f.jump_speed_spread});
  }
  v.speed = combine(speeds);
  v.jump_speed = combine(jumps);
  if (v.speed.valid()) return v;
  if (v.episodes == 0)
    v.why_none = "no impact front: no velocity jump of 0.2 m/s rises from the layer's bottom";
  else if (std::isfinite(v.lower_bound))
    v.why_none = fmt::format("faster than the sampling resolves (> {:.1f} m/s)", v.lower_bound);
  else
    v.why_none = "the front is not found in half of the bootstrap resamples";
  return v;
}

}  // namespace

VelocityFronts velocityFronts(const FieldsRecord& r) {
  const PhaseProfiles& p = r.profiles;
  const double dt = r.cycles_per_window / (r.context.frequency * p.phases());
  const FrontProfiles pooled = frontProfiles(p.pooled, p.z);
  std::vector<FrontProfiles> blocks;
  for (const PhaseFields& b : p.blocks) blocks.push_back(frontProfiles(b, p.z));
  const std::vector<TrackedFront> tracked = trackWithBootstrap(pooled, blocks, dt);
  std::vector<Measurement> counted;
  VelocityFronts v = summarise(tracked, &counted);
  // Weak and strong: the T~g-peak impact fronts as ImpactFronts ranks them, each matched to
  // the velocity-jump episode that starts nearest, within 3 phases (the bootstrap's matching
  // rule); an unmatched, unresolved or dropped episode leaves it invalid.
  const ImpactFronts ranked = impactFronts(p);
  if (ranked.count == 0) return v;
  std::vector<int> starts;
  for (const TrackedFront& f : tracked) starts.push_back(f.first_phase);
  auto matched = [&](int phase) {
    const int k = nearestEpisode(starts, phase, p.phases(), 3);
    return k < 0 ? Measurement{} : counted[static_cast<std::size_t>(k)];
  };
  v.weak = matched(ranked.weak_phase);
  v.strong = matched(ranked.strong_phase);
  return v;
}

int nearestEpisode(const std::vector<int>& starts, int phase, int phases, int within) {
  int best = -1, nearest = within + 1;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    const int apart = ((starts[k] - phase) % phases + phases) % phases;
    const int gap = std::min(apart, phases - apart);
    if (gap < nearest) {
      nearest = gap;
      best = static_cast<int>(k);
    }
  }
  return best;
}

VelocityFronts velocityFronts(const PhaseProfiles& p, double phase_dt) {
  return summarise(trackFronts(frontProfiles(p.pooled, p.z), phase_dt));
}

VelocityFronts combineVelocityFronts(const std::vector<VelocityFronts>& seeds) {
  VelocityFronts v;
  std::vector<Measurement> speeds, jumps, weak, strong;
  for (const VelocityFronts& s : seeds) {
    weak.push_back(s.weak);
    strong.push_back(s.strong);
    v.episodes += s.episodes;
    v.resolved += s.resolved;
    speeds.push_back(s.speed);
    jumps.push_back(s.jump_speed);
    if (std::isfinite(s.lower_bound))
      v.lower_bound =
          std::isfinite(v.lower_bound) ? std::min(v.lower_bound, s.lower_bound) : s.lower_bound;
    if (!s.why_none.empty() && v.why_none.empty()) v.why_none = s.why_none;
  }
  v.speed = combine(speeds);
  v.jump_speed = combine(jumps);
  v.weak = combine(weak);
  v.strong = combine(strong);
  if (v.speed.valid()) v.why_none.clear();
  return v;
}

}  // namespace granwave
