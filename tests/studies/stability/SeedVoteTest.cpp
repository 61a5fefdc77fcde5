// The stability study's verdict over seeds (studies/stability/SeedVote.hpp): the most frequent
// answer, deterministic ties, and which runs vote.
#include <gtest/gtest.h>

#include <stdexcept>

#include "studies/stability/SeedVote.hpp"

namespace granwave {
namespace {

LayerPatterns classified(const std::string& state, int period, bool wave = false, int kinks = 0,
                         double psi6 = 0.5, double bonds = 0.5) {
  LayerPatterns p;
  p.available = true;
  p.state = state;
  p.period = period;
  p.surface_wave = wave;
  p.surface_wave_mode = wave ? 2 : 0;
  p.surface_wave_amplitude_d = wave ? 1.5 : 0;
  p.kinks = kinks;
  p.psi6 = psi6;
  p.bonds_kept = bonds;
  return p;
}

TEST(SeedVote, MostFrequentValueWinsWithItsCount) {
  const Vote<int> v = mostFrequent(std::vector<int>{2, 1, 2});
  EXPECT_EQ(v.value, 2);
  EXPECT_EQ(v.count, 2);
  EXPECT_EQ(v.of, 3);
  EXPECT_FALSE(v.unanimous());
}

TEST(SeedVote, TieGoesToTheValueSeenFirst) {
  EXPECT_EQ(mostFrequent(std::vector<std::string>{"liquid-like", "crystal"}).value, "liquid-like");
  EXPECT_EQ(mostFrequent(std::vector<std::string>{"crystal", "liquid-like"}).value, "crystal");
  EXPECT_EQ(mostFrequent(std::vector<int>{4, 1, 1, 4}).value, 4);
}

TEST(SeedVote, NoVotesGiveNoVerdict) {
  const Vote<bool> v = mostFrequent(std::vector<bool>{});
  EXPECT_EQ(v.of, 0);
  EXPECT_EQ(v.count, 0);
  EXPECT_FALSE(v.unanimous());
}

TEST(SeedVote, UnanimousSeedsAgree) {
  const LayerVerdict v =
      voteOverSeeds({classified("crystal", 1), classified("crystal", 1)}, {true, true}, {"", ""});
  EXPECT_TRUE(v.seedsAgree());
  EXPECT_EQ(v.state.value, "crystal");
  EXPECT_EQ(v.state.count, 2);
}

TEST(SeedVote, FailedSeedDoesNotVoteButIsCountedWithItsReason) {
  const LayerVerdict v =
      voteOverSeeds({classified("crystal", 1), LayerPatterns{}, classified("liquid-like", 2)},
                    {true, false, true}, {"", "inelastic collapse at t = 0.1 s", ""});
  EXPECT_EQ(v.runs, 3);
  EXPECT_EQ(v.failed, 1);
  EXPECT_EQ(v.failure, "inelastic collapse at t = 0.1 s");
  EXPECT_EQ(v.state.of, 2);
  EXPECT_EQ(v.state.value, "crystal");  // tie: the first seed's
  EXPECT_FALSE(v.seedsAgree());
}

TEST(SeedVote, UnclassifiedRunVotesForThePeriodOnly) {
  LayerPatterns short_run;
  short_run.period = 2;  // available = false: too few cycles to classify
  const LayerVerdict v =
      voteOverSeeds({short_run, classified("amorphous", 2, true)}, {true, true}, {"", ""});
  EXPECT_EQ(v.period.of, 2);
  EXPECT_EQ(v.period.count, 2);
  EXPECT_EQ(v.state.of, 1);
  EXPECT_TRUE(v.classified());
}

TEST(SeedVote, WavesAndKinksAreMajorityVotesAndNumbersAreMeansOverTheClassifiedSeeds) {
  const LayerVerdict v = voteOverSeeds({classified("liquid-like", 2, true, 0, 0.6, 0.1),
                                        classified("liquid-like", 2, true, 1, 0.7, 0.2),
                                        classified("liquid-like", 1, false, 0, 0.8, 0.3)},
                                       {true, true, true}, {"", "", ""});
  EXPECT_TRUE(v.surface_wave.value);
  EXPECT_EQ(v.surface_wave.count, 2);
  EXPECT_FALSE(v.kinks.value);
  EXPECT_EQ(v.kinks.count, 2);
  EXPECT_NEAR(v.psi6, 0.7, 1e-12);
  EXPECT_NEAR(v.bonds_kept, 0.2, 1e-12);
  EXPECT_NEAR(v.surface_wave_amplitude_d, 1.5, 1e-12);  // over the seeds with the wave
  EXPECT_EQ(v.surface_wave_mode, 2);
  EXPECT_EQ(v.period.value, 2);
}

TEST(SeedVote, SeedsThatAllFailOrAnswerNothingDoNotDisagree) {
  const LayerVerdict all_failed =
      voteOverSeeds({LayerPatterns{}, LayerPatterns{}}, {false, false}, {"a", "b"});
  EXPECT_FALSE(all_failed.classified());
  EXPECT_TRUE(all_failed.seedsAgree());
  LayerPatterns short_run;
  short_run.period = 1;  // not classified: no state, waves or kinks voted on
  EXPECT_TRUE(voteOverSeeds({short_run, short_run}, {true, true}, {"", ""}).seedsAgree());
}

TEST(SeedVote, MismatchedInputsAreRejected) {
  EXPECT_THROW(voteOverSeeds({classified("crystal", 1)}, {true, true}, {"", ""}),
               std::invalid_argument);
}

}  // namespace
}  // namespace granwave
