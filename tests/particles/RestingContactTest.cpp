// Resting contacts (docs/physics.md, "Resting contacts"): a particle that would bounce back
// within the TC time comes to rest, a resting layer keeps its energy exactly, and a layer
// carried by a gently shaken plate costs a fixed number of events per cycle.
#include <gtest/gtest.h>

#include <cmath>

#include "EngineTestSupport.hpp"
#include "particles/CellGrid.hpp"

using namespace granwave;

namespace {

// One dry particle, TC model on (t_c = 9.2 us, the paper's "auto"), plate at rest.
Scene stillPlate(int n, double duration) {
  Scene s;
  s.particles.count = n;
  s.drive.frequency = 0;
  s.drive.gamma.reset();
  s.contact.restitution = RestitutionKind::Dry;
  s.run.duration = duration;
  return s;
}

}  // namespace

TEST(RestingContact, DryBallDroppedOnStillPlateWithTcComesToRest) {
  // With the TC model on, a ball whose bounce would bring it back within t_c
  // (separation speed below g t_c / 2 = 45 um/s) is in enduring contact with the plate: it
  // rests. Without that rule it hovered at about that speed, bouncing elastically (TC) every
  // t_c, 10^5 collisions a second, forever. Dropped from 1 mm, e_dry(v) = 1 - 0.1 v^(1/5)
  // takes it below that speed in a few hundred bounces (e < 0.98 above 45 um/s), so 10^4
  // wall collisions in 2 s can only be exceeded by the hovering.
  const Scene s = stillPlate(1, 2.0);
  const EngineConfig c = engineConfig(s);
  InitialCondition ic;
  ic.x = {0.03};
  ic.z = {0.001 + 0.001};
  ic.vx = {0};
  ic.vz = {0};
  EdSimulation sim(c, ic);
  sim.run();
  EXPECT_EQ(sim.counters().collisions.rests, 1u);
  EXPECT_LT(sim.counters().collisions.wall, 10000u);
  const Snapshot end = sim.snapshot();
  EXPECT_EQ(end.z[0], 0.001);  // on the plate, exactly
  EXPECT_EQ(end.vz[0], 0.0);
  // Energy budget: everything lost in the bounces and the absorbed residual motion.
  const double e0 = c.mass * c.gravity * 0.002, e1 = test::totalEnergy(end.obs);
  EXPECT_NEAR(e0 - e1, end.obs.dissipated_energy, 1e-15 * e0);
}

TEST(RestingContact, RestingRowOnStillPlateKeepsItsEnergyExactly) {
  // Ten particles placed at rest on the plate (two diameters apart) ride it from t = 0: no
  // further event, and the energy, all potential, stays the same to the last bit.
  const Scene s = stillPlate(10, 20.0);
  const EngineConfig c = engineConfig(s);
  InitialCondition ic;
  for (int i = 0; i < 10; ++i) {
    ic.x.push_back(0.004 + 0.004 * i);
    ic.z.push_back(0.001);
    ic.vx.push_back(0);
    ic.vz.push_back(0);
  }
  EdSimulation sim(c, ic);
  const double e0 = test::totalEnergy(sim.snapshot().obs);
  sim.run();
  const Snapshot end = sim.snapshot();
  EXPECT_EQ(sim.counters().collisions.rests, 10u);
  EXPECT_EQ(sim.counters().events, 10u);  // the ten rests, nothing after
  EXPECT_EQ(test::totalEnergy(end.obs), e0);
  EXPECT_EQ(end.obs.dissipated_energy, 0.0);
  EXPECT_EQ(end.obs.wall_work, 0.0);
}

TEST(RestingContact, RiderOnGentlyShakenPlateCrossesEachCellBoundaryTwicePerCycle) {
  // A particle resting on a plate at Gamma = 0.5 moves as z = A sin(w t) + d/2 for ever
  // (take-off needs Gamma > 1). Every horizontal cell boundary inside (d/2 - A, d/2 + A) is
  // crossed exactly twice a cycle, and nothing else happens: the events are 2 x boundaries x
  // cycles, give or take the partial cycles at the ends.
  Scene s = stillPlate(1, 10.0);
  s.drive.frequency = 10.0;
  s.drive.gamma = 0.5;
  const EngineConfig c = engineConfig(s);
  const double A = c.plate.amplitude, w = c.plate.omega, d = c.diameter;
  InitialCondition ic;
  ic.x = {0.03};
  ic.z = {0.5 * d};
  ic.vx = {0};
  ic.vz = {A * w};  // the plate's velocity at t = 0
  EdSimulation sim(c, ic);
  sim.run();
  const double span = c.height + 2 * A;
  const int nz = cellsAlong(span, d);
  int boundaries = 0;
  for (int k = 1; k < nz; ++k) {
    const double zk = -A + k * span / nz;
    if (std::abs(zk - 0.5 * d) < A) ++boundaries;
  }
  ASSERT_GT(boundaries, 0);
  const double expected = 2.0 * boundaries * 100 + 1;  // 100 cycles, plus the rest at t = 0
  EXPECT_EQ(sim.counters().collisions.rests, 1u);
  EXPECT_NEAR(static_cast<double>(sim.counters().events), expected, 2.0 * boundaries);
  EXPECT_NEAR(sim.snapshot().z[0] - sim.snapshot().plate_height, 0.5 * d, 1e-12);
}
