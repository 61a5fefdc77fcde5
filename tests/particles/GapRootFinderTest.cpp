// First closing root of a gap with bounded curvature: the moving-wall root finder
// (docs/physics.md, "Event-driven dynamics"). Expected values come from closed forms or from
// a dense brute-force scan, never from the finder itself.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "particles/GapRootFinder.hpp"
#include "particles/PlateMotion.hpp"

using namespace granwave;

namespace {
// A ball (centre height z0, velocity v0 at t0) above a plate z_b = A sin(w t), radius r.
struct BallOverPlate {
  double z0, v0, t0, g, r;
  PlateMotion plate;
  GapRate operator()(double t) const {
    const double tau = t - t0;
    return {z0 + v0 * tau - 0.5 * g * tau * tau - r - plate.height(t),
            v0 - g * tau - plate.velocity(t)};
  }
  double curvature() const { return g + plate.maxAcceleration(); }
};

// Brute force: first sign change of h on a fine grid, refined by bisection.
double scanFirstRoot(const BallOverPlate& b, double t0, double t1, int n) {
  double prev = b(t0).h;
  for (int k = 1; k <= n; ++k) {
    const double t = t0 + (t1 - t0) * k / n;
    const double h = b(t).h;
    if (prev > 0 && h <= 0) {
      double lo = t - (t1 - t0) / n, hi = t;
      for (int it = 0; it < 200; ++it) {
        const double mid = 0.5 * (lo + hi);
        (b(mid).h > 0 ? lo : hi) = mid;
      }
      return hi;
    }
    prev = h;
  }
  return std::numeric_limits<double>::infinity();
}
}  // namespace

TEST(GapRootFinder, FreeFallOntoFixedFloorMatchesClosedForm) {
  // Fixed floor (A = 0): h = 0.01 - g t^2 / 2 closes at sqrt(0.02 / g).
  BallOverPlate b{0.011, 0.0, 0.0, 9.81, 0.001, {0.0, 0.0}};
  const double t = firstClosingRoot(b, b.curvature(), 0.0, 1.0);
  EXPECT_NEAR(t, std::sqrt(0.02 / 9.81), 1e-12);
}

TEST(GapRootFinder, BallOnVibratingPlateMatchesDenseScan) {
  const double w = 2 * std::numbers::pi * 10;
  for (int k = 0; k < 40; ++k) {
    // Various launch heights and speeds, Gamma = 4.
    BallOverPlate b{0.002 + 0.0005 * k,     0.3 - 0.02 * k, 0.013 * k, 9.81, 0.001,
                    {4 * 9.81 / (w * w), w}};
    if (b(b.t0).h <= 0) continue;
    const double expected = scanFirstRoot(b, b.t0, b.t0 + 0.5, 200000);
    const double got = firstClosingRoot(b, b.curvature(), b.t0, b.t0 + 0.5);
    EXPECT_NEAR(got, expected, 1e-9) << "case " << k;
    EXPECT_LT(b(got).rate, 0.0);
  }
}

TEST(GapRootFinder, GrazingApproachThatMissesIsNotAContact) {
  // h(t) = 1e-9 + (t - 1)^2 with curvature 2: closest approach 1 nm, no root.
  auto gap = [](double t) { return GapRate{1e-9 + (t - 1) * (t - 1), 2 * (t - 1)}; };
  EXPECT_EQ(firstClosingRoot(gap, 2.0, 0.0, 3.0), std::numeric_limits<double>::infinity());
}

TEST(GapRootFinder, GrazingApproachThatTouchesIsFound) {
  // h(t) = (t - 1)^2 - 1e-10: roots at 1 -+ 1e-5; the first is found, not skipped.
  auto gap = [](double t) { return GapRate{(t - 1) * (t - 1) - 1e-10, 2 * (t - 1)}; };
  EXPECT_NEAR(firstClosingRoot(gap, 2.0, 0.0, 3.0, {1e-15}), 1.0 - 1e-5, 1e-9);
}

TEST(GapRootFinder, NeverSkipsTheFirstOfTwoCloseRoots) {
  // A fast oscillation dips below zero briefly before a later, deeper dip.
  const double w = 200.0;
  auto gap = [&](double t) {
    return GapRate{0.001 + 0.0011 * std::sin(w * t), 0.0011 * w * std::cos(w * t)};
  };
  const double curvature = 0.0011 * w * w;
  const double t = firstClosingRoot(gap, curvature, 0.0, 1.0, {1e-14});
  // First root of sin(w t) = -0.001/0.0011 on the descending branch.
  const double expected = (std::numbers::pi + std::asin(0.001 / 0.0011)) / w;
  EXPECT_NEAR(t, expected, 1e-10);
}

TEST(GapRootFinder, OpeningContactIsNotACollision) {
  // Touching and separating (h = 0, h' > 0), then flying away: no root.
  auto gap = [](double t) { return GapRate{t, 1.0}; };
  EXPECT_EQ(firstClosingRoot(gap, 1.0, 0.0, 5.0), std::numeric_limits<double>::infinity());
}
