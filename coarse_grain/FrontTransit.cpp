#include "coarse_grain/FrontTransit.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace granwave {

namespace {

constexpr double kNaNValue = std::numeric_limits<double>::quiet_NaN();

double densityAt(const FrontProfiles& p, int phase, int j) {
  const double rho = p.at(p.density, phase, j);
  return std::isfinite(rho) && rho > 0 ? rho : 0.0;
}

// The trapezoidal integral of the density from the lowest height up to `height` (all of the
// profile when `height` is above it).
double massBelow(const FrontProfiles& p, int phase, double height) {
  double m = 0;
  for (int j = 0; j + 1 < p.nz; ++j) {
    const double z0 = p.height(phase, j), z1 = p.height(phase, j + 1);
    if (height <= z0) break;
    const double r0 = densityAt(p, phase, j), r1 = densityAt(p, phase, j + 1);
    if (height >= z1) {
      m += 0.5 * (r0 + r1) * (z1 - z0);
      continue;
    }
    const double s = (height - z0) / (z1 - z0);
    m += 0.5 * (r0 + (r0 + s * (r1 - r0))) * (height - z0);
    break;
  }
  return m;
}

// The track's phase index of its point k (TrackedFront::time counts phases from the window's
// start, unwrapped).
int phaseOf(const TrackedFront& f, std::size_t k, double dt, int phases) {
  return static_cast<int>(std::llround(f.time[k] / dt)) % phases;
}

// The height below which the share `x` of the layer's mass lies at a phase (the inverse of
// massFractionBelow, linear within a row interval).
double heightOfFraction(const FrontProfiles& p, int phase, double x) {
  const double total = massBelow(p, phase, std::numeric_limits<double>::infinity());
  double m = 0;
  for (int j = 0; j + 1 < p.nz; ++j) {
    const double z0 = p.height(phase, j), z1 = p.height(phase, j + 1);
    const double r0 = densityAt(p, phase, j), r1 = densityAt(p, phase, j + 1);
    const double dm = 0.5 * (r0 + r1) * (z1 - z0);
    if (dm > 0 && m + dm >= x * total) return z0 + (x * total - m) / dm * (z1 - z0);
    m += dm;
  }
  return p.height(phase, p.nz - 1);
}

}  // namespace

double massFractionBelow(const FrontProfiles& p, int phase, double height) {
  const double total = massBelow(p, phase, std::numeric_limits<double>::infinity());
  return total > 0 ? massBelow(p, phase, height) / total : kNaNValue;
}

FrontTransit frontTransit(const FrontProfiles& p, const TrackedFront& f, double dt, double from,
                          double to, const FrontTrackOptions& o) {
  if (!(from >= 0 && from < to && to <= 1))
    throw std::invalid_argument("frontTransit: mass fractions must satisfy 0 <= from < to <= 1");
  FrontTransit t;
  t.speed = t.speed_lower_bound = kNaNValue;
  std::vector<double> q;
  for (std::size_t k = 0; k < f.time.size(); ++k)
    q.push_back(massFractionBelow(p, phaseOf(f, k, dt, p.phases), f.height[k]));
  // The first tracked point at or past fraction x, and the passage interpolated before it.
  auto passage = [&](double x, double& time, double& height) -> long {
    for (std::size_t k = 0; k < q.size(); ++k) {
      if (!(q[k] >= x)) continue;
      if (k == 0) {  // passed before the track began, within the phase before its first
        time = f.time[0] - dt;
        height = heightOfFraction(p, phaseOf(f, 0, dt, p.phases), x);
        return 0;
      }
      // The previous point's share is below x (or unknown: then the passage is taken here).
      const double s = std::isfinite(q[k - 1]) ? (x - q[k - 1]) / (q[k] - q[k - 1]) : 1.0;
      time = f.time[k - 1] + s * (f.time[k] - f.time[k - 1]);
      height = f.height[k - 1] + s * (f.height[k] - f.height[k - 1]);
      return static_cast<long>(k);
    }
    return -1;
  };
  const long a = passage(from, t.from_time, t.from_height);
  const long b = passage(to, t.to_time, t.to_height);
  if (a < 0 || b < 0) return t;
  t.reached = true;
  // Tracked phases strictly inside the passage: points a .. b-1 (a first crossing at point 0
  // happened before the track, so it spans none of them at the start).
  const long inside = b - a;
  t.resolved = a > 0 && inside >= o.min_points;
  if (t.resolved)
    t.speed = (t.to_height - t.from_height) / (t.to_time - t.from_time);
  else
    t.speed_lower_bound = (t.to_height - t.from_height) / ((inside + 1) * dt);
  return t;
}

}  // namespace granwave
