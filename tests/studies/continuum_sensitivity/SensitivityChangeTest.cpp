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

TEST(SensitivityChange, FrontsWithoutFitErrorsHaveNoSignificance) {
  const SensitivityChange c = sensitivityChange(answer(2.0, 0.0), answer(2.02, 0.0), 0.05);
  EXPECT_NEAR(c.front, 0.01, 1e-12);
  EXPECT_TRUE(std::isnan(c.front_sigma));
  EXPECT_TRUE(c.within);
}
