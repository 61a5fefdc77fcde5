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

// A front's transits: a speed (error > 0), or a bound (error 0 stands for "a bound"), or, with
// neither, a front that does not reach the fractions.
TransitSpeeds transit(double speed, double error) {
  TransitSpeeds t;
  t.fronts = 1;
  if (!std::isfinite(speed)) return t;
  t.reached = 1;
  if (error > 0) {
    t.speed = {speed, error};
    t.resolved = 1;
  } else {
    t.lower_bound = speed;
  }
  return t;
}

VelocityFronts fronts(const TransitSpeeds& dense, const TransitSpeeds& upper,
                      Measurement fit = {}) {
  VelocityFronts v;
  v.speed = fit;
  v.transit[0] = dense;
  v.transit[1] = upper;
  return v;
}

TEST(SweepTransitMatch, BothTransitsWithinTheToleranceAndTheSamePeriodReproduce) {
  std::string why;
  // 2.0 +- 0.05 against 2.1 +- 0.05 (as above); 1.0 +- 0.02 against 1.05 +- 0.02: gap 0.05 +
  // 1.96 * 0.028 = 0.105 < 0.1575.
  EXPECT_EQ(sweepTransitMatch(fronts(transit(2.0, 0.05), transit(1.0, 0.02)), 1,
                              fronts(transit(2.1, 0.05), transit(1.05, 0.02)), {1, 1}, 0.15, why),
            Match::yes);
  EXPECT_EQ(why, "transits (mass 0.1-0.5: -5 +- 3 %; mass 0.5-0.9: -5 +- 3 %) and period");
}

TEST(SweepTransitMatch, TheTransitFarthestOffDecidesWhateverTheFitSays) {
  std::string why;
  // The upper part 30 % too fast; the fits agree exactly.
  EXPECT_EQ(sweepTransitMatch(fronts(transit(2.0, 0.05), transit(1.3, 0.02), {2.0, 0.05}), 1,
                              fronts(transit(2.0, 0.05), transit(1.0, 0.02), {2.0, 0.05}), {1},
                              0.15, why),
            Match::no);
}

TEST(SweepTransitMatch, ATransitTheParticlesFrontsDoNotReachIsLeftOut) {
  std::string why;
  EXPECT_EQ(sweepTransitMatch(fronts(transit(2.0, 0.05), transit(1.3, 0.02)), 1,
                              fronts(transit(2.0, 0.05), transit(NAN, 0)), {1}, 0.15, why),
            Match::yes);
  EXPECT_NE(why.find("the particles' fronts do not reach it"), std::string::npos) << why;
}

TEST(SweepTransitMatch, AContinuumFrontThatStopsBelowATransitTheParticlesMakeDoesNotReproduce) {
  std::string why;
  EXPECT_EQ(sweepTransitMatch(fronts(transit(2.0, 0.05), transit(NAN, 0)), 1,
                              fronts(transit(2.0, 0.05), transit(1.0, 0.02)), {1}, 0.15, why),
            Match::no);
  EXPECT_NE(why.find("stops below it"), std::string::npos) << why;
}

TEST(SweepTransitMatch, ABoundDiffersOnlyBeyondTheToleranceAndOtherwiseStaysOpen) {
  std::string why;
  const TransitSpeeds upper = transit(1.0, 0.02);
  // The continuum crosses the dense half faster than 14 m/s, the particles at 2.0 +- 0.05.
  EXPECT_EQ(sweepTransitMatch(fronts(transit(14, 0), upper), 1, fronts(transit(2.0, 0.05), upper),
                              {1}, 0.15, why),
            Match::no);
  // A bound of 2.1 m/s: the particles' 2.0 +- 0.05 may be reached by a speed above it.
  EXPECT_EQ(sweepTransitMatch(fronts(transit(2.1, 0), upper), 1, fronts(transit(2.0, 0.05), upper),
                              {1}, 0.15, why),
            Match::not_yet);
  // The particles' bound 100 m/s against a continuum at 5 m/s: far too slow.
  EXPECT_EQ(sweepTransitMatch(fronts(transit(5.0, 0.5), upper), 1, fronts(transit(100, 0), upper),
                              {1}, 0.15, why),
            Match::no);
}

TEST(SweepTransitMatch, AParticleTransitWithoutAnErrorLeavesTheVerdictOpenHoweverClose) {
  std::string why;
  const TransitSpeeds upper = transit(1.0, 0.02);
  TransitSpeeds dense = transit(2.0, 0.05);
  dense.speed.error = NAN;  // fewer than half of the bootstrap's resamples resolve it
  EXPECT_EQ(
      sweepTransitMatch(fronts(transit(2.0, 0.05), upper), 1, fronts(dense, upper), {1}, 0.15, why),
      Match::not_yet);
  EXPECT_NE(why.find("+0 %, the particles' without an error"), std::string::npos) << why;
}

TEST(SweepTransitMatch, WithoutATransitToCompareTheFitJudges) {
  std::string why;
  const TransitSpeeds none = transit(NAN, 0);
  EXPECT_EQ(sweepTransitMatch(fronts(none, none, {2.0, 0.05}), 2, fronts(none, none, {2.1, 0.05}),
                              {2, 2}, 0.15, why),
            Match::yes);
  EXPECT_EQ(why.rfind("the fit (front speed and period)", 0), 0u) << why;
}

TEST(SweepTransitMatch, APeriodOtherThanTheSeedsDoesNotReproduceWhateverTheTransits) {
  std::string why;
  const TransitSpeeds dense = transit(2.0, 0.05);
  EXPECT_EQ(sweepTransitMatch(fronts(dense, dense), 1, fronts(dense, dense), {2, 2}, 0.15, why),
            Match::no);
  EXPECT_EQ(why, "period 1 against the particles' 2");
}

}  // namespace
