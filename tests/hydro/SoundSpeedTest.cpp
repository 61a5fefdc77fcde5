// Adiabatic and isothermal sound speeds of the disk gas (docs/hydro.md, "Reference values"): the
// table of c_s / sqrt(theta), the dilute limit gamma = 2, c_T < c_s, and the general formula with a
// temperature-dependent Phi_P against finite differences of the equation of state.
#include <gtest/gtest.h>

#include <cmath>

#include "hydro/PairCorrelation.hpp"
#include "hydro/RestitutionClosure.hpp"
#include "hydro/SoundSpeed.hpp"
#include "tests/hydro/CaseGrid.hpp"

using namespace granwave::hydro;

namespace {

void expectPrinted(double value, double printed, double last_digit) {
  EXPECT_LE(std::abs(value - printed), 0.5 * last_digit * (1.0 + 1e-9))
      << "value " << value << " does not round to " << printed;
}

// Reduced pressure p~ = nu theta F(nu, theta) = p (pi sigma^2/4) / m, so that
// c_s^2 = dp~/dnu|_theta + (2 p~ / (d nu^2)) dp~/dtheta|_nu, d = 2.
double reducedPressure(double nu, double theta, const RestitutionClosure& r) {
  return nu * theta * pressureFactor(nu, theta, r);
}

double soundSpeedByFiniteDifferences(double nu, double theta, const RestitutionClosure& r,
                                     bool adiabatic) {
  const double hn = 1e-5 * nu, ht = 1e-5 * theta;
  const double dp_dnu =
      (reducedPressure(nu + hn, theta, r) - reducedPressure(nu - hn, theta, r)) / (2 * hn);
  const double dp_dtheta =
      (reducedPressure(nu, theta + ht, r) - reducedPressure(nu, theta - ht, r)) / (2 * ht);
  const double p = reducedPressure(nu, theta, r);
  return std::sqrt(dp_dnu + (adiabatic ? p / (nu * nu) * dp_dtheta : 0.0));
}

}  // namespace

TEST(SoundSpeed, ReproducesTheTableOfSection3_1) {
  struct Row {
    double nu, e09, e1;
  };
  const Row rows[] = {{0.01, 1.44, 1.44}, {0.1, 1.73, 1.74}, {0.3, 2.79, 2.85}, {0.5, 5.27, 5.44},
                      {0.6, 8.03, 8.33},  {0.7, 13.8, 14.4}, {0.8, 29.9, 31.2}};
  const RestitutionClosure e09 = RestitutionClosure::constant(0.9);
  const RestitutionClosure e1 = RestitutionClosure::constant(1.0);
  const double theta = 0.1;
  for (const Row& r : rows) {
    SCOPED_TRACE(r.nu);
    const double digit = r.nu < 0.65 ? 0.01 : 0.1;
    expectPrinted(adiabaticSoundSpeed(r.nu, theta, e09) / std::sqrt(theta), r.e09, digit);
    expectPrinted(adiabaticSoundSpeed(r.nu, theta, e1) / std::sqrt(theta), r.e1, digit);
  }
}

TEST(SoundSpeed, ConstantRestitutionFormula) {
  // c_s^2 = theta [F + nu F' + F^2], c_T^2 = theta [F + nu F'], F = 1 + (1 + e) nu g2.
  const RestitutionClosure r = RestitutionClosure::constant(0.8);
  for (double nu = 0.05; nu < 0.9; nu += 0.05) {
    const double F = 1 + 1.8 * nu * pairCorrelation(nu);
    const double dF = 1.8 * (pairCorrelation(nu) + nu * pairCorrelationDerivative(nu));
    const double theta = 0.3;
    EXPECT_NEAR(adiabaticSoundSpeed(nu, theta, r), std::sqrt(theta * (F + nu * dF + F * F)),
                1e-13 * std::sqrt(theta * (F + nu * dF + F * F)));
    EXPECT_NEAR(isothermalSoundSpeed(nu, theta, r), std::sqrt(theta * (F + nu * dF)),
                1e-13 * std::sqrt(theta * (F + nu * dF)));
  }
}

TEST(SoundSpeed, DiluteLimitIsTheIdealGasWithGammaTwo) {
  for (const RestitutionClosure& r :
       {RestitutionClosure::constant(0.9), RestitutionClosure::dry(0.1),
        RestitutionClosure::wet(0.91, 0.0698)}) {
    for (double theta : {1e-3, 0.1, 2.0}) {
      const double cs = adiabaticSoundSpeed(1e-10, theta, r);
      const double cT = isothermalSoundSpeed(1e-10, theta, r);
      EXPECT_NEAR(cs * cs, 2.0 * theta, 1e-8 * theta);
      EXPECT_NEAR(cT * cT, theta, 1e-8 * theta);
    }
  }
}

TEST(SoundSpeed, IsothermalIsSlowerThanAdiabatic) {
  test::forEachCase(
      std::vector{RestitutionClosure::constant(0.9), RestitutionClosure::constant(1.0),
                  RestitutionClosure::dry(0.1), RestitutionClosure::wet(0.91, 0.0698)},
      std::vector{0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8}, std::vector{1e-4, 1e-2, 1.0},
      [](const RestitutionClosure& r, double nu, double theta) {
        EXPECT_LT(isothermalSoundSpeed(nu, theta, r), adiabaticSoundSpeed(nu, theta, r));
      });
}

TEST(SoundSpeed, GeneralFormulaMatchesFiniteDifferencesOfTheEquationOfState) {
  // T-dependent Phi_P adds theta Phi_P'(theta) nu g2 to dp/dT|_n (docs/hydro.md, "Theory helpers").
  test::forEachCase(std::vector{RestitutionClosure::dry(0.1), RestitutionClosure::wet(0.91, 0.0698),
                                RestitutionClosure::constant(0.9)},
                    std::vector{0.05, 0.3, 0.6, 0.8}, std::vector{1e-4, 1e-3, 1e-2, 0.1, 1.0},
                    [](const RestitutionClosure& r, double nu, double theta) {
                      const double cs = adiabaticSoundSpeed(nu, theta, r);
                      const double cT = isothermalSoundSpeed(nu, theta, r);
                      EXPECT_NEAR(cs, soundSpeedByFiniteDifferences(nu, theta, r, true), 1e-8 * cs);
                      EXPECT_NEAR(cT, soundSpeedByFiniteDifferences(nu, theta, r, false),
                                  1e-8 * cT);
                    });
}

TEST(SoundSpeed, TemperatureDependenceOfTheClosureMatters) {
  // Wet grains near the onset: Phi_P rises steeply with theta, so the adiabatic speed is
  // above the one computed with Phi_P frozen at its local value.
  const RestitutionClosure wet = RestitutionClosure::wet(0.91, 0.0698);
  const double nu = 0.6, theta = 1e-3;
  const RestitutionClosure frozen = RestitutionClosure::constant(wet.phiP(theta) - 1.0);
  EXPECT_GT(adiabaticSoundSpeed(nu, theta, wet), 1.02 * adiabaticSoundSpeed(nu, theta, frozen));
  EXPECT_NEAR(isothermalSoundSpeed(nu, theta, wet), isothermalSoundSpeed(nu, theta, frozen), 1e-12);
}

TEST(SoundSpeed, PaperExample) {
  // nu = 0.6, theta = v0^2/4 with v0 = 0.6245 m/s, e = 0.9: c_s ~ 2.5 m/s.
  const double v0 = 0.6245;
  expectPrinted(adiabaticSoundSpeed(0.6, v0 * v0 / 4, RestitutionClosure::constant(0.9)), 2.5, 0.1);
}
