// The run loop's limits (particles/EdSimulation.cpp): an interrupt is seen within a few
// thousand events even in the middle of a record, and a run making events far faster than
// its budget stops with a clear message instead of running for ever (docs/scenes.md).
#include <gtest/gtest.h>

#include <atomic>
#include <string>

#include "EngineTestSupport.hpp"
#include "particles/EventLoopStall.hpp"

namespace granwave {
namespace {

TEST(RunLimits, InterruptStopsAdvanceWithinAFewThousandEvents) {
  // 300 elastic disks at area fraction 0.3: about 1e5 events per simulated second.
  const Scene s = test::periodicGas(300, 0.3, 1e-6, 1.0);
  EdSimulation sim = test::makeSimulation(s);
  const std::atomic<bool> interrupt{true};
  EXPECT_FALSE(sim.advanceTo(100.0, &interrupt));
  EXPECT_LT(sim.now(), 100.0);
  EXPECT_GT(sim.counters().events, 0u);
  EXPECT_LE(sim.counters().events, 4096u);
}

TEST(RunLimits, InterruptInsideALongRecordIsNotAtARecord) {
  Scene s = test::periodicGas(300, 0.3, 1e-6, 1.0);
  s.run.duration = 1000;
  s.run.record_interval = 500;
  EngineConfig c = engineConfig(s);
  EdSimulation sim(c, initialCondition(s, c));
  std::atomic<bool> interrupt{false};
  int asked = 0;
  // The pause predicate is asked after the record at t = 0: raise the flag there.
  const RunStatus st = sim.run(&interrupt, [&] {
    interrupt.store(++asked == 1);
    return false;
  });
  EXPECT_TRUE(st.interrupted);
  EXPECT_FALSE(st.at_record);
  EXPECT_FALSE(st.completed);
  EXPECT_LT(st.time, 1.0);  // a few thousand events: well inside the first record
}

TEST(RunLimits, RunFasterThanItsEventBudgetStopsWithAClearMessage) {
  const Scene s = test::periodicGas(300, 0.3, 1e-6, 1.0);
  EngineConfig c = engineConfig(s);
  EXPECT_GT(c.max_event_rate, 0.0);  // every scene gets a budget
  c.max_event_rate = 1000;           // far below the gas's 1e5 events per second
  c.max_event_rate_grace = 0;
  EdSimulation sim(c, initialCondition(s, c));
  try {
    sim.advanceTo(10.0);
    FAIL() << "expected EventLoopStall";
  } catch (const EventLoopStall& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("would not finish"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
  EXPECT_LT(sim.now(), 1.0);
}

TEST(RunLimits, BudgetLeavesThePaperSceneFarFromTheLimit) {
  // Paper's dry scene, 1 s: a physical run stays orders of magnitude below its budget.
  const Scene s = test::paperScene(RestitutionKind::Dry, 1.0);
  EdSimulation sim = test::makeSimulation(s);
  sim.advanceTo(1.0);
  EXPECT_LT(static_cast<double>(sim.counters().events), 1e-2 * sim.config().max_event_rate);
}

}  // namespace
}  // namespace granwave
