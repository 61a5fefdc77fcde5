// The tiny surface-waves study (tests/studies/data/tiny-surface-waves.toml): what must hold
// whatever the run length.
//
// Dissipation of the pair impacts. e_eff^2 = sum (1 - e^2) E_n / sum E_n over the impacts the
// restitution law decided is an energy-weighted mean of e(v)^2, so e_eff lies within the range
// of the law over the impacts' speeds. The dry law (kappa = 0.1, v in m/s) gives
// e = 1 - 0.1 v^(1/5) > 1 - 0.1 x 2^(1/5) = 0.8851 below 2 m/s (the paper's layer hits at
// 0.5-1 m/s; the plate's peak speed is 0.62 m/s), and e < 1: e_eff in (0.885, 1). The wet law
// e = e_inf (1 - St_c / (q v)) never exceeds e_inf = 0.91 (and is 0 below v_c), so e_eff <=
// 0.91; and since e_wet(v) < e_dry(v) for every v below the laws' crossing at 2.28 m/s, the
// wet layer's impacts are the more dissipative at the same drive. These are bounds of the laws
// (particles/Restitution.hpp), exact whatever the statistics.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tests/studies/contract/TinyStudy.hpp"

namespace {

constexpr char kKind[] = "surface-waves";
using SurfaceWavesResults = granwave::testing::TinyStudyTest<kKind>;
const std::string kRoot = "/results/surface_waves";

// The onset-scan point of `variant` (0 dry, 1 wet) at Gamma, from the tiny file's grid.
std::string onsetPoint(int variant, double gamma) {
  for (int i = 0; i < 4; ++i) {
    const std::string g = kRoot + "/onset/point_00" + std::to_string(i);
    if (SurfaceWavesResults::study().value(g, "variant") == variant &&
        SurfaceWavesResults::study().value(g, "gamma") == gamma)
      return g;
  }
  return "";
}

TEST_F(SurfaceWavesResults, PairImpactsDissipateWithinTheRangeOfEachLaw) {
  for (double gamma : {3.0, 4.0}) {
    const std::string dry = onsetPoint(0, gamma), wet = onsetPoint(1, gamma);
    ASSERT_FALSE(dry.empty());
    ASSERT_FALSE(wet.empty());
    const double e_dry = study().value(dry, "e_eff"), e_wet = study().value(wet, "e_eff");
    EXPECT_GT(e_dry, 1 - 0.1 * std::pow(2.0, 0.2)) << "Gamma " << gamma;
    EXPECT_LT(e_dry, 1.0) << "Gamma " << gamma;
    EXPECT_LE(e_wet, 0.91) << "Gamma " << gamma;
    EXPECT_LT(e_wet, e_dry) << "Gamma " << gamma << ": wet impacts must dissipate more";
    // Energy is lost in every cycle of a driven steady layer.
    EXPECT_GT(study().value(dry, "loss_per_cycle"), 0.0);
    EXPECT_GT(study().value(wet, "loss_per_cycle"), 0.0);
  }
}

TEST_F(SurfaceWavesResults, EveryPointHasASpectrumWithWindowsAndAnAllowedWavelength) {
  // 40 cycles less the transient leave at least one window of 10 cycles; a standing mode of
  // the walled 30 d box has lambda = 2 W / m, between 4 d (the shortest admitted) and 60 d.
  for (int i = 0; i < 4; ++i) {
    const std::string g = kRoot + "/onset/point_00" + std::to_string(i);
    EXPECT_GE(study().value(g, "windows"), 1.0) << g;
    const double share = study().value(g, "wave_fraction");
    EXPECT_GE(share, 0.0);
    EXPECT_LE(share, 1.0);
    const double m = study().value(g, "standing_mode");
    EXPECT_GE(m, 1.0);
    EXPECT_LE(2 * 30 / m, 60.0);
    EXPECT_GE(2 * 30 / m, 4.0);
  }
}

TEST_F(SurfaceWavesResults, EveryVariantHasAnOnsetOrABound) {
  for (int v = 0; v < 2; ++v) {
    const std::string g = kRoot + "/onsets/onset_00" + std::to_string(v);
    const double gamma_c = study().value(g, "gamma_c");
    if (std::isfinite(gamma_c)) {
      EXPECT_GE(gamma_c, 3.0);
      EXPECT_LE(gamma_c, 4.0);
    }
  }
}

TEST_F(SurfaceWavesResults, ContinuumPointHasASpectrumBesideTheParticlesAndACostForEach) {
  // The wet layer's 2D continuum in the periodic 30 d box: 40 cycles leave two windows of 10
  // in the second half; a standing mode of a periodic box of width W has lambda = W / m.
  const std::string g = kRoot + "/continuum/point_000";
  EXPECT_EQ(study().value(g, "variant"), 1.0);
  EXPECT_EQ(study().value(g, "width_d"), 30.0);
  EXPECT_EQ(study().value(g, "gamma"), 4.0);
  for (const std::string model : {"continuum_", "particles_"}) {
    EXPECT_EQ(study().value(g, model + "runs_ok"), 1.0) << model;
    EXPECT_GE(study().value(g, model + "windows"), 2.0) << model;
    EXPECT_EQ(study().value(g, model + "seeds"), 1.0) << model;
    const double share = study().value(g, model + "wave_fraction");
    EXPECT_GE(share, 0.0) << model;
    EXPECT_LE(share, 1.0) << model;
    const double m = study().value(g, model + "standing_mode");
    EXPECT_GE(m, 1.0) << model;
    EXPECT_GE(30 / m, 4.0) << model;
    EXPECT_GT(study().value(g, model + "cpu_per_cycle"), 0.0) << model;
  }
  // The onsets of the two models over the continuum's Gamma, continuum first.
  for (int i = 0; i < 2; ++i) {
    const std::string o = kRoot + "/continuum_onsets/onset_00" + std::to_string(i);
    EXPECT_EQ(study().file().readStringAttribute(o, "model"), i == 0 ? "continuum" : "particles");
    EXPECT_EQ(study().value(o, "width_d"), 30.0);
  }
}

}  // namespace
