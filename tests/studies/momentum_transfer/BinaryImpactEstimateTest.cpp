// The collision-weighted binary-impact ratio R = <(1 + e_dry(v)) / (1 + e_wet(v))>
// (studies/momentum_transfer/BinaryImpactEstimate.hpp) on constructed histograms whose answer
// is known in closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "studies/momentum_transfer/BinaryImpactEstimate.hpp"

namespace granwave {
namespace {

// The paper's wet law (Mueller & Huang 2016): e_inf = 0.91, St_c = 40, q = 573.3 s/m.
const Restitution kWet = Restitution::wet(0.91, 40.0, 573.3);

TEST(BinaryImpactEstimate, ImpactsBelowTheWetOnsetGiveThePapersTwo) {
  // All impacts below v_c = 0.0698 m/s: e_wet = 0, and e_dry = 1 gives exactly 2 (Sec. V).
  const ImpactSpeedCounts h{0.06, {5, 7, 11}};
  EXPECT_EQ(lawRatioOverImpacts(h, Restitution::constant(1.0), kWet), 2.0);
}

TEST(BinaryImpactEstimate, TwoSpeedsWeighAsTheirImpactCounts) {
  // Bins of 0.5 m/s: 3 impacts at 0.25 m/s (e_wet = 0 below the onset 0.5 m/s) and one at
  // 0.75 m/s (e_wet = 0.9 (1 - 0.5 / 0.75) = 0.3); e_dry = 0.8 at both.
  const Restitution wet = Restitution::wet(0.9, 0.5, 1.0);  // q = 1 s/m: v_c = St_c = 0.5 m/s
  const ImpactSpeedCounts h{1.0, {3, 1}};
  const double expected = (3 * 1.8 / 1.0 + 1 * 1.8 / 1.3) / 4;
  EXPECT_NEAR(lawRatioOverImpacts(h, Restitution::constant(0.8), wet), expected, 1e-14);
}

TEST(BinaryImpactEstimate, UniformSpeedsGiveTheIntegralOfTheWetLaw) {
  // Impacts spread evenly over (0, V): R = (1 + e_d) / V int_0^V dv / (1 + e_wet(v)). With
  // a = 1 + e_inf, b = e_inf v_c: 1 / (1 + e_wet) = v / (a v - b) above v_c, 1 below, so
  // int = v_c + [v / a + b / a^2 ln(a v - b)] from v_c to V. Bin centres err by O(width^2)
  // (width 0.5 mm/s: ~1e-7 relative) except in the bin that holds the onset's kink
  // (~ its share 1/2000 times the jump of the integrand ~0.1).
  const double V = 1.0, e_d = 0.9, e_inf = 0.91, vc = 40.0 / 573.3;
  const double a = 1 + e_inf, b = e_inf * vc;
  auto F = [&](double v) { return v / a + b / (a * a) * std::log(a * v - b); };
  const double expected = (1 + e_d) / V * (vc + F(V) - F(vc));
  const ImpactSpeedCounts h{V, std::vector<std::uint64_t>(2000, 10)};
  EXPECT_NEAR(lawRatioOverImpacts(h, Restitution::constant(e_d), kWet), expected, 1e-4);
}

TEST(BinaryImpactEstimate, NoImpactsGiveNoValue) {
  EXPECT_TRUE(std::isnan(lawRatioOverImpacts({1.0, {0, 0}}, Restitution::constant(1), kWet)));
}

}  // namespace
}  // namespace granwave
