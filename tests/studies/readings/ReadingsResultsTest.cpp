// The tiny readings study (tests/studies/data/tiny-readings.toml): readings "as built"
// (kappa in m/s, smooth, rolling) and "kappa cm/s", at 10 Hz, Gamma = 4 and 40 Hz,
// Gamma = 5, two seeds, 30 cycles.
//
// - The cost of a kappa reading is analytic: e_dry(1 m/s) = 1 - kappa u^(-1/5) with the
//   paper's kappa = 0.1 and u = 1 m/s or 1 cm/s: 0.9 and 1 - 0.1 * 100^(1/5) = 0.74881.
// - kappa enters the dry law only (paper, eq. drycor): the wet layer of the cm/s reading is
//   the same layer as today's, so its numbers are identical, while the dry layer, losing
//   more per impact, is a different one.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tests/studies/contract/TinyStudy.hpp"

namespace {

constexpr char kKind[] = "readings";
using ReadingsResults = granwave::testing::TinyStudyTest<kKind>;
const std::string kRoot = "/results/readings";

TEST_F(ReadingsResults, KappaReadingsCostTheDryRestitutionTheLawPredicts) {
  EXPECT_NEAR(study().value(kRoot + "/reading_0", "e_dry_1ms"), 0.9, 1e-12);
  EXPECT_NEAR(study().value(kRoot + "/reading_1", "e_dry_1ms"), 1 - 0.1 * std::pow(100.0, 0.2),
              1e-12);
  EXPECT_NEAR(study().value(kRoot + "/reading_1", "e_dry_1ms"), 0.7488, 1e-4);
}

TEST_F(ReadingsResults, KappaUnitChangesTheDryLayerAndLeavesTheWetOneAlone) {
  // Bit for bit, a value missing in both (a front the tiny runs do not resolve) included.
  for (const char* key : {"tc_elastic_share_wet", "period2_fraction_wet", "minimum_phase_wet",
                          "weak_front", "strong_front"}) {
    const double a = study().value(kRoot + "/reading_0", key);
    const double b = study().value(kRoot + "/reading_1", key);
    EXPECT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << key << ": " << a << " " << b;
  }
  EXPECT_TRUE(std::isfinite(study().value(kRoot + "/reading_0", "minimum_phase_wet")));
  EXPECT_NE(study().value(kRoot + "/reading_0", "tc_elastic_share_dry"),
            study().value(kRoot + "/reading_1", "tc_elastic_share_dry"));
}

TEST_F(ReadingsResults, EveryReadingHasAVerdictForEveryStatement) {
  const auto verdicts = study().series(kRoot + "/verdicts");
  ASSERT_EQ(verdicts.size(), 2u * 10u);
  for (double v : verdicts) EXPECT_TRUE(v >= 0 && v <= 3) << v;
}

}  // namespace
