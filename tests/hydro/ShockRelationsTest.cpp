// Rankine-Hugoniot relations of the disk gas (docs/hydro.md, "Theory helpers"): the strong-shock
// table of "Reference values" at e = 0.9, the dilute ideal gas (gamma = 2), the general solver's
// limits (cold upstream, dilute upstream, weak shock -> sound speed), and the three jump conditions
// on its output.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "hydro/RestitutionClosure.hpp"
#include "hydro/ShockRelations.hpp"
#include "hydro/SoundSpeed.hpp"
#include "tests/hydro/CaseGrid.hpp"

using namespace granwave::hydro;

namespace {

void expectPrinted(double value, double printed, double last_digit) {
  EXPECT_LE(std::abs(value - printed), 0.5 * last_digit * (1.0 + 1e-9))
      << "value " << value << " does not round to " << printed;
}

const RestitutionClosure kE09 = RestitutionClosure::constant(0.9);
const RestitutionClosure kDry = RestitutionClosure::dry(0.1);
const RestitutionClosure kWet = RestitutionClosure::wet(0.91, 0.0698);

// Jump conditions in SI units, independent of the library's residual helper: paper disks
// (m = 1.0807e-5 kg, sigma = 2 mm), p = rho theta F.
void expectJumpConditions(const GasState& up, const ShockSolution& down, double U,
                          const RestitutionClosure& r, double tol) {
  const double m = 1.0807e-5, sigma = 0.002;
  const double rho1 = m * 4 * up.nu / (std::numbers::pi * sigma * sigma);
  const double rho2 = m * 4 * down.nu / (std::numbers::pi * sigma * sigma);
  const double p1 = rho1 * up.theta * pressureFactor(up.nu, up.theta, r);
  const double p2 = rho2 * down.theta * pressureFactor(down.nu, down.theta, r);
  const double s = down.speed;
  EXPECT_NEAR(rho1 * s, rho2 * (s - U), tol * rho1 * s) << "mass";
  EXPECT_NEAR(p2 - p1, rho1 * s * U, tol * rho1 * s * U) << "momentum";
  EXPECT_NEAR(down.theta - up.theta, 0.5 * (p1 + p2) * (1 / rho1 - 1 / rho2), tol * down.theta)
      << "energy";  // (d/2) = 1 in 2D
  const JumpResiduals res = jumpResiduals(up, down, U, r);
  EXPECT_LT(std::abs(res.mass), tol);
  EXPECT_LT(std::abs(res.momentum), tol);
  EXPECT_LT(std::abs(res.energy), tol);
}

}  // namespace

// docs/hydro.md ("Reference values"), 2D Henderson, e = 0.9: (nu1, nu2, s/U_p).
TEST(StrongShock, ReproducesTheTableOfSection3_2) {
  struct Row {
    double nu1, nu2, s_over_U;
  };
  const Row rows[] = {{0.05, 0.127, 1.65}, {0.20, 0.364, 2.22}, {0.40, 0.557, 3.54},
                      {0.50, 0.634, 4.74}, {0.60, 0.704, 6.78}, {0.65, 0.738, 8.40}};
  for (const Row& r : rows) {
    SCOPED_TRACE(r.nu1);
    const ShockSolution s = strongShock(r.nu1, 0.4, kE09);
    expectPrinted(s.nu, r.nu2, 1e-3);
    expectPrinted(s.speed / 0.4, r.s_over_U, 1e-2);
    // e = 1 changes s/U_p by "only ~2 %" (2.1 % at nu1 = 0.5 to 2.6 % at 0.65).
    const double elastic = strongShock(r.nu1, 0.4, RestitutionClosure::constant(1.0)).speed;
    EXPECT_GT(elastic / s.speed, 1.0);
    EXPECT_LT(elastic / s.speed, 1.03);
  }
}

