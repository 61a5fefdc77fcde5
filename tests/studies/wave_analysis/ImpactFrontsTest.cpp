// How the weak and strong impact fronts of a run are told apart and combined over seeds, and
// the collision time from the centre of mass.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "studies/wave_analysis/ImpactFronts.hpp"

using granwave::Measurement;

namespace {

// A front starting at t/T = `start` of a two-cycle window sampled at t/T = k/100.
struct Front {
  double start, speed, error, peak;
  bool impact = true;
};

granwave::PhaseProfiles window(const std::vector<Front>& fronts) {
  granwave::PhaseProfiles p;
  p.pooled.phases = 200;
  for (int k = 0; k < 200; ++k) p.phase.push_back(k / 100.0);
  for (const Front& f : fronts) {
    granwave::FrontEpisode e;
    e.first_phase = static_cast<int>(std::lround(f.start * 100));
    e.speed = f.speed;
    e.speed_error = f.error;
    e.peak_temperature = f.peak;
    e.from_impact = f.impact;
    p.fronts.push_back(e);
  }
  return p;
}

granwave::ImpactFronts impactFronts(const std::vector<Front>& fronts) {
  return granwave::impactFronts(window(fronts));
}

}  // namespace

TEST(StudyImpactFronts, WeakImpactIsTheFrontWithTheLowerPeak) {
  // The strong front comes first in the window and is the slower one: order and speed must
  // not decide, only the peak.
  const granwave::ImpactFronts r = impactFronts({{0.4, 1.2, 0.1, 6.0}, {1.4, 1.9, 0.2, 2.5}});
  EXPECT_EQ(r.count, 2);
  EXPECT_DOUBLE_EQ(r.weak.value, 1.9);
  EXPECT_DOUBLE_EQ(r.weak.error, 0.2);
  EXPECT_DOUBLE_EQ(r.weak_start, 1.4);
  EXPECT_DOUBLE_EQ(r.strong.value, 1.2);
  EXPECT_DOUBLE_EQ(r.strong.error, 0.1);
  EXPECT_DOUBLE_EQ(r.strong_start, 0.4);
  const Measurement all = granwave::combine({{1.2, 0.1}, {1.9, 0.2}});
  EXPECT_DOUBLE_EQ(r.all.value, all.value);
  EXPECT_DOUBLE_EQ(r.all.error, all.error);
}

TEST(StudyImpactFronts, FrontsNotFromAnImpactAreIgnored) {
  const granwave::ImpactFronts r = impactFronts({{0.1, 5.0, 0.1, 0.5, false},
                                                 {0.4, 1.2, 0.1, 6.0},
                                                 {0.7, 9.0, 0.1, 50, false},
                                                 {1.4, 1.9, 0.2, 2.5}});
  EXPECT_EQ(r.count, 2);
  EXPECT_DOUBLE_EQ(r.weak.value, 1.9);
  EXPECT_DOUBLE_EQ(r.strong.value, 1.2);
}

TEST(StudyImpactFronts, SingleImpactFrontStandsForBothImpacts) {
  const granwave::ImpactFronts r =
      impactFronts({{0.9, 1.5, 0.1, 3.0}, {0.2, 4.0, 0.1, 9.0, false}});
  EXPECT_EQ(r.count, 1);
  EXPECT_DOUBLE_EQ(r.weak.value, 1.5);
  EXPECT_DOUBLE_EQ(r.strong.value, 1.5);
  EXPECT_DOUBLE_EQ(r.weak_start, 0.9);
  EXPECT_DOUBLE_EQ(r.strong_start, 0.9);
  EXPECT_DOUBLE_EQ(r.all.value, 1.5);
}

TEST(StudyImpactFronts, NoImpactFrontGivesInvalidSpeeds) {
  const granwave::ImpactFronts r = impactFronts({{0.2, 4.0, 0.1, 9.0, false}});
  EXPECT_EQ(r.count, 0);
  EXPECT_FALSE(r.weak.valid());
  EXPECT_FALSE(r.strong.valid());
  EXPECT_FALSE(r.all.valid());
  EXPECT_EQ(r.weak_start, granwave::ImpactFronts::kNoPhase);
}

TEST(StudyImpactFronts, CombiningRunsCombinesEachImpactSeparately) {
  const granwave::ImpactFronts a = impactFronts({{0.4, 1.0, 0.1, 6.0}, {1.4, 2.0, 0.1, 2.5}});
  const granwave::ImpactFronts b = impactFronts({{0.5, 1.1, 0.1, 6.0}, {1.5, 2.1, 0.1, 2.5}});
  const granwave::ImpactFronts r = granwave::combineImpactFronts({a, b});
  EXPECT_EQ(r.count, 4);
  EXPECT_NEAR(r.weak.value, 2.05, 1e-12);
  EXPECT_NEAR(r.strong.value, 1.05, 1e-12);
  EXPECT_DOUBLE_EQ(r.weak_start, 1.4);  // the first run's
}

TEST(StudyImpactFronts, CenterOfMassMinimumPhasesFindTheLowestPointOfEachCycle) {
  // A two-cycle window, 50 phases per cycle, centre of mass z = 5 + cos(2 pi (t/T - 0.3)):
  // lowest at t/T = 0.8 and 1.8, i.e. 0.8 in both cycles.
  granwave::PhaseProfiles p;
  p.pooled.phases = 100;
  for (int k = 0; k < p.phases(); ++k) {
    const double t = 2.0 * k / p.phases();
    p.phase.push_back(t);
    p.pooled.center_of_mass_height.push_back(5 + std::cos(2 * std::numbers::pi * (t - 0.3)));
  }
  const std::vector<double> phases = granwave::centerOfMassMinimumPhases(p, 2);
  ASSERT_EQ(phases.size(), 2u);
  EXPECT_NEAR(phases[0], 0.8, 1e-12);
  EXPECT_NEAR(phases[1], 0.8, 1e-12);
  // One cycle per window: the window's single lowest point.
  const std::vector<double> one = granwave::centerOfMassMinimumPhases(p, 1);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_NEAR(one[0], 0.8, 1e-12);
}

TEST(StudyImpactFronts, CenterOfMassMinimumPhasesOfAnEmptyWindowAreNone) {
  granwave::PhaseProfiles p;
  EXPECT_TRUE(granwave::centerOfMassMinimumPhases(p, 2).empty());
  p.pooled.phases = 1;
  p.phase = {0.0};
  p.pooled.center_of_mass_height = {1.0};
  EXPECT_TRUE(granwave::centerOfMassMinimumPhases(p, 0).empty());
  EXPECT_TRUE(granwave::centerOfMassMinimumPhases(p, 2).empty());
}
