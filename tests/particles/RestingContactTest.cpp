// Resting contacts (docs/physics.md, "Resting contacts"): a particle that would bounce back
// within the TC time comes to rest, a resting layer keeps its energy exactly, and a layer
// carried by a gently shaken plate costs a fixed number of events per cycle. With the TC
// model on, particles in enduring contact with what the bottom holds are put to sleep
// (carried by it), so a poured packing settles, stays at rest at no cost, and carries its
// weight on the plate.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "EngineTestSupport.hpp"
#include "h5/File.hpp"
#include "particles/CellGrid.hpp"
#include "particles/StateArchive.hpp"
#include "scene/SceneParser.hpp"
#include "tests/h5/ScratchDir.hpp"

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

namespace {

Scene paperFile(const std::string& law, std::vector<std::string> overrides) {
  return parseSceneFile(std::string(GRANWAVE_SOURCE_DIR) + "/scenes/paper-" + law + ".toml",
                        overrides);
}

// Runs to the scene's duration; the collapse detector throws if a contact is not resolved.
double runToEnd(const Scene& s) {
  EdSimulation sim = test::makeSimulation(s);
  sim.run();
  return sim.now();
}

// Vertical momentum of the layer (kg m/s).
double verticalMomentum(const EdSimulation& sim) {
  double p = 0;
  for (int i = 0; i < sim.size(); ++i) p += sim.config().mass * sim.velocity(i).z;
  return p;
}

// A still plate, the paper's box, n particles poured at random (dry, TC on).
Scene pouredPacking(int n, double duration) {
  Scene s = test::paperScene(RestitutionKind::Dry, duration);
  s.particles.count = n;
  s.drive.frequency = 0;
  s.drive.gamma.reset();
  s.run.seed = 3;
  return s;
}

}  // namespace

// The three runs that the collapse detector stopped before resting contacts (a crystal whose
// rows fill the L_x = 30 d box exactly rattled elastically within t_c for ever) now run past
// their stopping time (0.206, 0.242 and 0.139 s) to 1 s.
TEST(RestingContact, SettlingDryLayerOnStillPlateRunsPastTheOldCollapse) {
  EXPECT_EQ(runToEnd(paperFile("dry", {"drive.frequency=0", "run.seed=2", "run.duration=1"})), 1.0);
}

TEST(RestingContact, DryLayerAtGammaOneRunsPastTheOldCollapse) {
  EXPECT_EQ(runToEnd(paperFile("dry", {"drive.gamma=1", "run.seed=2", "run.duration=1"})), 1.0);
}

TEST(RestingContact, SettlingWetLayerOnStillPlateRunsPastTheOldCollapse) {
  EXPECT_EQ(runToEnd(paperFile("wet", {"drive.frequency=0", "run.seed=2", "run.duration=1"})), 1.0);
}

TEST(RestingContact, PouredPackingSettlesAndThePlateCarriesItsWeight) {
  // Statics: a layer at rest on the plate between smooth side walls (no wall friction, so no
  // Janssen screening) presses on it with its whole weight, F = N m g. The plate's force is
  // measured as the impulse it gives over a window over the window's length; Newton's second
  // law for the layer says J - N m g T = P_z(t2) - P_z(t1), so the tolerance is the change of
  // the layer's vertical momentum over T (zero once it sleeps) plus round-off.
  const int n = 120;
  EdSimulation sim = test::makeSimulation(pouredPacking(n, 6.0));
  sim.advanceTo(3.0);  // poured from random heights up to L_z: settled well within 3 s
  const double z1 = sim.snapshot().obs.center_of_mass_height;
  const double j1 = sim.bottomImpulse(), p1 = verticalMomentum(sim);
  sim.advanceTo(6.0);
  const double z2 = sim.snapshot().obs.center_of_mass_height;
  const double j2 = sim.bottomImpulse(), p2 = verticalMomentum(sim);
  const EngineConfig& c = sim.config();
  const double weight = n * c.mass * c.gravity, window = 3.0;
  EXPECT_GT(sim.sleeps(), 0u);
  EXPECT_NEAR(z2, z1, 1e-9 * c.diameter);  // the centre of mass no longer moves
  const double tolerance = std::abs(p2 - p1) / window + 1e-12 * weight;
  EXPECT_NEAR((j2 - j1) / window, weight, tolerance);
  // And the packing sits on the plate: its centre of mass lies between that of a single row
  // piled up to n / 30 rows of hexagonal packing (rows sqrt(3)/2 d apart) and twice that.
  const double rows = n / 30.0, d = c.diameter;
  const double hex = 0.5 * d + 0.5 * (rows - 1) * std::sqrt(3.0) / 2.0 * d;
  EXPECT_GT(z2, hex * 0.9);
  EXPECT_LT(z2, 2.0 * hex);
}

