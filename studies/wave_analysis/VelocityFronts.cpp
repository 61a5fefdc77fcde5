#include "studies/wave_analysis/VelocityFronts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "coarse_grain/FrontTransit.hpp"
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

// Transit speeds of every resample of every episode, per pair of fractions.
using ResampledTransits = std::vector<std::array<std::vector<double>, 2>>;

// The std of a front's transit over the resamples in which it was resolved; NaN when fewer
// than half of the resamples resolved it (the others, too fast or not reached, would be left
// out and the spread biased low).
double spread(const std::vector<double>& x) {
  if (2 * x.size() < static_cast<std::size_t>(kBootstrapResamples)) return NAN;
  return bootstrapSpread(x);
}

// Each episode's transits on the pooled profiles, with the std over the bootstrap's resamples
// when there are any. A resolved episode the bootstrap finds in fewer than half of its
// resamples is left out, as for the fitted speed; one too fast for a fit (whose bootstrap
// share says nothing of it) still gives its transits' bounds. Without resamples (the
// continuum, deterministic) the transits of the run's fronts (two at period 2) are averaged
// with no statistical error: their difference is the two impacts', not noise.
void addTransits(VelocityFronts& v, const FrontProfiles& p, const std::vector<TrackedFront>& fronts,
                 double dt, const ResampledTransits* resampled = nullptr) {
  for (int i = 0; i < 2; ++i) {
    TransitSpeeds& t = v.transit[i];
    std::vector<Measurement> speeds;
    for (std::size_t e = 0; e < fronts.size(); ++e) {
      const TrackedFront& f = fronts[e];
      if (f.resolved && std::isfinite(f.bootstrap_found) && f.bootstrap_found < 0.5) continue;
      ++t.fronts;
      const FrontTransit x =
          frontTransit(p, f, dt, kReportedFractions[i], kReportedFractions[i + 1]);
      if (!x.reached) continue;
      ++t.reached;
      if (!x.resolved) {
        t.lower_bound = std::isfinite(t.lower_bound) ? std::min(t.lower_bound, x.speed_lower_bound)
                                                     : x.speed_lower_bound;
        continue;
      }
      ++t.resolved;
      speeds.push_back({x.speed, resampled ? spread((*resampled)[e][i]) : NAN});
    }
    t.speed = combine(speeds);
    if (!resampled) t.speed.error = NAN;
  }
}

// Combined over seeds: resolved transits by granwave::combine, bounds by their smallest.
TransitSpeeds combineTransits(const std::vector<TransitSpeeds>& seeds) {
  TransitSpeeds t;
  std::vector<Measurement> speeds;
  for (const TransitSpeeds& s : seeds) {
    t.fronts += s.fronts;
    t.reached += s.reached;
    t.resolved += s.resolved;
    speeds.push_back(s.speed);
    if (std::isfinite(s.lower_bound))
      t.lower_bound =
          std::isfinite(t.lower_bound) ? std::min(t.lower_bound, s.lower_bound) : s.lower_bound;
  }
  t.speed = combine(speeds);
  return t;
}

}  // namespace

std::string transitCell(const TransitSpeeds& t) {
  if (t.speed.valid() && std::isfinite(t.lower_bound))
    return fmt::format("{}; another front > {:.1f}", format(t.speed), t.lower_bound);
  if (t.speed.valid()) return format(t.speed);
  if (std::isfinite(t.lower_bound))
    return fmt::format("> {:.1f} (within fewer phases than a speed needs)", t.lower_bound);
  if (t.fronts == 0) return "no front";
  return "not reached: the fronts stop below these fractions of the mass";
}

VelocityFronts velocityFronts(const FieldsRecord& r) {
  const PhaseProfiles& p = r.profiles;
  const double dt = r.cycles_per_window / (r.context.frequency * p.phases());
  const FrontProfiles pooled = frontProfiles(p.pooled, p.z);
  std::vector<FrontProfiles> blocks;
  for (const PhaseFields& b : p.blocks) blocks.push_back(frontProfiles(b, p.z));
  ResampledTransits resampled;
  auto visit = [&](const FrontProfiles& q, std::size_t e, const TrackedFront& f) {
    if (resampled.size() <= e) resampled.resize(e + 1);
    for (int i = 0; i < 2; ++i) {
      const FrontTransit x =
          frontTransit(q, f, dt, kReportedFractions[i], kReportedFractions[i + 1]);
      if (x.resolved) resampled[e][static_cast<std::size_t>(i)].push_back(x.speed);
    }
  };
  const std::vector<TrackedFront> tracked = trackWithBootstrap(
      pooled, blocks, dt, FrontTrackOptions{}, kBootstrapResamples, kBootstrapSeed, visit);
  resampled.resize(tracked.size());
  std::vector<Measurement> counted;
  VelocityFronts v = summarise(tracked, &counted);
  addTransits(v, pooled, tracked, dt, &resampled);
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
  const FrontProfiles pooled = frontProfiles(p.pooled, p.z);
  const std::vector<TrackedFront> tracked = trackFronts(pooled, phase_dt);
  VelocityFronts v = summarise(tracked);
  addTransits(v, pooled, tracked, phase_dt);
  return v;
}

VelocityFronts combineVelocityFronts(const std::vector<VelocityFronts>& seeds) {
  VelocityFronts v;
  std::vector<Measurement> speeds, jumps, weak, strong;
  std::vector<TransitSpeeds> transits[2];
  for (const VelocityFronts& s : seeds) {
    for (int i = 0; i < 2; ++i) transits[i].push_back(s.transit[i]);
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
  for (int i = 0; i < 2; ++i) v.transit[i] = combineTransits(transits[i]);
  if (v.speed.valid()) v.why_none.clear();
  return v;
}

}  // namespace granwave
