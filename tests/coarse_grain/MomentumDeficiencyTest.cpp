// Deficiency factor r_x = RMS(v_x)_dry / RMS(v_x)_wet on profiles of known ratio.
#include <gtest/gtest.h>

#include "coarse_grain/MomentumDeficiency.hpp"

using namespace granwave;

TEST(MomentumDeficiency, RatioOfKnownProfilesAndItsRowMean) {
  PhaseFields dry, wet;
  for (PhaseFields* f : {&dry, &wet}) {
    f->phases = 2;
    f->nz = 3;
    f->nx = 1;
  }
  dry.profile_rms_velocity_x = {0.2, 0.4, kNaN, 0.3, 0.3, 0.3};
  wet.profile_rms_velocity_x = {0.1, 0.2, 0.1, 0.1, 0.15, 1e-5};
  const Deficiency r = momentumDeficiency(dry, wet);
  EXPECT_DOUBLE_EQ(r.ratio[0], 2.0);
  EXPECT_DOUBLE_EQ(r.ratio[1], 2.0);
  EXPECT_TRUE(std::isnan(r.ratio[2]));  // dry undefined
  EXPECT_TRUE(std::isnan(r.ratio[5]));  // wet RMS below min_rms
  EXPECT_DOUBLE_EQ(r.row_mean[0], 2.0);
  EXPECT_DOUBLE_EQ(r.row_mean[1], 2.5);  // (3 + 2) / 2
  EXPECT_DOUBLE_EQ(r.mean, 2.25);
  const Deficiency only_first = momentumDeficiency(dry, wet, {true, false});
  EXPECT_DOUBLE_EQ(only_first.mean, 2.0);
  EXPECT_EQ(only_first.phases_used, 1);
}