TEST(RestingContact, SettledPackingStaysAtRestForHundredSecondsWithNoEnergyDrift) {
  // Once asleep, nothing moves relative to the still plate: no event, and the energy (all
  // potential) stays the same to the last bit over 100 s.
  EdSimulation sim = test::makeSimulation(pouredPacking(120, 103.0));
  sim.advanceTo(3.0);
  const double e0 = test::totalEnergy(sim.snapshot().obs);
  const auto events0 = sim.counters().events;
  sim.advanceTo(103.0);
  EXPECT_EQ(test::totalEnergy(sim.snapshot().obs), e0);
  EXPECT_LE(sim.counters().events - events0, 120u);  // O(1) per particle, not per second
}

TEST(RestingContact, SleepStateRestartsBitIdenticallyThroughTheArchive) {
  // Runs paused while the layer settles (some asleep, some rattling), saved through the
  // HDF5 archive and continued end exactly where an uninterrupted run ends.
  const Scene s = pouredPacking(120, 1.0);
  EdSimulation whole = test::makeSimulation(s);
  whole.run();
  const Snapshot a = whole.snapshot();
  for (const int pause_at : {5, 10, 20, 40}) {
    EdSimulation first = test::makeSimulation(s);
    int records = 0;
    first.run(nullptr, [&] { return ++records == pause_at; });
    ASSERT_LT(first.now(), 1.0);
    granwave::testing::ScratchDir dir;
    {
      h5::File f = h5::File::create(dir.file("state.h5"));
      writeEngineState(f, "/engine", first.state());
    }
    EdSimulation second(first.config(),
                        readEngineState(h5::File::openReadOnly(dir.file("state.h5")), "/engine"));
    second.run();
    const Snapshot b = second.snapshot();
    EXPECT_EQ(a.x, b.x) << "paused at record " << pause_at;
    EXPECT_EQ(a.z, b.z) << "paused at record " << pause_at;
    EXPECT_EQ(a.vx, b.vx) << "paused at record " << pause_at;
    EXPECT_EQ(a.vz, b.vz) << "paused at record " << pause_at;
    EXPECT_EQ(whole.sleeps(), second.sleeps());
    EXPECT_EQ(whole.bottomImpulse(), second.bottomImpulse());
  }
  EXPECT_GT(whole.sleeps(), 0u);
}

TEST(RestingContact, SleepIsOnByDefaultOnlyWhereThePlateCannotLiftTheLayer) {
  // contact.sleep = "auto": on with no drive or Gamma <= 1 (a resting layer stays at rest, so
  // stopping its own motion is exact), off on a layer that flies (Gamma > 1).
  const std::string wet = std::string(GRANWAVE_SOURCE_DIR) + "/scenes/paper-wet.toml";
  auto sleeps = [&](std::vector<std::string> set) {
    return engineConfig(parseSceneFile(wet, set)).sleep;
  };
  EXPECT_FALSE(sleeps({}));  // the paper's Gamma = 4
  EXPECT_FALSE(sleeps({"drive.gamma=1.2"}));
  EXPECT_TRUE(sleeps({"drive.gamma=1"}));
  EXPECT_TRUE(sleeps({"drive.gamma=0.5"}));
  EXPECT_TRUE(sleeps({"drive.frequency=0"}));
  EXPECT_TRUE(sleeps({"contact.sleep=\"on\""}));
  EXPECT_FALSE(sleeps({"drive.gamma=0.5", "contact.sleep=\"off\""}));
}
