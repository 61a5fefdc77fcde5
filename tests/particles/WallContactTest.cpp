// Moving walls: no particle is ever found outside the container over long driven runs,
// for the dry and the wet law, with friction and rough walls (docs/physics.md, "Collision rule").
#include <gtest/gtest.h>

#include "EngineTestSupport.hpp"

using namespace granwave;

namespace {
// Checks every record that all centres lie inside bottom, lid and side walls.
class ContainmentCheck : public SnapshotObserver {
 public:
  ContainmentCheck(double d, double w, double h) : d_(d), w_(w), h_(h) {}
  void observe(const Snapshot& s) override {
    const double tol = 1e-9 * d_;
    for (int i = 0; i < s.size(); ++i) {
      const double below = s.plate_height + 0.5 * d_ - s.z[i];
      const double above = s.z[i] - (s.plate_height + h_ - 0.5 * d_);
      worst = std::max({worst, below, above, 0.5 * d_ - s.x[i], s.x[i] - (w_ - 0.5 * d_)});
      if (below > tol || above > tol) ++violations;
    }
    ++records;
  }
  double worst = -1;
  int violations = 0;
  int records = 0;

 private:
  double d_, w_, h_;
};

void runContained(Scene s) {
  EdSimulation sim = test::makeSimulation(s);
  ContainmentCheck check(s.particles.diameter, s.container.width, s.container.height);
  sim.addObserver(&check);
  const RunStatus st = sim.run();
  ASSERT_TRUE(st.completed);
  EXPECT_EQ(check.violations, 0) << "worst excursion " << check.worst << " m";
  EXPECT_LT(check.worst, 1e-9 * s.particles.diameter);
  EXPECT_GT(sim.counters().collisions.wall, 1000u);
}
}  // namespace

TEST(WallContact, DryLayerStaysInsideContainerOverManyCycles) {
  runContained(test::paperScene(RestitutionKind::Dry, 3.0));
}

TEST(WallContact, WetLayerStaysInsideContainerOverManyCycles) {
  runContained(test::paperScene(RestitutionKind::Wet, 3.0));
}

TEST(WallContact, RoughWallsAndHighGammaKeepParticlesInside) {
  Scene s = test::paperScene(RestitutionKind::Dry, 2.0);
  s.contact.wall_tangential = ContactTangential::Coulomb;
  s.drive.gamma = 7.0;  // the lid is hit too
  runContained(s);
}

TEST(WallContact, RestingBallRidesPlateBelowOneGAndNeverLeaves) {
  // Gamma < 1: the plate never pulls away faster than g, so a ball at rest on it stays
  // on it (Mehta & Luck: take-off needs Gamma > 1).
  Scene s;
  s.particles.count = 1;
  s.drive.gamma = 0.8;
  s.contact.restitution = RestitutionKind::Constant;
  s.contact.e = 0.0;
  s.contact.tc_enabled = false;
  s.run.duration = 2.0;
  const EngineConfig c = engineConfig(s);
  InitialCondition ic;
  ic.x = {0.03};
  ic.z = {0.001 + 1e-4};
  ic.vx = {0};
  ic.vz = {0};
  EdSimulation sim(c, ic);
  ContainmentCheck check(s.particles.diameter, s.container.width, s.container.height);
  sim.addObserver(&check);
  sim.run();
  EXPECT_EQ(check.violations, 0);
  const Snapshot end = sim.snapshot();
  EXPECT_NEAR(end.z[0] - end.plate_height, 0.001, 1e-12);  // resting on the plate
  EXPECT_EQ(sim.counters().collisions.rests, 1u);
}

// Regressions: resting layers on the plate once trapped the event loop (same instant,
// collisions forever) in three configurations, now resolved exactly (docs/physics.md,
// "Resting contacts"): a particle pinched between the plate and a plate-carried particle
// (paper wet scene, seed 3, t = 8.40 s), two plate-carried particles overlapping by
// round-off while sliding (wet, Gamma = 7, t = 3.20 s), and, without friction, a flyer
// touching a rider that moves horizontally into it right after an e_n = 0 collision
// (paper wet scene, mu = 0, t = 0.0969 s): prediction scheduled a rest that execution
// refuses; and two plate-carried particles stacked exactly on top of each other against a
// side wall (wet, f = 15 Hz, Gamma = 2, seed 2, t = 3.94 s), whose horizontal sliding counted
// as an approach, so that they swapped their vx at one instant until the collapse detector
// stopped the run. All must run through and keep the energy budget.
TEST(WallContact, WetLayerAtGammaSevenRunsThroughResting) {
  Scene s = test::paperScene(RestitutionKind::Wet, 3.5);
  s.drive.gamma = 7.0;
  runContained(s);
}

namespace {
// Runs `s` to its duration without an exception; the energy budget E(t) - E(0) = W - D
// closes to 1e-9 of the wall work. Returns the final observables.
Observables runThroughKeepingTheBudget(const Scene& s) {
  EdSimulation sim = test::makeSimulation(s);
  const Observables o0 = sim.snapshot().obs;
  EXPECT_NO_THROW(sim.advanceTo(s.run.duration));
  const Observables o1 = sim.snapshot().obs;
  EXPECT_NEAR(test::totalEnergy(o1) - test::totalEnergy(o0), o1.wall_work - o1.dissipated_energy,
              1e-9 * o1.wall_work);
  return o1;
}
}  // namespace

TEST(WallContact, WetLayerSeedThreeRunsThroughPinchedContacts) {
  Scene s = test::paperScene(RestitutionKind::Wet, 8.6);
  s.run.seed = 3;
  runThroughKeepingTheBudget(s);
}

TEST(WallContact, FrictionlessWetLayerRunsThroughFlyersSlidingIntoRiders) {
  Scene s = test::paperScene(RestitutionKind::Wet, 0.2);
  s.contact.friction = 0.0;
  EXPECT_GT(runThroughKeepingTheBudget(s).collisions.rests, 0u);
}

TEST(WallContact, WetLayerRunsThroughRidersStackedAtASideWall) {
  Scene s = test::paperScene(RestitutionKind::Wet, 4.0);
  s.drive.frequency = 15.0;
  s.drive.gamma = 2.0;
  s.run.seed = 2;
  runThroughKeepingTheBudget(s);
}
