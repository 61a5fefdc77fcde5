// How the report states a verdict of the simplest-model comparison (studies/method_comparison/
// MethodComparisonReport.cpp, modelSection): what decided it, in plain words, with the share of
// bootstrap resamples of the seeds that repeat it beside it; never "decided" alone.
#include <gtest/gtest.h>

#include <string>

#include "studies/method_comparison/MethodComparisonReport.hpp"

using namespace granwave;

namespace {

// The headline lines of modelSection for a dry and a wet verdict.
std::vector<std::string> headline(const VerdictStability& dry, const VerdictStability& wet) {
  MethodComparisonConfig c;
  ModelHierarchy models[2];
  models[0].stability = dry;
  models[1].stability = wet;
  Report report;
  return modelSection(c, models, report);
}

VerdictStability decided(std::string verdict, double agreement, int seeds) {
  VerdictStability v;
  v.verdict = std::move(verdict);
  v.decided = true;
  v.agreement = agreement;
  v.seeds = seeds;
  v.resamples = 200;
  v.shares[v.verdict] = agreement;
  if (agreement < 1) v.shares["none"] = 1 - agreement;
  return v;
}

}  // namespace

TEST(VerdictText, ADecidedVerdictSaysWhatDecidedItAndHowOftenResamplesRepeatIt) {
  const auto lines =
      headline(decided("particles, constant e = 0.847", 0.58, 5), decided("none", 1.0, 21));
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].rfind("Dry layer: particles, constant e = 0.847 is the simplest model that "
                           "reproduces the particles. Decided: with all 5 seeds every simpler "
                           "candidate is settled",
                           0),
            0u)
      << lines[0];
  EXPECT_NE(lines[0].find("lie wholly within the tolerances, or one lies wholly outside"),
            std::string::npos);
  EXPECT_NE(lines[0].find("The same verdict in 58 % of 200 bootstrap resamples of the seeds (all "
                          "they give: 'none' 42 %, 'particles, constant e = 0.847' 58 %)."),
            std::string::npos)
      << lines[0];
  EXPECT_NE(lines[1].find("Wet layer: none of the simpler models reproduces the particles. "
                          "Decided: with all 21 seeds"),
            std::string::npos);
  EXPECT_NE(lines[1].find("The same verdict in 100 % of 200 bootstrap resamples"),
            std::string::npos);
}

TEST(VerdictText, AVerdictAtTheCapOfSeedsIsNotCalledDecidedByTheData) {
  VerdictStability v = decided("none", 1.0, 1);
  v.open = {"hydro, velocity-dependent closure, Jenkins-Richman"};
  const auto lines = headline(v, v);
  EXPECT_NE(lines[0].find("none of the simpler models is shown to reproduce the particles. Not "
                          "decided by the data: at the cap of 1 seed 1 candidate is still not "
                          "settled"),
            std::string::npos)
      << lines[0];
  EXPECT_NE(lines[0].find("With one seed the bootstrap cannot test it"), std::string::npos);
  EXPECT_EQ(lines[0].find("Decided:"), std::string::npos);
}

TEST(VerdictText, AnUndecidedVerdictGivesWhatTheResamplesGave) {
  VerdictStability v = decided("undecided", 0.7, 3);
  v.decided = false;
  const auto lines = headline(v, v);
  EXPECT_NE(lines[0].find("Dry layer: undecided at 3 seeds: a simpler candidate is not yet "
                          "settled"),
            std::string::npos)
      << lines[0];
  EXPECT_NE(lines[0].find("'undecided' 70 %"), std::string::npos);
}
