// The stability of the wave-fronts study's simplest-model verdict over seeds
// (studies/wave_fronts/WaveFrontsVerdicts.cpp), on model inputs whose bootstrap distribution is
// known in closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "studies/wave_fronts/WaveFrontsAnalysis.hpp"

using namespace granwave;

namespace {

// Seeds 1-3 of the full model: periods (2, 2, 1); the constant-e particle model has period 2
// on every seed and the same fronts; every hydro candidate failed. With all seeds the
// reference period is 2 and "particles, constant e" reproduces it; a resample whose mode is 1
// (seed 3 drawn at least twice of three: probability 3 (1/3)^2 (2/3) + (1/3)^3 = 7/27) says
// "none".
ModelInputs bistableInputs(const std::vector<int>& periods) {
  ModelInputs in;
  SeedRun run{true, {}, 2};
  run.fronts.all = {1.0, 0.1};
  for (std::size_t i = 0; i < periods.size(); ++i) {
    in.seeds.push_back(static_cast<int>(i) + 1);
    run.period = periods[i];
    in.particles[""].push_back(run);
    run.period = 2;
    in.particles["constant e "].push_back(run);
    in.particles["no rotation "].push_back(SeedRun{});
  }
  for (const char* tag : {"constant", "velocity", "Garzo-Dufty", "rough"})
    in.hydro[WaveFrontsConfig::hydroRun(1, tag)].failure = "failed";
  return in;
}

}  // namespace

TEST(VerdictStability, ABistableReferenceLeavesTheVerdictUndecidedAtTheBootstrapShare) {
  WaveFrontsConfig c;
  c.e_eff[1] = 0.8;
  const VerdictStability v = modelVerdictStability(c, bistableInputs({2, 2, 1}), 1);
  EXPECT_EQ(v.verdict, "particles, constant e = 0.800");
  EXPECT_EQ(v.seeds, 3);
  // Expected agreement 20/27 = 0.741; binomial sd over 200 resamples 0.031: 4 sd.
  EXPECT_NEAR(v.agreement, 20.0 / 27.0, 0.125);
  EXPECT_FALSE(v.decided);  // below 0.9
  EXPECT_NEAR(v.shares.at("none"), 7.0 / 27.0, 0.125);
}

TEST(VerdictStability, SeedsThatAllAgreeGiveADecidedVerdict) {
  WaveFrontsConfig c;
  c.e_eff[1] = 0.8;
  const VerdictStability v = modelVerdictStability(c, bistableInputs({2, 2, 2, 2}), 1);
  EXPECT_EQ(v.verdict, "particles, constant e = 0.800");
  EXPECT_DOUBLE_EQ(v.agreement, 1.0);
  EXPECT_TRUE(v.decided);
}

TEST(VerdictStability, TheSameInputsGiveTheSameResamplesEveryTime) {
  WaveFrontsConfig c;
  const ModelInputs in = bistableInputs({2, 1, 2, 1, 1});
  EXPECT_EQ(modelVerdictStability(c, in, 1).agreement, modelVerdictStability(c, in, 1).agreement);
}
