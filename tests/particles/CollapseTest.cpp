// Inelastic collapse (McNamara & Young 1994): a strongly inelastic gas without the TC
// model makes infinitely many collisions in finite time. The engine must stop with a
// clear InelasticCollapse naming the time, the particles and the remedy, not hang; with
// the TC model (Luding & McNamara 1998) the same scene runs through.
#include <gtest/gtest.h>

#include "EngineTestSupport.hpp"
#include "particles/InelasticCollapse.hpp"

using namespace granwave;

namespace {
Scene collapsingGas() {
  // e = 0.3 in a dense periodic gas: collapse within a few collisions per particle.
  Scene s = test::periodicGas(400, 0.4, 1e-6, 0.3);
  s.initial.placement = InitialPlacement::Random;
  return s;
}
}  // namespace

TEST(InelasticCollapse, IsDetectedAndReportedWithoutTC) {
  EdSimulation sim = test::makeSimulation(collapsingGas());
  try {
    sim.advanceTo(100.0);
    FAIL() << "expected inelastic collapse";
  } catch (const InelasticCollapse& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("inelastic collapse at t ="), std::string::npos) << msg;
    EXPECT_NE(msg.find("contact.tc"), std::string::npos) << msg;  // names the remedy
    EXPECT_GE(e.particle(), 0);
    EXPECT_GT(e.time(), 0.0);
    EXPECT_EQ(msg.find('\n'), std::string::npos);  // one line
  }
}

TEST(InelasticCollapse, IsPreventedByTheTCModel) {
  Scene s = collapsingGas();
  s.contact.tc_enabled = true;
  s.contact.tc_time = 1e-4;
  EdSimulation sim = test::makeSimulation(s);
  EXPECT_NO_THROW(sim.advanceTo(5.0));
  EXPECT_GT(sim.counters().collisions.tc_elastic, 0u);
}
