// Wave fronts of the paper's wet layer (N = 300, f = 10 Hz, Gamma = 4; paper Sec. IV,
// Fig. 5): 1.61 +- 0.25 m/s after the weak impact, 1.95 +- 0.25 m/s after the strong one.
// 30 simulated seconds (300 cycles, as the paper) for each of seeds 1, 2, 3, phase-averaged
// live over a window of two cycles (the layer is period-doubled); the slower of a run's two
// fronts is matched to the weak impact. Each front is combined over the seeds by inverse
// variance, its error scaled by sqrt(chi^2 / dof) when the seeds scatter more than their
// errors (as the wave-fronts study does). The test asserts agreement within three combined
// standard errors, sqrt(s_ours^2 + s_paper^2), and that the measurement is informative
// (s_ours < 0.6 m/s). One seed alone is a chaotic sample whose error swings with round-off:
// seed 1 gave 1.80 +- 0.46 / 1.86 +- 0.37, 1.18 +- 0.42 / 1.28 +- 0.40 on earlier builds and
// 1.88 +- 0.99 for the strong front after the rider-pair fix (docs/physics.md, item 5;
// docs/fields.md).
// This checks the paper's own marker, the T~g peak, measured the paper's way. On this scene
// that peak jumps from near the plate to the top of the layer within one phase, so its line
// is not a travelling front and its agreement is weaker evidence than it looks; the studies
// compare the velocity-jump front instead (docs/studies.md, "Front speeds on the paper's
// scene").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "coarse_grain/FieldsAnalysis.hpp"
#include "particles/EdSimulation.hpp"
#include "particles/InitialState.hpp"
#include "scene/SceneDerived.hpp"

using namespace granwave;

namespace {

// The two impact fronts of one 30 s run of the paper's wet scene with `seed`, slower first.
std::vector<FrontEpisode> wetImpactFronts(std::uint64_t seed) {
  Scene s;
  s.contact.restitution = RestitutionKind::Wet;
  s.run.duration = 30.0;
  s.run.seed = seed;
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
  EXPECT_TRUE(sim.run().completed);
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
  std::sort(impact.begin(), impact.end(),
            [](const FrontEpisode& x, const FrontEpisode& y) { return x.speed < y.speed; });
  return impact;
}

}  // namespace

TEST(PaperWaveFronts, WetLayerFrontSpeedsAgreeWithThePaperWithinCombinedErrors) {
  const double paper[2] = {1.61, 1.95}, paper_err = 0.25;
  // Inverse-variance sums per front over the seeds, for the mean, its error and chi^2.
  double w[2] = {0, 0}, wv[2] = {0, 0}, wv2[2] = {0, 0};
  for (std::uint64_t seed : {1, 2, 3}) {
    const std::vector<FrontEpisode> impact = wetImpactFronts(seed);
    ASSERT_EQ(impact.size(), 2u) << "seed " << seed
                                 << ": one front after each of the two impacts of the window";
    for (int k = 0; k < 2; ++k) {
      const FrontEpisode& e = impact[k];
      // Fronts move up, faster relative to the gas ahead, which falls onto the plate.
      EXPECT_GT(e.speed, 0.0);
      EXPECT_LT(e.gas_velocity_ahead, 0.0);
      const double wk = 1.0 / (e.speed_error * e.speed_error);
      w[k] += wk;
      wv[k] += wk * e.speed;
      wv2[k] += wk * e.speed * e.speed;
      std::printf("seed %d, front %d: %.3f +- %.3f m/s\n", static_cast<int>(seed), k, e.speed,
                  e.speed_error);
    }
  }
  for (int k = 0; k < 2; ++k) {
    const double mean = wv[k] / w[k];
    const double chi2 = wv2[k] - w[k] * mean * mean;  // sum of ((v - mean) / s)^2
    const double error = std::sqrt(1.0 / w[k]) * std::max(1.0, std::sqrt(chi2 / 2.0));
    std::printf("front %d combined: %.3f +- %.3f m/s (chi2/dof %.2f); paper %.2f +- %.2f\n", k,
                mean, error, chi2 / 2.0, paper[k], paper_err);
    EXPECT_LT(error, 0.6) << "front " << k << ": not informative";
    EXPECT_LT(std::abs(mean - paper[k]), 3 * std::hypot(error, paper_err))
        << "front " << k << ": " << mean << " +- " << error << " m/s vs paper " << paper[k]
        << " +- " << paper_err;
  }
}
