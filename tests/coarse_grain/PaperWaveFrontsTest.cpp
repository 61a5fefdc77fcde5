// Wave fronts of the paper's wet layer (N = 300, f = 10 Hz, Gamma = 4; paper Sec. IV,
// Fig. 5): 1.61 +- 0.25 m/s after the weak impact, 1.95 +- 0.25 m/s after the strong one.
// 30 simulated seconds (300 cycles, as the paper), phase-averaged live over a window of two
// cycles (the layer is period-doubled). The test asserts agreement within three combined
// standard errors, sqrt(s_ours^2 + s_paper^2), with the slower of our two fronts matched to
// the weak impact. It also asserts that the measurement is informative (s_ours < 0.6 m/s).
// Measured (seed 1, live): 1.80 +- 0.46 and 1.86 +- 0.37 m/s on the final build of the first
// session, 1.18 +- 0.42 and 1.28 +- 0.40 on an earlier one (round-off changes the chaotic
// trajectory); docs/fields.md discusses both.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "coarse_grain/FieldsAnalysis.hpp"
#include "particles/EdSimulation.hpp"
#include "particles/InitialState.hpp"
#include "scene/SceneDerived.hpp"

using namespace granwave;

TEST(PaperWaveFronts, WetLayerFrontSpeedsAgreeWithThePaperWithinCombinedErrors) {
  Scene s;
  s.contact.restitution = RestitutionKind::Wet;
  s.run.duration = 30.0;
  const SceneDerived dv = derive(s);
  const EngineConfig c = engineConfig(s);
  EdSimulation sim(c, initialCondition(s, c));
  PhaseAveragerConfig pc;
  pc.grid = FieldGrid::forContainer(s.container.width, s.container.height, dv.amplitude,
                                    s.particles.diameter);
  pc.samples_per_cycle = 100;
  pc.cycles_per_window = 2;
  pc.total_cycles = 300;
  PhaseAverager av(pc);
  sim.addObserver(&av);
  ASSERT_TRUE(sim.run().completed);
  FieldsContext ctx;
  ctx.diameter = s.particles.diameter;
  ctx.mass = dv.mass;
  ctx.inertia = dv.inertia;
  ctx.frequency = 10.0;
  ctx.amplitude = dv.amplitude;
  ctx.T0 = dv.T0;
  const FieldsAnalysis a = analyseFields(av, ctx);
  EXPECT_GE(a.pooled_cycles, 250);

  std::vector<FrontEpisode> impact;
  for (const FrontEpisode& e : a.fronts)
    if (e.from_impact) impact.push_back(e);
  ASSERT_EQ(impact.size(), 2u) << "one front after each of the two impacts of the window";
  std::sort(impact.begin(), impact.end(),
            [](const FrontEpisode& x, const FrontEpisode& y) { return x.speed < y.speed; });
  const double paper[2] = {1.61, 1.95}, paper_err = 0.25;
  for (int k = 0; k < 2; ++k) {
    const FrontEpisode& e = impact[k];
    EXPECT_LT(e.speed_error, 0.6);
    const double combined = std::hypot(e.speed_error, paper_err);
    EXPECT_LT(std::abs(e.speed - paper[k]), 3 * combined)
        << "front " << k << ": " << e.speed << " +- " << e.speed_error << " m/s vs paper "
        << paper[k] << " +- " << paper_err;
    // Fronts move up, faster relative to the gas ahead, which falls onto the plate.
    EXPECT_GT(e.speed, 0.0);
    EXPECT_LT(e.gas_velocity_ahead, 0.0);
  }
}
