// How far a continuum run's answers moved from its base run's (studies/continuum_sensitivity/
// ContinuumSensitivityAnalysis.hpp), on made-up answers: the relative change of a matched
// front's transit speeds, which decides, and of its fitted speed, shown with that change in
// units of the two fits' combined error.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "studies/continuum_sensitivity/ContinuumSensitivityAnalysis.hpp"

using namespace granwave;

namespace {

SensitivityAnswer answer(double speed, double fit_error, std::vector<SensitivityTransit> t = {}) {
  SensitivityAnswer a;
  a.ok = true;
  a.period = 1;
  a.com_low = 0.01;
  a.com_high = 0.03;
  SensitivityFront f;
  f.start = 0.05;
  f.resolved = true;
  f.speed = speed;
  f.fit_error = fit_error;
  f.transits = std::move(t);
  a.fronts.push_back(f);
  return a;
}

}  // namespace

TEST(SensitivityChange, FitChangeIsRelativeAndInUnitsOfTheFitsCombinedError) {
  // 2.0 +- 0.1 against 2.3 +- 0.1 m/s: 15 % and 0.3 / sqrt(0.02) = 2.12 sigma. Without
  // transits the front is judged by its fit.
  const SensitivityChange c = sensitivityChange(answer(2.0, 0.1), answer(2.3, 0.1), 0.05);
  EXPECT_NEAR(c.fit, 0.15, 1e-12);
  EXPECT_NEAR(c.fit_sigma, 0.3 / std::sqrt(0.02), 1e-12);
  EXPECT_NEAR(c.front, 0.15, 1e-12);
  EXPECT_FALSE(c.within);
}

TEST(SensitivityChange, TransitSpeedsDecideWhenTheFitOfADeceleratingTrackMoves) {
  // The fit moves 10 % (the track ended elsewhere), the transits 1 % and 3 %: within.
  const SensitivityChange c =
      sensitivityChange(answer(2.18, 0.07, {{true, true, 90.0}, {true, true, 6.0}}),
                        answer(2.40, 0.08, {{true, true, 90.9}, {true, true, 6.18}}), 0.05);
  EXPECT_NEAR(c.fit, 0.22 / 2.18, 1e-12);
  EXPECT_NEAR(c.front, 0.03, 1e-12);
  EXPECT_TRUE(c.within);
  // A transit the base resolves at 90 m/s and the run passes faster than the sampling, above
  // 80 m/s: the bound cannot tell them apart, so the change is undetermined (not within).
  const SensitivityChange unknown =
      sensitivityChange(answer(2.18, 0.07, {{true, true, 90.0}, {true, true, 6.0}}),
                        answer(2.18, 0.07, {{true, false, 80.0}, {true, true, 6.0}}), 0.05);
  EXPECT_TRUE(std::isnan(unknown.front));
  EXPECT_FALSE(unknown.within);
  // A later front with a measured change keeps the verdict undetermined.
  SensitivityAnswer base2 = answer(2.18, 0.07, {{true, true, 90.0}, {true, true, 6.0}});
  SensitivityAnswer run2 = answer(2.18, 0.07, {{true, false, 80.0}, {true, true, 6.0}});
  SensitivityFront later = base2.fronts.front();
  later.start = 0.5;
  base2.fronts.push_back(later);
  later.transits[1].speed = 6.1;
  run2.fronts.push_back(later);
  EXPECT_TRUE(std::isnan(sensitivityChange(base2, run2, 0.05).front));
  // Above 150 m/s: more than the tolerance faster, changed.
  const SensitivityChange faster =
      sensitivityChange(answer(2.18, 0.07, {{true, true, 90.0}, {true, true, 6.0}}),
                        answer(2.18, 0.07, {{true, false, 150.0}, {true, true, 6.0}}), 0.05);
  EXPECT_TRUE(std::isinf(faster.front));
  EXPECT_FALSE(faster.within);
  // Both faster than the sampling: no change from that transit.
  const SensitivityChange both =
      sensitivityChange(answer(2.18, 0.07, {{true, false, 120.0}, {true, true, 6.0}}),
                        answer(2.18, 0.07, {{true, false, 150.0}, {true, true, 6.1}}), 0.05);
  EXPECT_NEAR(both.front, 0.1 / 6.0, 1e-12);
  // The run's front no longer reaches the upper fraction: changed.
  const SensitivityChange short_track =
      sensitivityChange(answer(2.18, 0.07, {{true, true, 90.0}, {true, true, 6.0}}),
                        answer(2.18, 0.07, {{true, true, 90.0}, {false, false, 0.0}}), 0.05);
  EXPECT_TRUE(std::isinf(short_track.front));
}

TEST(SensitivityChange, BaseAgainstItselfHasNoChangeAndZeroSigma) {
  const SensitivityChange c = sensitivityChange(answer(2.0, 0.1), answer(2.0, 0.1), 0.05);
  EXPECT_EQ(c.front, 0.0);
  EXPECT_EQ(c.fit_sigma, 0.0);
  EXPECT_TRUE(c.within);
}

TEST(SensitivityChange, SigmaIsThatOfTheFrontWithTheLargestChangeAndNoneWhenOneVanishes) {
  // Two fronts: the first moves 10 % with large errors (0.2 / sqrt(0.08) = 0.71 sigma), the
  // second 5 % with small ones (7.1 sigma): the sigma is the first's, the largest relative
  // change.
  SensitivityAnswer base = answer(2.0, 0.2), run = answer(2.2, 0.2);
  SensitivityFront second = base.fronts.front();
  second.start = 0.5;
  second.fit_error = 0.01;
  base.fronts.push_back(second);
  second.speed = 2.1;
  run.fronts.push_back(second);
  const SensitivityChange c = sensitivityChange(base, run, 0.05);
  EXPECT_NEAR(c.fit, 0.1, 1e-12);
  EXPECT_NEAR(c.fit_sigma, 0.2 / std::sqrt(0.08), 1e-12);
  // The second front unresolved in the run: a front changed its kind, no sigma is given.
  run.fronts.back().resolved = false;
  const SensitivityChange gone = sensitivityChange(base, run, 0.05);
  EXPECT_TRUE(std::isinf(gone.front));
  EXPECT_TRUE(std::isnan(gone.fit_sigma));
}

TEST(SensitivityChange, FrontsWithoutFitErrorsHaveNoSignificance) {
  const SensitivityChange c = sensitivityChange(answer(2.0, 0.0), answer(2.02, 0.0), 0.05);
  EXPECT_NEAR(c.front, 0.01, 1e-12);
  EXPECT_TRUE(std::isnan(c.fit_sigma));
  EXPECT_TRUE(c.within);
}
