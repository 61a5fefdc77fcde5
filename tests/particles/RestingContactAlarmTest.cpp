// The sleep rule's alarm (docs/physics.md, "Resting contacts", item 7): with
// contact.sleep = "auto" on a layer that flies, the rule is off until one particle makes
// kAutoSleepAlarm enduring collisions in a row (each within t_c of the previous one), which
// only a particle rattling at no gap does; from then on it is on for the rest of the run, and
// a particle that still rattles that long collides perfectly inelastically with its group.
// The paper's scenes never raise it, and the stability-grid runs the collapse detector
// stopped finish.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "h5/File.hpp"
#include "particles/EdSimulation.hpp"
#include "particles/InelasticCollapse.hpp"
#include "particles/InitialState.hpp"
#include "particles/StateArchive.hpp"
#include "scene/SceneParser.hpp"
#include "tests/h5/ScratchDir.hpp"

using namespace granwave;

namespace {

Scene paperFile(const std::string& law, std::vector<std::string> overrides) {
  return parseSceneFile(std::string(GRANWAVE_SOURCE_DIR) + "/scenes/paper-" + law + ".toml",
                        overrides);
}

EdSimulation simulationOf(const EngineConfig& c, const Scene& s) {
  return EdSimulation(c, initialCondition(s, c));
}

// The paper's dry layer at Gamma = 1 (seed 2), which rattled at no gap in a row filling the
// box and was stopped by the collapse detector at t = 0.242 s with the sleep rule off, run
// with the rule off and the alarm as "auto" sets it on a flying layer.
Scene dryAtGammaOne(double duration) {
  return paperFile("dry",
                   {"drive.gamma=1", "run.seed=2", "run.duration=" + std::to_string(duration)});
}

EngineConfig alarmOnly(const Scene& s, std::uint32_t alarm) {
  EngineConfig c = engineConfig(s);
  c.sleep = false;
  c.sleep_alarm = alarm;
  return c;
}

}  // namespace

TEST(RestingContactAlarm, AutoAndOnCountEnduringCollisionsOffDoesNot) {
  auto config = [](std::vector<std::string> set) { return engineConfig(paperFile("wet", set)); };
  EXPECT_FALSE(config({}).sleep);  // Gamma = 4: off until the alarm
  EXPECT_EQ(config({}).sleep_alarm, kAutoSleepAlarm);
  EXPECT_EQ(config({"drive.gamma=0.5"}).sleep_alarm, kAutoSleepAlarm);  // on, and ends rattles
  EXPECT_EQ(config({"contact.sleep=\"on\""}).sleep_alarm, kAutoSleepAlarm);
  EXPECT_EQ(config({"contact.sleep=\"off\""}).sleep_alarm, 0u);  // off means off
}

TEST(RestingContactAlarm, RowRattlingAtNoGapRaisesTheAlarmAndIsPutToSleep) {
  // Without the alarm the collapse detector stops the run (a particle collides 2000 times
  // within ~t_c): the test can fail. With it the rule switches on before that, the row is
  // put to sleep, and the energy budget E - E0 = W - D still closes to round-off.
  const Scene s = dryAtGammaOne(1.0);
  EdSimulation off = simulationOf(alarmOnly(s, 0), s);
  EXPECT_THROW(off.run(), InelasticCollapse);
  const double stopped = off.now();

  EdSimulation sim = simulationOf(alarmOnly(s, kAutoSleepAlarm), s);
  const Observables o0 = sim.snapshot().obs;
  sim.run();
  EXPECT_EQ(sim.now(), 1.0);
  EXPECT_GT(sim.sleepAlarmTime(), 0.0);
  EXPECT_LE(sim.sleepAlarmTime(), stopped);
  EXPECT_GT(sim.sleeps(), 0u);
  const Observables o = sim.snapshot().obs;
  auto energy = [](const Observables& b) {
    return b.kinetic_energy + b.rotational_energy + b.potential_energy;
  };
  EXPECT_NEAR(energy(o) - energy(o0), o.wall_work - o.dissipated_energy, 1e-12 * energy(o0));
}

