// A single completely inelastic ball on a sinusoidally vibrated plate (Mehta & Luck 1990;
// Melo et al. 1994): it rests on the plate until the plate's acceleration falls
// below -g (sin(w t) = 1/Gamma), flies freely, lands with zero rebound and rests again.
// Period 1 below Gamma = sqrt(pi^2 + 4) = 3.7242, period 2 from there to 6.5938.
//
// The expected landing phases are computed here by an independent map (dense scan plus
// bisection, no code shared with the engine) and compared with the engine's wall impacts,
// located to one record (1/1000 of a cycle). The container is made tall (0.5 m) so the
// ball never reaches the lid, as the map assumes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "EngineTestSupport.hpp"
#include "coarse_grain/PeriodDetector.hpp"

using namespace granwave;

namespace {
constexpr double kG = 9.81, kF = 10.0;
constexpr int kM = 1000;

// Landing phases (in cycles, mod 1) of the steady orbit of the completely inelastic ball.
std::vector<double> mapLandingPhases(double gamma, int cycles) {
  const double w = 2 * std::numbers::pi * kF, A = gamma * kG / (w * w);
  auto zb = [&](double t) { return A * std::sin(w * t); };
  auto vb = [&](double t) { return A * w * std::cos(w * t); };
  const double phi_off = std::asin(1.0 / gamma);
  std::vector<double> landings;
  double t_off = phi_off / w;
  for (int k = 0; k < cycles; ++k) {
    const double z0 = zb(t_off), v0 = vb(t_off);
    auto gap = [&](double t) {
      const double tau = t - t_off;
      return z0 + v0 * tau - 0.5 * kG * tau * tau - zb(t);
    };
    // dense scan for the first sign change after take-off, then bisection
    const double dt = 1e-6;
    double t = t_off + dt;
    while (gap(t) > 0) t += dt;
    double lo = t - dt, hi = t;
    for (int it = 0; it < 100; ++it) {
      const double mid = 0.5 * (lo + hi);
      (gap(mid) > 0 ? lo : hi) = mid;
    }
    const double t_land = hi;
    landings.push_back(std::fmod(t_land * kF, 1.0));
    // It rests (plate pushes: sin < 1/Gamma) until the next take-off phase; if the plate
    // already pulls away faster than g it leaves at once.
    const double s = std::sin(w * t_land);
    if (s < 1.0 / gamma) {
      const double two_pi = 2 * std::numbers::pi;
      t_off = (phi_off + two_pi * std::ceil((w * t_land - phi_off) / two_pi)) / w;
    } else {
      t_off = t_land;
    }
  }
  return landings;
}

struct Trajectory : SnapshotObserver {
  std::vector<double> height;
  std::vector<double> impact_phases;  // record interval in which the wall count rose
  std::uint64_t walls = 0;
  void observe(const Snapshot& s) override {
    height.push_back(s.z[0]);
    if (s.obs.collisions.wall != walls && s.step > 0)
      impact_phases.push_back(std::fmod((static_cast<double>(s.step) - 0.5) / kM, 1.0));
    walls = s.obs.collisions.wall;
  }
};

struct BallRun {
  std::vector<double> landing_phases;  // of the last cycles
  int period = 0;
};

BallRun runBall(double gamma, double duration) {
  Scene s;
  s.particles.count = 1;
  s.container.height = 0.5;
  s.drive.gamma = gamma;
  s.contact.restitution = RestitutionKind::Constant;
  s.contact.e = 0.0;
  s.contact.friction = 0.0;
  s.contact.tc_enabled = false;
  s.run.duration = duration;
  s.run.phases_per_cycle = kM;
  const EngineConfig c = engineConfig(s);
  InitialCondition ic;
  ic.x = {0.03};
  ic.z = {0.001};
  ic.vx = {0};
  ic.vz = {c.plate.velocity(0)};
  EdSimulation sim(c, ic);
  Trajectory tr;
  sim.addObserver(&tr);
  sim.run();
  BallRun r;
  r.landing_phases = tr.impact_phases;
  r.period = detectPeriod(tr.height, 6, {kM}).period;
  return r;
}

double phaseDistance(double a, double b) {
  const double d = std::abs(a - b);
  return std::min(d, 1.0 - d);
}
}  // namespace

class BouncingBall : public ::testing::TestWithParam<std::pair<double, int>> {};

TEST_P(BouncingBall, FollowsTheCompletelyInelasticBouncingBallMap) {
  const auto [gamma, expected_period] = GetParam();
  const BallRun run = runBall(gamma, 4.0);  // 40 cycles
  EXPECT_EQ(run.period, expected_period) << "Gamma = " << gamma;
  const std::vector<double> map = mapLandingPhases(gamma, 60);
  ASSERT_GE(run.landing_phases.size(), 6u);
  // The last landings of the engine must each match one of the map's steady landings.
  for (std::size_t k = run.landing_phases.size() - 4; k < run.landing_phases.size(); ++k) {
    double best = 1.0;
    for (std::size_t j = map.size() - 4; j < map.size(); ++j)
      best = std::min(best, phaseDistance(run.landing_phases[k], map[j]));
    EXPECT_LT(best, 1.0 / kM) << "Gamma = " << gamma << ", landing " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(PeriodOneBelowDoubling, BouncingBall,
                         ::testing::Values(std::pair{2.5, 1}, std::pair{3.0, 1}, std::pair{3.5, 1},
                                           std::pair{3.6, 1}));
INSTANTIATE_TEST_SUITE_P(PeriodTwoUpTo6p59, BouncingBall,
                         ::testing::Values(std::pair{3.9, 2}, std::pair{4.0, 2}, std::pair{5.0, 2},
                                           std::pair{6.0, 2}, std::pair{6.5, 2}));
// Beyond the second doubling (6.5938) the orbit has period 4.
INSTANTIATE_TEST_SUITE_P(PeriodFourBeyond6p59, BouncingBall, ::testing::Values(std::pair{6.65, 4}));
