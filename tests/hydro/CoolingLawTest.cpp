// Homogeneous cooling with velocity-dependent restitution in the PDE (docs/hydro.md,
// "Cooling"). A uniform gas with elastic walls and no gravity stays
// uniform, and its temperature obeys d(theta)/dt = -(4/sqrt(pi)) Phi_W(theta) G theta^(3/2)
// / sigma. Each test checks (1) that the PDE integrated by CVODE reproduces that ODE,
// integrated independently here by RK4 with 10^5 steps (to kWallTolerance, see below), and (2)
// the analytic limit:
//  - dry: to leading order in kappa, theta^(-3/5) is linear in t with slope (3/5) B',
//    B' = 2 sqrt(pi) kappa Gamma(21/10) 4^(1/10) g2 n sigma (2D, per unit mass); the kappa^2
//    term of Phi_W changes the rate by kappa Gamma(11/5)(4 theta)^(1/10) / (2 Gamma(21/10))
//    ~ 5 %, so the analytic law is asserted to 7 %;
//  - wet: once the gas is cold (y = v_c sqrt(m/(4T)) >> 1) every collision is completely
//    inelastic, Phi_W -> 1: the local cooling rate equals Haff's with e = 0 to 1e-3.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "HydroTestSupport.hpp"
#include "hydro/CvodeIntegrator.hpp"
#include "hydro/GranularHydro1D.hpp"

using namespace granwave::hydro;

namespace {
using test::kD;
using test::kDisk;
using test::kMass;
constexpr double kNu = 0.2;
// The walls are a stiff contact, not rigid: as the gas cools 100-fold its pressure falls and
// each wall's contact gives way by ~0.006 sigma, 6e-4 of the 20-sigma box. The cooling rate
// goes as n^2 g2 (1.7e-3 slower) and theta late as its inverse square (3.4e-3). The PDE
// follows the ODE at the initial density to this (docs/hydro.md).
constexpr double kWallTolerance = 5e-3;

double thetaRate(const ConstitutiveModel& m, double nu, double theta) {
  const double G = nu * m.pair_correlation.g2(nu);
  return -(4 / std::sqrt(std::numbers::pi)) * m.restitution.phiW(theta) * G * std::pow(theta, 1.5) /
         kD;
}

double rk4(const ConstitutiveModel& m, double nu, double theta0, double t, int steps) {
  double th = theta0;
  const double h = t / steps;
  for (int k = 0; k < steps; ++k) {
    const double a = thetaRate(m, nu, th), b = thetaRate(m, nu, th + 0.5 * h * a);
    const double c = thetaRate(m, nu, th + 0.5 * h * b), d = thetaRate(m, nu, th + h * c);
    th += h * (a + 2 * b + 2 * c + d) / 6;
  }
  return th;
}

// The middle cell of a uniform gas with elastic walls, no gravity: its temperature at t, and
// its area fraction.
struct Cooled {
  double theta, nu, nu_now;  // temperature at t; area fraction at 0 and at t
};
Cooled pdeTheta(const ConstitutiveModel& m, double theta0, double t) {
  const test::Column c = test::uniformGas(m, 20, 20 * kD, kNu, theta0);
  const double nu0 = m.areaFraction(c.pde->cellView(c.U.data(), 10).rho);
  CvodeIntegrator cv = test::integrator(*c.pde, c.U, 1e-9);
  cv.advanceTo(t);
  const double nu = m.areaFraction(c.pde->cellView(cv.state().data(), 10).rho);
  return {c.pde->temperature(cv.state().data(), 10), nu0, nu};
}

}  // namespace

TEST(HydroCooling, DryGasFollowsTheViscoelasticCoolingLaw) {
  const double kappa = 0.1, theta0 = 0.1;
  const ConstitutiveModel m =
      test::beadModel(RestitutionClosure::dry(kappa), RestitutionClosure::constant(1.0));
  for (double t : {0.02, 0.1, 0.3}) {
    const Cooled pde = pdeTheta(m, theta0, t);
    const double n = pde.nu / kDisk;
    const double B = 2 * std::sqrt(std::numbers::pi) * kappa * std::tgamma(2.1) *
                     std::pow(4.0, 0.1) * m.pair_correlation.g2(pde.nu) * n *
                     kD;  // d(theta)/dt = -B theta^(8/5) (per mass)
    EXPECT_NEAR(pde.theta / rk4(m, pde.nu, theta0, t, 100000), 1.0, kWallTolerance) << "t = " << t;
    const double leading = theta0 * std::pow(1 + 0.6 * B * std::pow(theta0, 0.6) * t, -5.0 / 3.0);
    EXPECT_NEAR(pde.theta / leading, 1.0, 0.07) << "t = " << t;
  }
}

TEST(HydroCooling, WetGasCoolsWithTheErfcClosureAndEndsCompletelyInelastic) {
  const double q = 2580 * kD / (9 * 1e-3), v_c = 40 / q, theta0 = 0.05;
  const ConstitutiveModel m =
      test::beadModel(RestitutionClosure::wet(0.91, v_c), RestitutionClosure::constant(1.0));
  for (double t : {0.01, 0.05, 0.3}) {
    const Cooled pde = pdeTheta(m, theta0, t);
    EXPECT_NEAR(pde.theta / rk4(m, pde.nu, theta0, t, 100000), 1.0, kWallTolerance) << "t = " << t;
  }
  // Late: y = v_c / sqrt(4 theta) >> 1, Phi_W -> 1. The PDE's own cooling rate (central
  // difference over +-0.05 s, truncation ~ (0.05 / t)^2 ~ 3e-4) equals Haff's with e = 0.
  const Cooled late = pdeTheta(m, theta0, 3.0);
  ASSERT_GT(v_c / std::sqrt(4 * late.theta), 3.0);
  const double rate = (pdeTheta(m, theta0, 3.05).theta - pdeTheta(m, theta0, 2.95).theta) / 0.1;
  const double haff_e0 = -(4 / std::sqrt(std::numbers::pi)) * late.nu_now *
                         m.pair_correlation.g2(late.nu_now) * std::pow(late.theta, 1.5) / kD;
  EXPECT_NEAR(rate / haff_e0, 1.0, 2e-3);
}
