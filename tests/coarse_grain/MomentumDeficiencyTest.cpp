// Deficiency factor r_x = RMS(v_x)_dry / RMS(v_x)_wet on profiles of known ratio.
#include <gtest/gtest.h>

#include <cmath>

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

namespace {
// Two phases of three rows; dry RMS = 2 x wet in every row, the area fraction 0.5.
PhaseFields layer(double rms) {
  PhaseFields f;
  f.phases = 2;
  f.nz = 3;
  f.nx = 1;
  f.profile_rms_velocity_x.assign(6, rms);
  f.profile_area_fraction.assign(6, 0.5);
  return f;
}
}  // namespace

TEST(MomentumDeficiency, RowsTooDiluteInEitherLayerAreLeftOut) {
  PhaseFields dry = layer(0.2), wet = layer(0.1);
  dry.profile_rms_velocity_x[0] = 0.9;  // row 0 of phase 0: dilute in the dry layer
  dry.profile_area_fraction[0] = 0.01;
  dry.profile_rms_velocity_x[4] = 0.9;  // row 1 of phase 1: dilute in the wet layer
  wet.profile_area_fraction[4] = 0.01;
  DeficiencyOptions o;
  o.min_area_fraction = 0.1;
  const Deficiency r = momentumDeficiency(dry, wet, o);
  EXPECT_TRUE(std::isnan(r.ratio[0]));
  EXPECT_TRUE(std::isnan(r.ratio[4]));
  EXPECT_NEAR(r.mean, 2.0, 1e-12);
  EXPECT_NEAR(momentumDeficiency(dry, wet).row_mean[0], (9.0 + 2 + 2) / 3, 1e-12);  // no cut
}

TEST(MomentumDeficiency, ShiftedDryLayerIsReadThatManyPhasesLater) {
  PhaseFields dry = layer(0.2), wet = layer(0.1);
  for (int j = 0; j < 3; ++j) dry.profile_rms_velocity_x[dry.row(1, j)] = 0.3;
  DeficiencyOptions o;
  o.dry_shift = 1;  // wet phase 0 against dry phase 1, wet phase 1 against dry phase 0 (cyclic)
  const Deficiency r = momentumDeficiency(dry, wet, o);
  EXPECT_NEAR(r.row_mean[0], 3.0, 1e-12);
  EXPECT_NEAR(r.row_mean[1], 2.0, 1e-12);
}

TEST(MomentumDeficiency, OneBlockIsComparedOnTheRowsThePooledFieldsKeep) {
  const PhaseFields dry = layer(0.2), wet = layer(0.1);
  PhaseFields dry_block = layer(0.3), wet_block = layer(0.1);
  dry_block.profile_area_fraction.assign(6, 0.0);  // a block's own density does not decide
  DeficiencyOptions o;
  o.min_area_fraction = 0.1;
  EXPECT_NEAR(momentumDeficiency(dry, wet, o, &dry_block, &wet_block).mean, 3.0, 1e-12);
}
