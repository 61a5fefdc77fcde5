// r_x over the wet wave window (paper Sec. V): on crafted profiles where the dry RMS(v_x) is
// exactly twice the wet one in every dense row, r~_x = 2 with no spread; rows more dilute
// than the threshold, or with a wet RMS below min_rms, are left out.
#include <gtest/gtest.h>

#include <cmath>

#include "studies/wave_analysis/WaveMomentumRatio.hpp"

using namespace granwave;

namespace {
FieldsRecord layer(double rms, int phases, int nz) {
  FieldsRecord r;
  r.cycles_per_window = 1;
  PhaseProfiles& p = r.profiles;
  p.pooled.phases = phases;
  p.pooled.nz = nz;
  const std::size_t n = static_cast<std::size_t>(phases) * nz;
  p.pooled.profile_rms_velocity_x.assign(n, rms);
  p.pooled.profile_area_fraction.assign(n, 0.5);
  for (int k = 0; k < phases; ++k) p.phase.push_back((k + 0.5) / phases);
  return r;
}
}  // namespace

TEST(WaveMomentumRatio, DryTwiceAsAgitatedGivesTwoWithoutSpread) {
  const FieldsRecord dry = layer(0.2, 50, 10), wet = layer(0.1, 50, 10);
  const Measurement r = waveMomentumRatio(dry, wet, {});
  EXPECT_NEAR(r.value, 2.0, 1e-12);
  EXPECT_NEAR(r.error, 0.0, 1e-12);
}

TEST(WaveMomentumRatio, DiluteRowsAndQuietWetRowsAreLeftOut) {
  FieldsRecord dry = layer(0.2, 50, 10), wet = layer(0.1, 50, 10);
  PhaseFields &d = dry.profiles.pooled, &w = wet.profiles.pooled;
  for (int k = 0; k < 50; ++k) {
    d.profile_rms_velocity_x[d.row(k, 0)] = 5.0;  // row 0: dilute in dry
    d.profile_area_fraction[d.row(k, 0)] = 0.01;
    w.profile_rms_velocity_x[w.row(k, 1)] = 1e-4;  // row 1: wet too quiet
  }
  EXPECT_NEAR(waveMomentumRatio(dry, wet, {}).value, 2.0, 1e-12);
}

TEST(WaveMomentumRatio, MismatchedFieldsGiveNoValue) {
  EXPECT_TRUE(std::isnan(waveMomentumRatio(layer(0.2, 50, 10), layer(0.1, 40, 10), {}).value));
}
