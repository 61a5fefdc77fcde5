// Prediction and execution agree on what a collision is (docs/physics.md, "Resting contacts",
// item 4): a pair the execution would find not approaching is not predicted to collide.
#include <gtest/gtest.h>

#include "EngineTestSupport.hpp"

using namespace granwave;

TEST(EventPrediction, TouchingFlyersClosingByRoundOffAreNotCollidedAgainAndAgain) {
  // Two dry particles falling side by side, as met in paper-dry at Gamma = 1.2, seed 3,
  // t = 4.6297 s (the state copied to the last digit): d apart horizontally, 9e-11 m apart
  // vertically, so their gap is of round-off (~1e-18 m), closing at 2.05e-10 m/s, just below
  // the round-off tolerance of an approach, 1e-9 x (sum of speeds + sqrt(g d)) = 2.1e-10 m/s.
  // The engine predicted a collision after gap / speed ~ 2e-9 s, found the pair not
  // approaching, and, x having moved by less than an ulp, predicted the same again: 3.2 M
  // events in 4 simulated seconds there, here the event-rate limit within 3e-4 s. They fall
  // 34 um in 1 ms, crossing no cell boundary: no event at all.
  Scene s;
  s.particles.count = 2;
  s.drive.frequency = 0;
  s.drive.gamma.reset();
  s.contact.restitution = RestitutionKind::Dry;
  const EngineConfig c = engineConfig(s);
  InitialCondition ic;
  ic.x = {0.032999989230674355, 0.030999989230674357};
  ic.z = {0.003972712701363304, 0.0039727127914212547};
  ic.vx = {-1.9972893935559611e-10, 5.3420124875715333e-12};
  ic.vz = {-0.033985083851182943, -0.033985087053728887};
  EdSimulation sim(c, ic);
  EXPECT_NO_THROW(sim.advanceTo(1e-3));
  EXPECT_EQ(sim.counters().collisions.pair, 0u);
  EXPECT_LT(sim.counters().events, 10u);
}
