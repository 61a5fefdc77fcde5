// The wave-fronts study's simplest-model verdict (studies/wave_fronts/WaveFrontsMethods.cpp,
// judgeModels) and its stability over seeds (WaveFrontsVerdicts.cpp), on model inputs whose
// bootstrap distribution is known in closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "studies/wave_fronts/WaveFrontsAnalysis.hpp"

using namespace granwave;

namespace {

// One seed's run: the same fronts for every model (so only the state decides), its period, and
// `period2` of 25 twelve-cycle windows in the period-2 state, `effective` of them independent.
SeedRun seedRun(int period, int period2, double effective) {
  SeedRun r{true, {}, period, 25, period2, effective};
  r.fronts.all = {1.0, 0.1};
  return r;
}

// The full model's seeds and the constant-e particle model's, seed by seed; the no-rotation
// model and every hydro candidate failed.
ModelInputs inputs(const std::vector<SeedRun>& reference, const std::vector<SeedRun>& constant_e) {
  ModelInputs in;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    in.seeds.push_back(static_cast<int>(i) + 1);
    in.particles[""].push_back(reference[i]);
    in.particles["constant e "].push_back(constant_e[i]);
    in.particles["no rotation "].push_back(SeedRun{});
  }
  for (const char* tag : {"constant", "velocity", "Garzo-Dufty", "rough"})
    in.hydro[WaveFrontsConfig::hydroRun(1, tag)].failure = "failed";
  return in;
}

WaveFrontsConfig config() {
  WaveFrontsConfig c;
  c.e_eff[1] = 0.8;
  return c;
}

const char* kConstantE = "particles, constant e = 0.800";

}  // namespace

TEST(VerdictStability, ABistableLayerIsJudgedByItsTimeInEachStateNotByItsRunsPeriods) {
  // Both models spend about half their time in each state; the runs' periods are the draw of
  // that (reference 2, 2, 1; candidate 1, 1, 2: opposite modes). Judged by the period, no
  // resample could agree; by the share of time (0.56 and 0.52 over 30 effective windows each,
  // the difference's 95 % interval about +-0.25) every resample does.
  const ModelInputs in = inputs({seedRun(2, 15, 10), seedRun(2, 14, 10), seedRun(1, 13, 10)},
                                {seedRun(1, 12, 10), seedRun(1, 13, 10), seedRun(2, 14, 10)});
  const VerdictStability v = modelVerdictStability(config(), in, 1);
  EXPECT_EQ(v.verdict, kConstantE);
  EXPECT_DOUBLE_EQ(v.agreement, 1.0);
  EXPECT_TRUE(v.decided);
}

TEST(VerdictStability, ACandidateStuckInOneStateDoesNotReproduceABistableLayer) {
  // The candidate never leaves period 1 (0 of 75 windows) against the reference's 0.56 of 30
  // effective windows (95 % interval 0.38-0.72): no model reproduces it, in every resample.
  const ModelInputs in = inputs({seedRun(2, 15, 10), seedRun(2, 14, 10), seedRun(1, 13, 10)},
                                {seedRun(1, 0, 25), seedRun(1, 0, 25), seedRun(1, 0, 25)});
  const ModelHierarchy m = judgeModels(config(), in, 1, {0, 1, 2});
  EXPECT_TRUE(m.simplest.empty());
  EXPECT_NEAR(m.reference_share.share, 42.0 / 75.0, 1e-12);
  EXPECT_FALSE(m.candidates[4].share_gap.compatible());
  const VerdictStability v = modelVerdictStability(config(), in, 1);
  EXPECT_EQ(v.verdict, "none");
  EXPECT_DOUBLE_EQ(v.agreement, 1.0);
}

TEST(VerdictStability, ASeedThatDecidesTheVerdictLeavesItUndecidedAtTheBootstrapShare) {
  // Seed 1 of the reference is period 2 throughout, seeds 2 and 3 never; the candidate never.
  // All seeds: 25 of 75 windows against 0 of 75, incompatible: "none". A resample without seed
  // 1 (probability (2/3)^3 = 8/27) has the reference at 0 too and names the candidate, so the
  // agreement is 19/27 = 0.70, below 0.9. Binomial sd over 200 resamples 0.032: 4 sd = 0.13.
  const ModelInputs in = inputs({seedRun(2, 25, 25), seedRun(1, 0, 25), seedRun(1, 0, 25)},
                                {seedRun(1, 0, 25), seedRun(1, 0, 25), seedRun(1, 0, 25)});
  const VerdictStability v = modelVerdictStability(config(), in, 1);
  EXPECT_EQ(v.verdict, "none");
  EXPECT_NEAR(v.agreement, 19.0 / 27.0, 0.13);
  EXPECT_FALSE(v.decided);
  EXPECT_NEAR(v.shares.at(kConstantE), 8.0 / 27.0, 0.13);
}

TEST(VerdictStability, TheSameInputsGiveTheSameResamplesEveryTime) {
  const ModelInputs in = inputs({seedRun(2, 25, 25), seedRun(1, 0, 25), seedRun(1, 3, 25),
                                 seedRun(2, 20, 25), seedRun(1, 0, 25)},
                                {seedRun(1, 0, 25), seedRun(1, 0, 25), seedRun(1, 0, 25),
                                 seedRun(1, 5, 25), seedRun(1, 0, 25)});
  EXPECT_EQ(modelVerdictStability(config(), in, 1).agreement,
            modelVerdictStability(config(), in, 1).agreement);
}