TEST(StrongShock, PostShockStateAndSpeed) {
  // theta2 = U_p^2 / d, s = U_p nu2/(nu2 - nu1) = U_p [1 + F(nu2)/d].
  for (double U : {0.1, 0.4, 2.0}) {
    for (const RestitutionClosure* r : {&kE09, &kDry, &kWet}) {
      const ShockSolution s = strongShock(0.45, U, *r);
      EXPECT_NEAR(s.theta, U * U / 2, 1e-15);
      EXPECT_NEAR(s.speed, U * (1 + pressureFactor(s.nu, s.theta, *r) / 2), 1e-12 * s.speed);
      EXPECT_EQ(s.mach, std::numeric_limits<double>::infinity());
      expectJumpConditions({0.45, 0.0}, s, U, *r, 1e-12);
    }
  }
  // Paper example: U_p ~ 0.4 m/s into nu1 ~ 0.5: s ~ 1.9 m/s.
  expectPrinted(strongShock(0.5, 0.4, kE09).speed, 1.9, 0.1);
}

TEST(StrongShock, DiluteLimitIsTheIdealGasMaximumCompression) {
  const ShockSolution s = strongShock(1e-9, 1.0, kE09);
  EXPECT_NEAR(s.nu / 1e-9, 3.0, 1e-7);  // (gamma + 1)/(gamma - 1) = 3 in 2D
  EXPECT_NEAR(s.speed, 1.5, 1e-7);
}

TEST(StrongShock, RejectsBadInput) {
  EXPECT_THROW(strongShock(0.0, 1.0, kE09), std::invalid_argument);
  EXPECT_THROW(strongShock(1.0, 1.0, kE09), std::invalid_argument);
  EXPECT_THROW(strongShock(0.5, 0.0, kE09), std::invalid_argument);
  EXPECT_THROW(rankineHugoniot({0.5, -1.0}, 1.0, kE09), std::invalid_argument);
}

TEST(IdealGas, MachRelations) {
  // gamma = 2: rho2/rho1 = 3M^2/(M^2 + 2), p2/p1 = (4M^2 - 1)/3; M = 1 is no shock.
  EXPECT_DOUBLE_EQ(idealGasDensityRatio(1.0), 1.0);
  EXPECT_DOUBLE_EQ(idealGasPressureRatio(1.0), 1.0);
  EXPECT_NEAR(idealGasDensityRatio(1e6), 3.0, 1e-11);
  for (double theta1 : {1e-3, 0.05, 1.0}) {
    for (double U : {0.01, 0.3, 3.0}) {
      const IdealGasShock s = idealGasPistonShock(theta1, U);
      EXPECT_NEAR(s.speed, 0.75 * U + std::sqrt(9.0 / 16 * U * U + 2 * theta1), 1e-14 * s.speed);
      EXPECT_NEAR(s.mach, s.speed / std::sqrt(2 * theta1), 1e-14 * s.mach);
      EXPECT_NEAR(s.density_ratio, idealGasDensityRatio(s.mach), 1e-12 * s.density_ratio);
      EXPECT_NEAR(s.pressure_ratio, idealGasPressureRatio(s.mach), 1e-12 * s.pressure_ratio);
      EXPECT_NEAR(s.temperature_ratio, s.pressure_ratio / s.density_ratio,
                  1e-12 * s.temperature_ratio);
    }
  }
  const IdealGasShock cold = idealGasPistonShock(0.0, 1.0);
  EXPECT_DOUBLE_EQ(cold.speed, 1.5);
  EXPECT_DOUBLE_EQ(cold.density_ratio, 3.0);
  EXPECT_DOUBLE_EQ(cold.theta, 0.5);
}

TEST(RankineHugoniot, ReducesToTheStrongShockForAColdUpstream) {
  for (double nu1 : {0.05, 0.3, 0.5, 0.65}) {
    const double U = 0.4;
    const ShockSolution strong = strongShock(nu1, U, kE09);
    double previous = std::numeric_limits<double>::infinity();
    for (double theta1 : {1e-2, 1e-4, 1e-6, 1e-8}) {
      const ShockSolution s = rankineHugoniot({nu1, theta1}, U, kE09);
      const double diff = std::abs(s.speed - strong.speed) / strong.speed;
      EXPECT_LT(diff, previous);  // converges as theta1 -> 0
      previous = diff;
    }
    EXPECT_LT(previous, 1e-6);
    const ShockSolution zero = rankineHugoniot({nu1, 0.0}, U, kE09);
    EXPECT_NEAR(zero.nu, strong.nu, 1e-14);
    EXPECT_NEAR(zero.speed, strong.speed, 1e-13 * strong.speed);
    EXPECT_NEAR(zero.theta, strong.theta, 1e-15);
  }
}

