// The cheapest model that reproduces the particles (studies/wave_fronts/CheapestModel.hpp):
// the choice among models judged against the particles, and the judgement of a continuum answer
// at a point of the N sweep.
#include <gtest/gtest.h>

#include <cmath>

#include "studies/wave_fronts/CheapestModel.hpp"

using namespace granwave;

namespace {

ModelCost model(const std::string& name, double cpu, Match match, bool reference = false) {
  ModelCost m;
  m.model = name;
  m.cpu = cpu;
  m.match = match;
  m.reference = reference;
  return m;
}

TEST(CheapestModel, TheCheapestModelShownToReproduceIsNamed) {
  SceneCost s;
  s.models = {model("particles", 10, Match::yes, true), model("hydro A", 2, Match::yes),
              model("hydro B", 1, Match::no), model("particles C", 5, Match::yes)};
  pickCheapest(s);
  EXPECT_EQ(s.cheapest, 1);  // B is cheaper but does not reproduce
  EXPECT_TRUE(s.cheaper_open.empty());
}

TEST(CheapestModel, TheParticlesAreNamedWhenNothingCheaperReproducesAndCheaperOpenOnesAreListed) {
  SceneCost s;
  s.models = {model("particles", 10, Match::yes, true), model("hydro A", 2, Match::not_yet),
              model("hydro B", 1, Match::cannot_tell), model("hydro C", 20, Match::not_yet),
              model("hydro D", 3, Match::no)};
  pickCheapest(s);
  EXPECT_EQ(s.cheapest, 0);
  EXPECT_EQ(s.cheaper_open, (std::vector<int>{1, 2}));  // C costs more than the particles
}

TEST(CheapestModel, AModelWithoutACostIsNeverTheCheapest) {
  SceneCost s;
  s.models = {model("particles", 10, Match::yes, true), model("hydro A", NAN, Match::yes)};
  pickCheapest(s);
  EXPECT_EQ(s.cheapest, 0);
}

TEST(SweepMatch, AContinuumFrontWithinTheToleranceAndTheSamePeriodReproduces) {
  std::string why;
  // 2.0 +- 0.05 against 2.1 +- 0.05: gap 0.1 + 1.96 * 0.071 = 0.24 < 0.15 * 2.1 = 0.315.
  EXPECT_EQ(sweepMatch({2.0, 0.05}, 2, {2.1, 0.05}, NAN, {2, 2}, 0.15, why), Match::yes);
  EXPECT_EQ(why, "front speed and period");
}

TEST(SweepMatch, APeriodOtherThanTheOneEverySeedAgreesOnDoesNotReproduce) {
  std::string why;
  EXPECT_EQ(sweepMatch({2.0, 0.05}, 1, {2.0, 0.05}, NAN, {2, 2}, 0.15, why), Match::no);
  EXPECT_EQ(why, "period 1 against the particles' 2");
}

TEST(SweepMatch, SeedsOfDifferentPeriodsJudgeTheFrontOfAContinuumWithOneOfTheirPeriods) {
  std::string why;
  EXPECT_EQ(sweepMatch({2.0, 0.05}, 4, {2.0, 0.05}, NAN, {2, 4}, 0.15, why), Match::yes);
  EXPECT_NE(why.find("one of the seeds has"), std::string::npos) << why;
  // A period none of them has stays open: the seeds scatter, and two do not rule it out.
  EXPECT_EQ(sweepMatch({2.0, 0.05}, 1, {2.0, 0.05}, NAN, {2, 4}, 0.15, why), Match::not_yet);
}

TEST(CheapestModel, NothingIsCheaperThanParticlesWhoseCostIsUnknown) {
  SceneCost s;
  s.models = {model("particles", NAN, Match::yes, true), model("hydro A", 2, Match::yes)};
  pickCheapest(s);
  EXPECT_EQ(s.cheapest, 0);
}

TEST(SweepMatch, AgainstALowerBoundAFrontFarTooSlowFailsAndAFastOneStaysOpen) {
  std::string why;
  // The particles' front crosses the layer faster than 100 m/s.
  EXPECT_EQ(sweepMatch({5.0, 0.5}, 1, {}, 100, {1}, 0.15, why), Match::no);
  EXPECT_EQ(sweepMatch({120.0, 5.0}, 1, {}, 100, {1}, 0.15, why), Match::not_yet);
}

TEST(SweepMatch, AContinuumWithoutAFrontDoesNotReproduce) {
  std::string why;
  EXPECT_EQ(sweepMatch({}, 1, {2.0, 0.1}, NAN, {1}, 0.15, why), Match::no);
  EXPECT_EQ(why, "no resolved front");
}

}  // namespace
