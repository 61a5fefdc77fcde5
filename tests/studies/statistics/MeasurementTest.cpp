// How measurements combine (inverse-variance mean with the PDG scale factor) and print.
#include <gtest/gtest.h>

#include <limits>

#include "studies/statistics/Measurement.hpp"

using granwave::Measurement;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

TEST(StudyMeasurement, CombiningTwoConsistentEqualErrorValuesGivesTheMeanAndSigmaOverSqrt2) {
  const Measurement m = granwave::combine({{1.0, 0.1}, {1.1, 0.1}});
  EXPECT_NEAR(m.value, 1.05, 1e-12);
  EXPECT_NEAR(m.error, 0.1 / std::sqrt(2.0), 1e-12);  // chi^2 / (n - 1) = 0.5: not scaled
}

TEST(StudyMeasurement, InverseVarianceWeightsFavourTheMorePreciseValue) {
  const Measurement m = granwave::combine({{1.0, 0.1}, {1.1, 0.2}});
  // weights 100 and 25; chi^2 = 0.8 < 1, so no scale factor
  EXPECT_NEAR(m.value, (100 * 1.0 + 25 * 1.1) / 125, 1e-12);
  EXPECT_NEAR(m.error, 1 / std::sqrt(125.0), 1e-12);
}

TEST(StudyMeasurement, ScatteredValuesScaleTheErrorBySqrtChi2PerDegreeOfFreedom) {
  const Measurement m = granwave::combine({{1.0, 0.1}, {2.0, 0.1}, {3.0, 0.1}});
  EXPECT_NEAR(m.value, 2.0, 1e-12);
  const double chi2 = 100 + 0 + 100;
  EXPECT_NEAR(m.error, 0.1 / std::sqrt(3.0) * std::sqrt(chi2 / 2), 1e-12);
}

TEST(StudyMeasurement, InvalidEntriesAreIgnored) {
  const Measurement with = granwave::combine({{1.0, 0.1}, {kNaN, 0.1}, {1.1, 0.1}, {}});
  const Measurement without = granwave::combine({{1.0, 0.1}, {1.1, 0.1}});
  EXPECT_DOUBLE_EQ(with.value, without.value);
  EXPECT_DOUBLE_EQ(with.error, without.error);
}

TEST(StudyMeasurement, EntryWithoutErrorCountsWithTheMeanErrorOfTheOthers) {
  const Measurement m = granwave::combine({{1.0, 0.1}, {1.1, kNaN}});
  EXPECT_NEAR(m.value, 1.05, 1e-12);
  EXPECT_NEAR(m.error, 0.1 / std::sqrt(2.0), 1e-12);
}

TEST(StudyMeasurement, NoValidEntryGivesAnInvalidResult) {
  EXPECT_FALSE(granwave::combine({}).valid());
  EXPECT_FALSE(granwave::combine({{kNaN, 0.1}, {}}).valid());
}

TEST(StudyMeasurement, SigmaDistanceIsTheDifferenceInCombinedSigmas) {
  EXPECT_NEAR(granwave::sigmaDistance({3.0, 0.3}, {1.0, 0.4}), 4.0, 1e-12);
  EXPECT_NEAR(granwave::sigmaDistance({1.0, 0.3}, {3.0, 0.4}), -4.0, 1e-12);
  EXPECT_NEAR(granwave::sigmaDistance({3.0, kNaN}, {1.0, 0.5}), 4.0, 1e-12);  // no error: 0
  EXPECT_TRUE(std::isnan(granwave::sigmaDistance({3.0, 0.0}, {1.0, 0.0})));
}

TEST(StudyMeasurement, FormatPrintsValuePlusMinusErrorOrADashWhenInvalid) {
  EXPECT_EQ(granwave::format({1.64, 0.45}), "1.64 ± 0.45");
  EXPECT_EQ(granwave::format({1.6449, 0.4451}), "1.64 ± 0.45");
  EXPECT_EQ(granwave::format({1.64, 0.45}, 3), "1.640 ± 0.450");
  EXPECT_EQ(granwave::format({1.64, kNaN}), "1.64");
  // Small numbers keep two significant digits of their error instead of printing 0.00000.
  EXPECT_EQ(granwave::format({3.4e-7, 1.2e-7}), "(3.4 ± 1.2)e-7");
  EXPECT_EQ(granwave::format({-5.5e-6, 1.3e-7}), "(-5.50 ± 0.13)e-6");
  EXPECT_EQ(granwave::format({1.64, 0.45}, 2, "m/s"), "1.64 ± 0.45 m/s");
  EXPECT_EQ(granwave::format(Measurement{}), "–");
  EXPECT_EQ(granwave::formatNumber(kNaN), "–");
  EXPECT_EQ(granwave::formatNumber(0.125, 1), "0.1");
}

// An error as large as the value leaves neither its size nor its sign measured: the report
// gives the one-sigma bound |value| + error and says why, never "1.04 ± 1.04".
TEST(StudyMeasurement, FormatGivesABoundWhenTheErrorIsAsLargeAsTheValue) {
  EXPECT_EQ(granwave::format({1.04, 1.04}), "< 2.1 (not resolved: error ≥ value)");
  EXPECT_EQ(granwave::format({1.04, 1.04}, 2, "m/s"), "< 2.1 m/s (not resolved: error ≥ value)");
  EXPECT_EQ(granwave::format({-3.2, 5.58}), "> -8.8 (not resolved: error ≥ value)");
  EXPECT_EQ(granwave::format({0.0, 0.031}), "< 0.031 (not resolved: error ≥ value)");
  EXPECT_EQ(granwave::format({1.2e-7, 3.4e-7}), "< 4.6e-7 (not resolved: error ≥ value)");
  EXPECT_EQ(granwave::format({1.64, 1.63}), "1.64 ± 1.63");  // just resolved
  // Seeds that agree exactly have no spread: not "0.00 ± 0.00".
  EXPECT_EQ(granwave::format({0.0, 0.0}), "0.00 (error 0: no spread)");
}

TEST(StudyMeasurement, FormatOrGivesTheReasonWhenThereIsNoValue) {
  EXPECT_EQ(granwave::formatOr(Measurement{}, "none: no front"), "none: no front");
  EXPECT_EQ(granwave::formatOr({1.64, 0.45}, "none: no front", 2, "m/s"), "1.64 ± 0.45 m/s");
}
