// How the readings study turns seeds into verdicts: the Wilson score interval (Wilson 1927) at
// z = 1 against its closed form, majority verdicts at the edges, and numbers against the
// paper within 2 sigma.
#include <gtest/gtest.h>

#include <cmath>

#include "studies/readings/ReadingsAnalysis.hpp"

using namespace granwave;

TEST(ReadingVerdict, WilsonIntervalOfFourInFiveMatchesTheClosedForm) {
  // p = 0.8, n = 5, z = 1: centre (0.8 + 0.1) / 1.2 = 0.75, half width
  // sqrt(0.8 * 0.2 / 5 + 1 / 100) / 1.2 = 0.17078.
  const SeedFraction f = seedFraction(4, 5);
  EXPECT_NEAR(f.low, 0.75 - std::sqrt(0.042) / 1.2, 1e-12);
  EXPECT_NEAR(f.high, 0.75 + std::sqrt(0.042) / 1.2, 1e-12);
  EXPECT_EQ(majority(f), Verdict::Holds);
}

TEST(ReadingVerdict, ThreeInFiveIsUndecidedAndNoneInFiveFails) {
  EXPECT_EQ(majority(seedFraction(3, 5)), Verdict::Undecided);
  EXPECT_EQ(majority(seedFraction(2, 5)), Verdict::Undecided);
  EXPECT_EQ(majority(seedFraction(0, 5)), Verdict::Fails);
  EXPECT_EQ(majority(seedFraction(5, 5)), Verdict::Holds);
  EXPECT_EQ(majority(seedFraction(0, 0)), Verdict::NoData);
}

TEST(ReadingVerdict, NumberAgreesWithinTwoCombinedSigmas) {
  // |1.0 - 1.95| = 0.95 > 2 hypot(0.1, 0.25) = 0.539: fails; 1.5 is within.
  EXPECT_EQ(agrees({1.0, 0.1}, 1.95, 0.25), Verdict::Fails);
  EXPECT_EQ(agrees({1.5, 0.1}, 1.95, 0.25), Verdict::Holds);
  EXPECT_EQ(agrees({}, 1.95, 0.25), Verdict::NoData);
}

TEST(ReadingVerdict, NumberLessPreciseThanThePaperCannotHoldButCanFail) {
  // 0.80 +- 1.26 against 1.61 +- 0.25 lies within 2 hypot(1.26, 0.25) = 2.57 but says nothing:
  // undecided. 9.0 +- 1.26 is beyond 2.57 even so: fails.
  EXPECT_EQ(agrees({0.80, 1.26}, 1.61, 0.25), Verdict::Undecided);
  EXPECT_EQ(agrees({9.0, 1.26}, 1.61, 0.25), Verdict::Fails);
  EXPECT_EQ(agrees({1.60, 0.25}, 1.61, 0.25), Verdict::Holds);
}