TEST(RestingContactAlarm, RunsWithoutAnAlarmAreBitIdenticalToTheRuleOff) {
  // Until it is raised the alarm only counts: the paper's wet scene (the longest run of
  // enduring collisions over seeds 1-12 is 141, far below the alarm) ends exactly as with
  // contact.sleep = "off". Its first 50 cycles (the same run up to 5 s, so the 141 bounds
  // them too): the landings, the enduring collisions and the period-2 state all occur in them.
  const Scene s = paperFile("wet", {"run.seed=1", "run.duration=5"});
  EdSimulation with_alarm = simulationOf(engineConfig(s), s);
  with_alarm.run();
  EdSimulation off = simulationOf(alarmOnly(s, 0), s);
  off.run();
  EXPECT_LT(with_alarm.sleepAlarmTime(), 0.0);
  const Snapshot a = with_alarm.snapshot(), b = off.snapshot();
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.z, b.z);
  EXPECT_EQ(a.vx, b.vx);
  EXPECT_EQ(a.vz, b.vz);
  EXPECT_EQ(with_alarm.counters().events, off.counters().events);
}

TEST(RestingContactAlarm, AlarmRestartsBitIdenticallyThroughTheArchive) {
  // Paused before and after the alarm (the record interval is 1 ms), saved through the HDF5
  // archive and continued: each ends exactly where the uninterrupted run ends, with the
  // alarm at the same time.
  const Scene s = dryAtGammaOne(0.5);
  const EngineConfig c = alarmOnly(s, kAutoSleepAlarm);
  EdSimulation whole = simulationOf(c, s);
  whole.run();
  ASSERT_GT(whole.sleepAlarmTime(), 0.0);
  const int alarm_record = static_cast<int>(whole.sleepAlarmTime() / c.record_interval);
  for (const int pause_at : {alarm_record - 5, alarm_record + 5}) {
    EdSimulation first = simulationOf(c, s);
    int records = 0;
    first.run(nullptr, [&] { return ++records == pause_at; });
    ASSERT_LT(first.now(), 0.5);
    granwave::testing::ScratchDir dir;
    {
      h5::File f = h5::File::create(dir.file("state.h5"));
      writeEngineState(f, "/engine", first.state());
    }
    EdSimulation second(c,
                        readEngineState(h5::File::openReadOnly(dir.file("state.h5")), "/engine"));
    second.run();
    const Snapshot a = whole.snapshot(), b = second.snapshot();
    EXPECT_EQ(a.x, b.x) << "paused at record " << pause_at;
    EXPECT_EQ(a.vx, b.vx) << "paused at record " << pause_at;
    EXPECT_EQ(a.vz, b.vz) << "paused at record " << pause_at;
    EXPECT_EQ(whole.sleepAlarmTime(), second.sleepAlarmTime()) << "paused at " << pause_at;
    EXPECT_EQ(whole.sleeps(), second.sleeps());
  }
}

namespace {

// A wet stability-grid point (150 cycles each), run to `duration` with the default settings.
struct GridPoint {
  std::string frequency, gamma, seed, duration;
};

void expectFinishesWithTheAlarm(const GridPoint& p) {
  const Scene s = paperFile("wet", {"drive.frequency=" + p.frequency, "drive.gamma=" + p.gamma,
                                    "run.seed=" + p.seed, "run.duration=" + p.duration});
  const std::string point = p.frequency + " Hz, Gamma " + p.gamma + ", seed " + p.seed;
  EdSimulation sim = simulationOf(engineConfig(s), s);
  EXPECT_NO_THROW(sim.run()) << point;
  EXPECT_NEAR(sim.now(), s.run.duration, 1e-9) << point;
  EXPECT_GT(sim.sleepAlarmTime(), 0.0) << point;
}

}  // namespace

// Runs the collapse detector stops with the rule off (contact.sleep = "off"), run with the
// default just past their stopping time: 10 Hz, Gamma = 2, seeds 2 and 4 (stopped at
// t = 1.307 and 1.902 s; measured with the round-off gap of docs/physics.md, "Resting
// contacts", item 4, which changed these trajectories). Seed 2 run to 3.3 s also needs the
// inelastic group collision of a particle that still rattles with the rule on: with the alarm
// alone, the detector stopped it at 3.285 s (measured before that change).
TEST(RestingContactAlarm, WetGridRunsTheDetectorStoppedFinishWithTheDefault) {
  for (const GridPoint& p : {GridPoint{"10", "2", "2", "3.3"}, GridPoint{"10", "2", "4", "2.0"}})
    expectFinishesWithTheAlarm(p);
}
