// The dense limit of the continuum model: Luding's global equation of state of hard disks
// against published simulations and the exact free-volume limit, mechanical stability
// (pressure rising with density everywhere), and the contact pressure's shape.
#include <gtest/gtest.h>

#include <cmath>

#include "hydro/ContactPressure.hpp"
#include "hydro/PairCorrelation.hpp"

using namespace granwave::hydro;

namespace {
double Z(const PairCorrelation& pc, double nu) { return 1 + 2 * nu * pc.g2(nu); }
}  // namespace

TEST(DenseLimit, LudingPressureMatchesEngelAtTheLiquidHexaticTransition) {
  // Engel et al., PRE 87, 042134 (2013), N = 1024^2, beta P d^2 = 9.1693 (nu = 0.698),
  // 9.1854 (0.700), 9.2308 (0.720) -> Z = beta P d^2 (pi/4)/nu. The global form is a fit
  // across all densities with a smooth merge where the real equation of state has its
  // coexistence plateau: asserted to 3 %.
  const PairCorrelation pc;
  for (auto [nu, bPd2] : {std::pair{0.698, 9.1693}, {0.700, 9.1854}, {0.720, 9.2308}}) {
    const double expected = bPd2 * std::numbers::pi / 4 / nu;
    EXPECT_NEAR(Z(pc, nu) / expected, 1.0, 0.03) << "nu = " << nu;
  }
}

TEST(DenseLimit, LudingPressureHasTheFreeVolumeDivergenceAtClosePacking) {
  // Salsburg & Wood (1962): Z -> 2 nu_max/(nu_max - nu) as nu -> nu_max (d = 2).
  const PairCorrelation pc;
  const double nu_max = kHexagonalClosePacking;
  for (double gap : {1e-3, 1e-4}) {
    const double nu = nu_max - gap;
    EXPECT_NEAR(Z(pc, nu) * gap / (2 * nu_max), 1.0, 10 * gap) << "gap " << gap;
  }
}

TEST(DenseLimit, LudingPressureAgreesWithHendersonInTheFluid) {
  // Below nu ~ 0.6 the merge is closed (m < 1e-4) and g_4 differs from Henderson's g2 only by
  // the fourth-virial term nu^3/(128 (1 - nu)^4).
  const PairCorrelation pc;
  for (double nu : {0.1, 0.3, 0.5, 0.6}) {
    const double h = 1 - nu;
    EXPECT_NEAR(pc.g2(nu), pairCorrelation(nu) - nu * nu * nu / (128 * h * h * h * h),
                2e-4 * pairCorrelation(nu))
        << nu;
  }
}

TEST(DenseLimit, PressureRisesWithDensityEverywhere) {
  // Mechanical stability: d(nu Z)/dnu > 0 on [0, nu_max) (a falling pressure would give an
  // imaginary sound speed), and dg2 is the derivative of g2 (central differences, 1e-6).
  const PairCorrelation pc;
  for (double nu = 1e-4; nu < kHexagonalClosePacking - 1e-3; nu += 5e-4) {
    const double slope = Z(pc, nu) + nu * 2 * (pc.g2(nu) + nu * pc.dg2(nu));
    EXPECT_GT(slope, 0.0) << "nu = " << nu;
    const double h = 1e-6;
    EXPECT_NEAR(pc.dg2(nu), (pc.g2(nu + h) - pc.g2(nu - h)) / (2 * h), 1e-5 * std::abs(pc.dg2(nu)))
        << "nu = " << nu;
  }
}

TEST(DenseLimit, ContactPressureVanishesBelowOnsetAndDivergesAtClosePacking) {
  ContactPressure c;
  c.scale = 1.0;
  EXPECT_EQ(c.pressure(0.81), 0.0);
  EXPECT_NEAR(c.pressure(0.88), std::pow((0.88 - 0.82) / (kHexagonalClosePacking - 0.88), 2),
              1e-12);
  EXPECT_GT(c.pressure(kHexagonalClosePacking - 1e-4), 7e5);  // (0.0868/1e-4)^2
  for (double nu : {0.83, 0.86, 0.9}) {
    const double h = 1e-7;
    EXPECT_NEAR(c.derivative(nu), (c.pressure(nu + h) - c.pressure(nu - h)) / (2 * h),
                1e-5 * c.derivative(nu));
  }
}
