// Energy bookkeeping. (1) An elastic periodic gas conserves kinetic energy to round-off
// over a million collisions (collisions are exact: only round-off can change E).
// (2) In driven runs the recorded observables close the budget
//     E(t) - E(0) = W_walls(t) - D(t)
// to round-off, for the dry and wet laws with friction: every energy change is accounted
// for by the walls' work or the collisions' dissipation.
#include <gtest/gtest.h>

#include "EngineTestSupport.hpp"

using namespace granwave;

TEST(EnergyConservation, ElasticPeriodicGasKeepsKineticEnergyToRoundOff) {
  const Scene s = test::periodicGas(1000, 0.3, 1e-6, 1.0);
  EdSimulation sim = test::makeSimulation(s);
  const double e0 = sim.snapshot().obs.kinetic_energy;
  double t = 0;
  while (sim.counters().collisions.pair < 1'000'000) {
    t += 0.01;
    sim.advanceTo(t);
  }
  const double e1 = sim.snapshot().obs.kinetic_energy;
  EXPECT_NEAR(e1 / e0, 1.0, 1e-10);
  EXPECT_NEAR(sim.counters().dissipated_energy, 0.0, 1e-10 * e0);  // round-off only
}

class EnergyBudget : public ::testing::TestWithParam<RestitutionKind> {};

TEST_P(EnergyBudget, WallWorkMinusDissipationEqualsEnergyChange) {
  Scene s = test::paperScene(GetParam(), 2.0);
  EdSimulation sim = test::makeSimulation(s);
  const Observables o0 = sim.snapshot().obs;
  sim.advanceTo(2.0);
  const Observables o1 = sim.snapshot().obs;
  const double lhs = test::totalEnergy(o1) - test::totalEnergy(o0);
  const double rhs = o1.wall_work - o1.dissipated_energy;
  // Round-off: ~1e-16 relative per event on energies of order W.
  EXPECT_NEAR(lhs, rhs, 1e-9 * o1.wall_work);
  EXPECT_GT(o1.dissipated_energy, 0.0);
  EXPECT_GT(o1.wall_work, 0.0);
}

INSTANTIATE_TEST_SUITE_P(AllLaws, EnergyBudget,
                         ::testing::Values(RestitutionKind::Dry, RestitutionKind::Wet,
                                           RestitutionKind::Constant));

TEST(EnergyBudget, WallShareIsAllOfTheLossOfGrainsThatMeetOnlyTheWalls) {
  // Four grains in a box 30 d wide on the driven plate: until two of them meet, every loss is
  // a wall collision or a come-to-rest on the plate, so the wall share equals the whole
  // dissipation (round-off only); once they meet, the pair share is the rest and positive.
  Scene s = test::paperScene(RestitutionKind::Dry, 0.5);
  s.particles.count = 4;
  s.initial.placement = InitialPlacement::Lattice;
  EdSimulation sim = test::makeSimulation(s);
  double t = 0;
  while (sim.counters().collisions.pair == 0 && t < 0.5) {
    t += 1e-3;
    sim.advanceTo(t);
    const Observables o = sim.snapshot().obs;
    if (o.collisions.pair > 0) break;
    ASSERT_NEAR(o.wall_dissipated_energy, o.dissipated_energy, 1e-12 * o.wall_work + 1e-30);
  }
  EXPECT_GT(sim.snapshot().obs.wall_dissipated_energy, 0.0);
}

TEST_P(EnergyBudget, WallAndPairSharesSplitTheDissipation) {
  // On the paper's scene both shares are positive and the wall share is part of the whole;
  // the pair collisions' normal loss (the restitution law's, TC-elastic ones excluded) is part
  // of what the wall share leaves: the rest is friction and rotation.
  Scene s = test::paperScene(GetParam(), 2.0);
  EdSimulation sim = test::makeSimulation(s);
  sim.advanceTo(2.0);
  const Observables o = sim.snapshot().obs;
  EXPECT_GT(o.wall_dissipated_energy, 0.0);
  EXPECT_LT(o.wall_dissipated_energy, o.dissipated_energy);
  EXPECT_LE(o.pair_impact_loss, (o.dissipated_energy - o.wall_dissipated_energy) * (1 + 1e-9));
}
