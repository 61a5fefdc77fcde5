#include "coarse_grain/ImpactFrontTracker.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "coarse_grain/LineFit.hpp"

namespace granwave {

namespace {

constexpr double kNaNValue = std::numeric_limits<double>::quiet_NaN();

bool finite(double v) { return std::isfinite(v); }

// A relative density jump smaller than this leaves the Rankine-Hugoniot speed undetermined.
constexpr double kMinDensityJump = 0.02;

double jumpSpeed(const FrontProfiles& p, int ph, int behind, int ahead) {
  const double rb = p.at(p.density, ph, behind), ra = p.at(p.density, ph, ahead);
  const double vb = p.at(p.velocity, ph, behind), va = p.at(p.velocity, ph, ahead);
  if (!finite(rb) || !finite(ra) || !finite(vb) || !finite(va)) return kNaNValue;
  if (std::abs(rb - ra) < kMinDensityJump * std::max(rb, ra)) return kNaNValue;
  return (rb * vb - ra * va) / (rb - ra);
}

// The downward crossing of `mid` between rows jb and ja with the largest drop over two rows
// either side; -1 if none.
int bestCrossing(const FrontProfiles& p, int ph, int jb, int ja, double mid) {
  int best = -1;
  double best_drop = -1;
  for (int k = jb; k < ja; ++k) {
    const double v0 = p.at(p.velocity, ph, k), v1 = p.at(p.velocity, ph, k + 1);
    if (!finite(v0) || !finite(v1) || !(v0 >= mid && v1 < mid)) continue;
    const double below = p.at(p.velocity, ph, std::max(k - 1, jb));
    const double above = p.at(p.velocity, ph, std::min(k + 2, ja));
    const double drop = (finite(below) ? below : v0) - (finite(above) ? above : v1);
    if (drop > best_drop) {
      best_drop = drop;
      best = k;
    }
  }
  return best;
}

}  // namespace

FrontProfiles frontProfiles(const PhaseFields& fields, const std::vector<double>& z) {
  FrontProfiles f;
  f.phases = fields.phases;
  f.nz = fields.nz;
  f.z = z;
  f.density = fields.profile_area_fraction;
  f.velocity = fields.profile_velocity_z;
  return f;
}

FrontCrossing locateFront(const FrontProfiles& p, int ph, const FrontTrackOptions& o) {
  FrontCrossing c;
  int lo = -1, hi = -1, jb = -1;
  for (int j = 0; j < p.nz; ++j) {
    const double rho = p.at(p.density, ph, j), v = p.at(p.velocity, ph, j);
    if (!(rho >= o.min_density) || !finite(v)) continue;
    if (lo < 0) lo = j;
    hi = j;
    if (jb < 0 || v > p.at(p.velocity, ph, jb)) jb = j;
  }
  if (lo < 0 || hi - lo < 2) return c;
  int ja = -1;
  for (int j = jb + 1; j <= hi; ++j) {
    const double v = p.at(p.velocity, ph, j);
    if (p.at(p.density, ph, j) >= o.min_density && finite(v) &&
        (ja < 0 || v < p.at(p.velocity, ph, ja)))
      ja = j;
  }
  if (ja < 0) return c;
  c.velocity_behind = p.at(p.velocity, ph, jb);
  c.velocity_ahead = p.at(p.velocity, ph, ja);
  c.layer_bottom = p.height(ph, lo);
  c.layer_top = p.height(ph, hi);
  c.spacing = (c.layer_top - c.layer_bottom) / (hi - lo);
  if (c.velocity_behind - c.velocity_ahead < o.min_jump) return c;
  const double mid = 0.5 * (c.velocity_behind + c.velocity_ahead);
  const int k = bestCrossing(p, ph, jb, ja, mid);
  if (k < 0) return c;
  const double v0 = p.at(p.velocity, ph, k), v1 = p.at(p.velocity, ph, k + 1);
  c.found = true;
  c.height = p.height(ph, k) + (v0 - mid) / (v0 - v1) * (p.height(ph, k + 1) - p.height(ph, k));
  c.jump_speed =
      jumpSpeed(p, ph, std::max(lo, k - o.state_offset), std::min(hi, k + 1 + o.state_offset));
  return c;
}

namespace {

// The episode starting at phase s: consecutive phases while the front does not move down by
// more than a row spacing, up to and including the first phase within a spacing of the top.
TrackedFront episodeFrom(const std::vector<FrontCrossing>& cs, int s, double dt,
                         const FrontTrackOptions& o) {
  const int n = static_cast<int>(cs.size());
  TrackedFront e;
  e.first_phase = s;
  std::vector<double> jumps;
  for (int step = 0; step < n; ++step) {
    const FrontCrossing& c = cs[(s + step) % n];
    if (!c.found || (step > 0 && c.height < e.height.back() - c.spacing)) break;
    e.time.push_back((s + step) * dt);
    e.height.push_back(c.height);
    if (finite(c.jump_speed)) jumps.push_back(c.jump_speed);
    if (c.height >= c.layer_top - c.spacing) break;
  }
  // Phases before the front leaves the bottom (the dilute underside compacting against the
  // plate) are not propagation: the track starts at the last of them.
  std::size_t m = 0;
  while (m + 1 < e.height.size() && e.height[m + 1] < e.height.front() + cs[s].spacing) ++m;
  e.time.erase(e.time.begin(), e.time.begin() + m);
  e.height.erase(e.height.begin(), e.height.begin() + m);
  e.points = static_cast<int>(e.time.size());
  e.resolved = e.points >= o.min_points;
  e.speed = e.fit_error = e.speed_lower_bound = kNaNValue;
  if (e.resolved) {
    const LineFit fit = fitLine(e.time, e.height);
    e.speed = fit.slope;
    e.fit_error = fit.slope_error;
  } else {
    e.speed_lower_bound = (cs[s].layer_top - cs[s].layer_bottom) / ((e.points + 1) * dt);
  }
  e.jump_speed = e.jump_speed_spread = kNaNValue;
  if (!jumps.empty()) {
    double m = 0, v = 0;
    for (double j : jumps) m += j / jumps.size();
    for (double j : jumps) v += (j - m) * (j - m) / std::max<std::size_t>(1, jumps.size() - 1);
    e.jump_speed = m;
    e.jump_speed_spread = std::sqrt(v);
  }
  e.bootstrap_error = e.bootstrap_found = kNaNValue;
  return e;
}

}  // namespace

namespace {

// Whether the front first seen at phase s, high above the bottom, crossed the rows below it
// within the phase: at s every layer row below it moves at or above the front's midpoint
// velocity (behind it), and one phase before the lowest layer row was still below it (ahead).
bool crossedBelowWithinPhase(const FrontProfiles& p, const std::vector<FrontCrossing>& cs, int s,
                             const FrontTrackOptions& o) {
  const FrontCrossing& c = cs[s];
  const double mid = 0.5 * (c.velocity_behind + c.velocity_ahead);
  const int n = p.phases, before = (s + n - 1) % n;
  int lowest = -1;
  for (int j = 0; j < p.nz && p.height(s, j) < c.height; ++j) {
    const double rho = p.at(p.density, s, j), v = p.at(p.velocity, s, j);
    if (!(rho >= o.min_density) || !finite(v)) continue;
    if (v < mid) return false;
    if (lowest < 0) lowest = j;
  }
  if (lowest < 0 || n < 2) return false;
  const double v_before = p.at(p.velocity, before, lowest);
  return finite(v_before) && v_before < mid;
}

}  // namespace

std::vector<TrackedFront> trackFronts(const FrontProfiles& p, double dt,
                                      const FrontTrackOptions& o) {
  const int n = p.phases;
  std::vector<FrontCrossing> cs;
  for (int ph = 0; ph < n; ++ph) cs.push_back(locateFront(p, ph, o));
  auto continues = [&](int from, int to) {
    return cs[from].found && cs[to].found && cs[to].height >= cs[from].height - cs[to].spacing;
  };
  std::vector<TrackedFront> out;
  for (int s = 0; s < n; ++s) {
    const FrontCrossing& c = cs[s];
    if (!c.found) continue;
    if (n > 1 && continues((s + n - 1) % n, s)) continue;  // not the episode's first phase
    const bool at_bottom = c.height <= c.layer_bottom + o.impact_rows * c.spacing;
    if (!at_bottom && !crossedBelowWithinPhase(p, cs, s, o)) continue;
    TrackedFront e = episodeFrom(cs, s, dt, o);
    e.bulk_crossing = at_bottom ? 0.0 : c.height - c.layer_bottom;
    e.bulk_speed_lower_bound = at_bottom ? kNaNValue : e.bulk_crossing / dt;
    out.push_back(std::move(e));
  }
  return out;
}

namespace {

FrontProfiles blockAverage(const std::vector<FrontProfiles>& blocks, const std::vector<int>& pick) {
  FrontProfiles a = blocks.front();
  const std::size_t cells = a.density.size();
  for (std::size_t i = 0; i < cells; ++i) {
    double rho = 0, flux = 0;
    int count = 0;
    for (int b : pick) {
      const double r = blocks[b].density[i], v = blocks[b].velocity[i];
      if (!finite(r)) continue;
      rho += r;
      ++count;
      if (r > 0 && finite(v)) flux += r * v;
    }
    a.density[i] = count > 0 ? rho / count : kNaNValue;
    a.velocity[i] = rho > 0 ? flux / rho : kNaNValue;
  }
  return a;
}

int cyclicDistance(int a, int b, int n) {
  const int d = std::abs(a - b) % n;
  return std::min(d, n - d);
}

}  // namespace

std::vector<TrackedFront> trackWithBootstrap(const FrontProfiles& pooled,
                                             const std::vector<FrontProfiles>& blocks, double dt,
                                             const FrontTrackOptions& o, int resamples,
                                             std::uint64_t seed, const ResampleVisitor& visit) {
  std::vector<TrackedFront> out = trackFronts(pooled, dt, o);
  if (blocks.size() < 2 || out.empty()) return out;
  std::mt19937_64 draw(seed);
  std::vector<std::vector<double>> speeds(out.size());
  std::vector<int> pick(blocks.size());
  for (int r = 0; r < resamples; ++r) {
    for (int& b : pick) b = static_cast<int>(draw() % blocks.size());
    const FrontProfiles resampled = blockAverage(blocks, pick);
    const std::vector<TrackedFront> again = trackFronts(resampled, dt, o);
    for (std::size_t e = 0; e < out.size(); ++e) {
      const TrackedFront* match = nullptr;
      for (const TrackedFront& t : again) {
        const int d = cyclicDistance(t.first_phase, out[e].first_phase, pooled.phases);
        if (t.resolved && d <= 3 &&
            (!match || d < cyclicDistance(match->first_phase, out[e].first_phase, pooled.phases)))
          match = &t;
      }
      if (!match) continue;
      speeds[e].push_back(match->speed);
      if (visit) visit(resampled, e, *match);
    }
  }
  for (std::size_t e = 0; e < out.size(); ++e) {
    out[e].bootstrap_found = static_cast<double>(speeds[e].size()) / resamples;
    if (speeds[e].size() >= 2) out[e].bootstrap_error = bootstrapSpread(speeds[e]);
  }
  return out;
}

double bootstrapSpread(const std::vector<double>& s) {
  if (s.size() < 2) return kNaNValue;
  double m = 0, v = 0;
  for (double x : s) m += x / s.size();
  for (double x : s) v += (x - m) * (x - m) / (s.size() - 1);
  return std::sqrt(v);
}

}  // namespace granwave
