// The tiny sound-speed study (tests/studies/data/tiny-sound-speed.toml): what must hold for
// every impact front whatever the run length.
//
// Gas dynamics of the predictions, evaluated on the measured state ahead of each front
// (Landau & Lifshitz, Fluid Mechanics, Secs. 64, 84-89; hydro/ShockRelations.hpp):
//   - c_T < c_s: the isothermal sound speed is the adiabatic one over sqrt(gamma), gamma > 1;
//   - c_s < s_RH: a compressive shock moves supersonically into the gas ahead (Lax);
//   - s_strong < s_RH: the same piston drives a faster shock into gas with a temperature.
// Mass conservation across a front that compacts the gas (area fraction nu_a ahead, nu_b
// behind, piston U_p): w = U_p nu_b / (nu_b - nu_a) >= U_p nu_max / (nu_max - nu_a), the
// compaction-front speed, since nu_b <= nu_max (close packing). The measured w must not fall
// below it by more than 2 combined sigma (the fronts' fit and block errors and the spread of
// the prediction over the blocks: the errors the study states).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "tests/studies/contract/TinyStudy.hpp"

namespace {

constexpr char kKind[] = "sound-speed";
using SoundSpeedResults = granwave::testing::TinyStudyTest<kKind>;
const std::string kRoot = "/results/sound_speed/theory_";

std::vector<double> predicted(int k) {
  return SoundSpeedResults::study().series(kRoot + std::to_string(k) + "/predicted");
}

TEST_F(SoundSpeedResults, EachLawShowsImpactFrontsComparedWithEveryTheory) {
  const auto w = study().series("/results/sound_speed/front_speed_relative");
  ASSERT_GE(w.size(), 2u) << "fewer impact fronts than laws";
  for (int k = 0; k < 5; ++k) EXPECT_EQ(predicted(k).size(), w.size()) << "theory " << k;
}

TEST_F(SoundSpeedResults, PredictionsOrderAsGasDynamicsRequiresForEveryFront) {
  const auto cs = predicted(0), cT = predicted(1), rh = predicted(2), strong = predicted(3);
  ASSERT_FALSE(cs.empty());
  for (std::size_t i = 0; i < cs.size(); ++i) {
    EXPECT_GT(cT[i], 0) << "front " << i;
    EXPECT_LT(cT[i], cs[i]) << "front " << i << ": c_T must be below c_s (gamma > 1)";
    EXPECT_GT(rh[i], cs[i]) << "front " << i << ": a shock is supersonic into the gas ahead";
    EXPECT_LT(strong[i], rh[i]) << "front " << i << ": a warmer gas ahead gives a faster shock";
  }
}

TEST_F(SoundSpeedResults, CompactingFrontsAreNoSlowerThanTheCompactionFrontWithinTheirErrors) {
  // theory_5 (mass conservation) lists the fronts whose gas behind is denser than ahead.
  const auto compacting = study().series(kRoot + "5/measured");
  const auto w = study().series(kRoot + "4/measured");
  const auto w_err = study().series(kRoot + "4/measured_error");
  const auto bound = predicted(4);
  const auto bound_err = study().series(kRoot + "4/predicted_error");
  ASSERT_FALSE(compacting.empty()) << "no front compacts the gas";
  int checked = 0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    bool listed = false;
    for (double c : compacting) listed |= c == w[i];
    if (!listed) continue;
    ++checked;
    const double sigma = std::hypot(w_err[i], bound_err[i]);
    EXPECT_GT(w[i], bound[i] - 2 * sigma)
        << "front " << i << ": w = " << w[i] << " m/s, compaction bound " << bound[i] << " +- "
        << bound_err[i];
  }
  EXPECT_EQ(checked, static_cast<int>(compacting.size()));
}

}  // namespace
