#pragma once
// First time a gap closes while closing, for gaps that are not polynomials in time.
//
// A gap h(t) (distance of a sphere to a vibrating wall, or of two spheres when one of them
// rides a vibrating wall) has a bounded curvature from below, h'' >= -H. From any t0,
//   h(t0 + s) >= h0 + h0' s - H s^2 / 2,
// so h has no root before the positive root s* of that parabola: stepping by s* can never
// skip a root (docs/physics.md, "Event-driven dynamics"). Near a root with h' < 0 the steps
// converge quadratically; at a grazing approach they stay finite (s ~ sqrt(2 h / H)).
// Returns the first t in [t0, horizon] with h <= tol and h' < 0, or +inf if there is none
// before the horizon. A touching gap whose rate is at or above zero is not a collision.
// If max_steps runs out, the time reached is returned: callers re-check the gap when the
// event comes due and re-predict if it is not closing, so an early return is never wrong.
#include <cmath>
#include <limits>

namespace granwave {

struct GapRate {
  double h;     // gap, m
  double rate;  // dh/dt, m/s
};

struct GapRootOptions {
  double tolerance = 1e-13;   // m: the gap counts as closed below this
  double rate_tolerance = 0;  // m/s: closing slower than this is round-off, not a collision
  int max_steps = 10000;      // safety net; hitting it means the horizon is far too long
};

// `first` is gap(t0), when the caller already has it (saves an evaluation of the gap,
// which for a vibrating wall costs a sin and a cos).
template <class Gap>
double firstClosingRoot(const Gap& gap, double curvature_bound, double t0, double horizon,
                        const GapRootOptions& opt, const GapRate& first) {
  constexpr double kNever = std::numeric_limits<double>::infinity();
  const double H = curvature_bound;
  double t = t0;
  for (int step = 0; step < opt.max_steps && t <= horizon; ++step) {
    const GapRate g = step == 0 ? first : gap(t);
    if (g.h <= opt.tolerance) {
      if (g.rate < -opt.rate_tolerance) return t;
      // Touching and opening (or stationary): step past the contact. The parabola through
      // h = 0 with rate r returns to zero after 2r/H; never less than the time to cover tol.
      const double s =
          H > 0 ? std::max(2.0 * g.rate / H, std::sqrt(2.0 * opt.tolerance / H)) : kNever;
      t += s;
      continue;
    }
    double s;
    if (H > 0.0) {
      s = (g.rate + std::sqrt(g.rate * g.rate + 2.0 * H * g.h)) / H;
    } else {
      if (g.rate >= 0.0) return kNever;
      s = g.h / -g.rate;
    }
    t += s;
  }
  return t <= horizon ? t : kNever;
}

template <class Gap>
double firstClosingRoot(const Gap& gap, double curvature_bound, double t0, double horizon,
                        const GapRootOptions& opt = {}) {
  return firstClosingRoot(gap, curvature_bound, t0, horizon, opt, gap(t0));
}

}  // namespace granwave
