// How far a continuum run's answers moved from its base run's (studies/continuum_sensitivity/
// ContinuumSensitivityAnalysis.hpp), on made-up answers: the relative change of a matched
// front and that change in units of the two fits' combined error.
#include <gtest/gtest.h>

#include <cmath>

#include "studies/continuum_sensitivity/ContinuumSensitivityAnalysis.hpp"

using namespace granwave;

namespace {

SensitivityAnswer answer(double speed, double fit_error) {
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
  a.fronts.push_back(f);
  return a;
}

}  // namespace

TEST(SensitivityChange, FrontChangeIsRelativeAndInUnitsOfTheFitsCombinedError) {
  // 2.0 +- 0.1 against 2.3 +- 0.1 m/s: 15 % and 0.3 / sqrt(0.02) = 2.12 sigma.
  const SensitivityChange c = sensitivityChange(answer(2.0, 0.1), answer(2.3, 0.1), 0.05);
  EXPECT_NEAR(c.front, 0.15, 1e-12);
  EXPECT_NEAR(c.front_sigma, 0.3 / std::sqrt(0.02), 1e-12);
  EXPECT_FALSE(c.within);
}

TEST(SensitivityChange, BaseAgainstItselfHasNoChangeAndZeroSigma) {
  const SensitivityChange c = sensitivityChange(answer(2.0, 0.1), answer(2.0, 0.1), 0.05);
  EXPECT_EQ(c.front, 0.0);
  EXPECT_EQ(c.front_sigma, 0.0);
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
  EXPECT_NEAR(c.front, 0.1, 1e-12);
  EXPECT_NEAR(c.front_sigma, 0.2 / std::sqrt(0.08), 1e-12);
  // The second front unresolved in the run: a front changed its kind, no sigma is given.
  run.fronts.back().resolved = false;
  const SensitivityChange gone = sensitivityChange(base, run, 0.05);
  EXPECT_TRUE(std::isinf(gone.front));
  EXPECT_TRUE(std::isnan(gone.front_sigma));
}

TEST(SensitivityChange, FrontsWithoutFitErrorsHaveNoSignificance) {
  const SensitivityChange c = sensitivityChange(answer(2.0, 0.0), answer(2.02, 0.0), 0.05);
  EXPECT_NEAR(c.front, 0.01, 1e-12);
  EXPECT_TRUE(std::isnan(c.front_sigma));
  EXPECT_TRUE(c.within);
}