TEST(RankineHugoniot, ReducesToTheIdealGasForADiluteUpstream) {
  for (double theta1 : {1e-3, 0.05, 1.0}) {
    for (double U : {0.01, 0.3, 3.0}) {
      const double nu1 = 1e-10;
      const ShockSolution s = rankineHugoniot({nu1, theta1}, U, kE09);
      const IdealGasShock ideal = idealGasPistonShock(theta1, U);
      EXPECT_NEAR(s.speed, ideal.speed, 1e-8 * ideal.speed);
      EXPECT_NEAR(s.nu / nu1, ideal.density_ratio, 1e-8 * ideal.density_ratio);
      EXPECT_NEAR(s.theta, ideal.theta, 1e-8 * ideal.theta);
      EXPECT_NEAR(s.mach, ideal.mach, 1e-8 * ideal.mach);
    }
  }
}

TEST(RankineHugoniot, WeakShockTravelsAtTheAdiabaticSoundSpeed) {
  // U_p -> 0: s -> c_s(nu1, theta1), including the T-dependence of Phi_P (checks 3.1's general
  // formula against the Hugoniot, which is tangent to the isentrope).
  test::forEachCase(
      std::vector<const RestitutionClosure*>{&kE09, &kDry, &kWet}, std::vector{0.1, 0.5, 0.7},
      std::vector{1e-3, 0.1}, [](const RestitutionClosure* r, double nu1, double theta1) {
        const double cs = adiabaticSoundSpeed(nu1, theta1, *r);
        const double U = 1e-7 * cs;  // s/c_s - 1 = O(U/c_s), coefficient ~5 at nu = 0.7
        const ShockSolution s = rankineHugoniot({nu1, theta1}, U, *r);
        EXPECT_NEAR(s.speed / cs, 1.0, 1e-5);
        EXPECT_GT(s.mach, 1.0);
      });
}

TEST(RankineHugoniot, SolutionSatisfiesTheJumpConditions) {
  test::forEachCase(std::vector<const RestitutionClosure*>{&kE09, &kDry, &kWet},
                    std::vector{1e-3, 0.05, 0.3, 0.5, 0.65, 0.8}, std::vector{1e-4, 0.01, 0.2},
                    std::vector{0.05, 0.4, 1.5},
                    [](const RestitutionClosure* r, double nu1, double theta1, double U) {
                      SCOPED_TRACE(::testing::Message() << nu1 << " " << theta1 << " " << U);
                      const GasState up{nu1, theta1};
                      const ShockSolution s = rankineHugoniot(up, U, *r);
                      EXPECT_GT(s.nu, nu1);
                      EXPECT_GT(s.theta, theta1);
                      EXPECT_GT(s.mach, 1.0);  // shocks are supersonic
                      expectJumpConditions(up, s, U, *r, 1e-10);
                    });
}

TEST(CompactionFront, SnowPloughSpeed) {
  // docs/hydro.md ("Theory helpers"): for nu1 = 0.5 the compaction front moves at 2.2-2.6 U_p
  // (nu_max 0.907-0.82).
  expectPrinted(compactionFrontSpeed(0.5, 1.0), 2.2, 0.1);
  expectPrinted(compactionFrontSpeed(0.5, 1.0, kRandomClosePacking2D), 2.6, 0.1);
  EXPECT_NEAR(compactionFrontSpeed(0.5, 0.4, 0.8), 0.4 * 0.8 / 0.3, 1e-15);
  EXPECT_THROW(compactionFrontSpeed(0.9, 1.0, 0.82), std::invalid_argument);
  // The compaction front is slower than the gas-dynamic shock into a dense layer.
  EXPECT_LT(compactionFrontSpeed(0.5, 0.4), strongShock(0.5, 0.4, kE09).speed);
}
