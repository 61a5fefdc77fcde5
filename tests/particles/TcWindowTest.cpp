// The two readings of the paper's TC rule, "only the first collision of each particle within
// this time scale is inelastic", on a crafted collision sequence: one sphere flying without
// gravity between the side walls of a box, hitting a wall every 0.6 t_c / (speed / v0), with
// e_n = 0.9. Hit times (in t_c): 0.3, then 2/3 t_c apart at speed 0.9 v0, and so on.
//   rolling (window restarts at every collision): hit 1 inelastic, every later hit comes
//     less than t_c after the previous one, so it is elastic: 1 loss, v = 0.9 v0;
//   anchored (window opens at the first collision after the last one closed): hits at
//     0.3 (inelastic), 0.967 (elastic), 1.633 (inelastic, 1.33 t_c after 0.3), 2.374
//     (elastic), 3.115 (inelastic): 3 losses, v = 0.729 v0.
#include <gtest/gtest.h>

#include <cmath>

#include "particles/EdSimulation.hpp"

using namespace granwave;

namespace {
constexpr double kTc = 0.01, kD = 0.002, kWidth = 0.02, kV0 = (kWidth - kD) / (0.6 * kTc);

struct Outcome {
  double speed = 0;
  std::uint64_t wall = 0, tc_elastic = 0;
};

Outcome flyBetweenSideWalls(TcWindowRule window) {
  EngineConfig c;
  c.diameter = kD;
  c.mass = 1e-5;
  c.gravity = 0;
  c.width = kWidth;
  c.height = kWidth;
  c.restitution = Restitution::constant(0.9);
  c.tc = kTc;
  c.tc_window = window;
  c.duration = 3.5 * kTc;
  c.record_interval = 0.1 * kTc;
  InitialCondition ic;
  ic.x = {0.5 * kWidth};
  ic.z = {0.5 * kWidth};
  ic.vx = {kV0};
  ic.vz = {0};
  ic.omega = {0};
  EdSimulation sim(c, ic);
  sim.run();
  const Snapshot s = sim.snapshot();
  return {std::abs(s.vx[0]), sim.counters().collisions.wall, sim.counters().collisions.tc_elastic};
}
}  // namespace

TEST(TcWindow, RollingWindowMakesEveryHitWithinTcOfTheLastOneElastic) {
  const Outcome o = flyBetweenSideWalls(TcWindowRule::Rolling);
  EXPECT_EQ(o.wall, 5u);
  EXPECT_EQ(o.tc_elastic, 4u);
  EXPECT_NEAR(o.speed, 0.9 * kV0, 1e-12);
}

TEST(TcWindow, AnchoredWindowAllowsOneDissipativeHitPerTc) {
  const Outcome o = flyBetweenSideWalls(TcWindowRule::Anchored);
  EXPECT_EQ(o.wall, 5u);
  EXPECT_EQ(o.tc_elastic, 2u);
  EXPECT_NEAR(o.speed, 0.729 * kV0, 1e-12);
}
