// The tiny effective-restitution study (tests/studies/data/tiny-effective-restitution.toml).
//
// Free cooling of smooth disks (mu = 0) follows Haff's law with the Maxwell-averaged loss
// Phi_W(T) = <1 - e^2> of the law (hydro/RestitutionClosure.hpp; docs/hydro.md), so the fitted
// Phi_W of the highest temperature range (where the TC model makes no collision elastic) must
// match the theory at that range's temperature, up to the known deviations of event-driven
// hard disks from the Maxwellian, uncorrelated theory (tests/particles/HomogeneousCoolingTest.cpp
// states them with their sources):
//   - the Sonine correction of the cooling rate, a factor 1 + 3 a2 / 16 with
//     a2 = 16 (1 - e)(1 - 2 e^2) / (9 + 24 d - (41 - 8 d) e + 30 (1 - e) e^2), d = 2
//     (van Noije & Ernst, Granular Matter 1, 57 (1998));
//   - velocity correlations, one-sided: cooling slower by at most kappa_max = 2.5 Phi_W nu;
//   - statistics: the 1/sqrt(T) trace of one run is a Brownian motion about Haff's line with
//     diffusion D(s) = Phi_W (1 + s) / N per Haff time s (Poisson collisions, exponential losses),
//     and a least-squares slope over a span L of it has the variance 6 D / (5 L); 4 sigma.
// Friction moves translational energy into rotation and dissipates it tangentially (Huthmann &
// Zippelius, Phys. Rev. E 56, R6275 (1997)), so the Haff fit with the scene's friction gives a
// lower e_eff than without, beyond the fits' errors (3 sigma).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "scene/SceneDerived.hpp"
#include "scene/SceneParser.hpp"
#include "studies/contract/StudyScenes.hpp"
#include "studies/hydro_run/HydroModel.hpp"
#include "tests/studies/contract/TinyStudy.hpp"

namespace {

constexpr char kKind[] = "effective-restitution";
using EffectiveRestitutionResults = granwave::testing::TinyStudyTest<kKind>;
const std::string kRoot = "/results/effective_restitution";
// The tiny study file's [cooling] keys.
constexpr int kParticles = 400;
constexpr double kHighest = 1.0, kLowest = 0.05;  // T / T0
constexpr int kRanges = 3;

double sonineRateFactor(double e) {
  const double d = 2;
  const double a2 =
      16 * (1 - e) * (1 - 2 * e * e) / (9 + 24 * d - (41 - 8 * d) * e + 30 * (1 - e) * e * e);
  return 1 + 3 * a2 / 16;
}

granwave::Scene scene(const char* law) {
  return granwave::parseSceneFile(std::string(GRANWAVE_SOURCE_DIR) + "/scenes/paper-" + law +
                                  ".toml");
}

TEST_F(EffectiveRestitutionResults, HaffFitOfSmoothDisksFollowsTheMaxwellAveragedLaw) {
  const granwave::SceneDerived dry = granwave::derive(scene("dry"));
  const double theta0 = 0.5 * dry.v0 * dry.v0;  // the study's temperature scale (dry scene)
  // The highest range runs from the start (s = 0) to T = kHighest (kLowest/kHighest)^(1/3).
  const double s_end = std::pow(kLowest / kHighest, -0.5 / kRanges) - 1;
  for (const char* law : {"dry", "wet"}) {
    const granwave::hydro::RestitutionClosure closure = granwave::restitutionClosure(scene(law));
    for (const char* nu : {"0.2", "0.4"}) {
      const std::string g = kRoot + "/" + law + "/cooling_smooth_nu_" + nu;
      const double T = study().series(g + "/temperature_over_T0").front();
      const double e_fit = study().series(g + "/e_eff").front();
      const double phi = closure.phiW(T * theta0);
      const double ratio = (1 - e_fit * e_fit) / phi;
      const double sigma = std::sqrt(6 * phi * (1 + s_end) / kParticles / (5 * s_end));
      const double sonine = sonineRateFactor(std::sqrt(1 - phi));
      const double kappa_max = 2.5 * phi * std::stod(nu);
      EXPECT_GT(ratio, sonine * (1 - kappa_max) - 4 * sigma) << law << ", nu = " << nu;
      EXPECT_LT(ratio, sonine + 4 * sigma)
          << law << ", nu = " << nu << ": T/T0 = " << T << ", e_fit = " << e_fit;
    }
  }
}

TEST_F(EffectiveRestitutionResults, EveryEstimateIsARestitutionCoefficient) {
  for (const char* law : {"dry", "wet"})
    for (const char* estimate :
         {"collision_statistics", "free_cooling", "free_cooling_with_friction", "hydro_fit"}) {
      const std::string g = kRoot + "/" + law;
      const double e = study().value(g, estimate);
      EXPECT_TRUE(e > 0 && e <= 1) << law << " " << estimate << " = " << e;
      EXPECT_TRUE(std::isfinite(study().value(g, std::string(estimate) + "_error")))
          << law << " " << estimate;
    }
}

TEST_F(EffectiveRestitutionResults, FrictionLowersTheEffectiveRestitutionOfFreeCooling) {
  for (const char* law : {"dry", "wet"}) {
    const std::string g = kRoot + "/" + law;
    const double smooth = study().value(g, "free_cooling");
    const double rough = study().value(g, "free_cooling_with_friction");
    const double sigma = std::hypot(study().value(g, "free_cooling_error"),
                                    study().value(g, "free_cooling_with_friction_error"));
    EXPECT_LT(rough, smooth - 3 * sigma) << law;
  }
}

}  // namespace
