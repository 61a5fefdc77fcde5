// Homogeneous cooling with velocity-dependent restitution in the PDE (physics-hydro.md 4.3,
// 4.4; tests 2 and 3 of section 7). A uniform gas with elastic walls and no gravity stays
// uniform, and its temperature obeys d(theta)/dt = -(4/sqrt(pi)) Phi_W(theta) G theta^(3/2)
// / sigma. Each test checks (1) that the PDE integrated by CVODE reproduces that ODE,
// integrated independently here by RK4 with 10^5 steps (1e-6), and (2) the analytic limit:
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
#include "hydro/PairCorrelation.hpp"

using namespace granwave::hydro;

namespace {
using test::kD;
using test::kDisk;
using test::kMass;
constexpr double kNu = 0.2;

struct Cooling {
  GranularHydro1D pde;
  CvodeIntegrator cv;
};

double thetaRate(const RestitutionClosure& law, double theta) {
  const double G = kNu * pairCorrelation(kNu);
  return -(4 / std::sqrt(std::numbers::pi)) * law.phiW(theta) * G * std::pow(theta, 1.5) / kD;
}

double rk4(const RestitutionClosure& law, double theta0, double t, int steps) {
  double th = theta0;
  const double h = t / steps;
  for (int k = 0; k < steps; ++k) {
    const double a = thetaRate(law, th), b = thetaRate(law, th + 0.5 * h * a);
    const double c = thetaRate(law, th + 0.5 * h * b), d = thetaRate(law, th + h * c);
    th += h * (a + 2 * b + 2 * c + d) / 6;
  }
  return th;
}

double pdeTheta(const RestitutionClosure& law, double theta0, double t) {
  const ConstitutiveModel m = test::beadModel(law, RestitutionClosure::constant(1.0));
  HydroGeometry g;
  g.cells = 20;
  g.height = 20 * kD;
  g.gravity = 0;
  const GranularHydro1D pde(g, m);
  const double rho = kNu * kMass / kDisk;
  std::vector<double> U(pde.size());
  for (int i = 0; i < g.cells; ++i) {
    U[3 * i] = rho;
    U[3 * i + 2] = rho * theta0;
  }
  CvodeOptions o;
  o.rtol = 1e-9;
  o.atol.assign(U.size(), 1e-16);
  o.band_upper = o.band_lower = GranularHydro1D::kHalfBand;
  CvodeIntegrator cv(
      [&pde](double tt, const double* y, double* d) { return pde.rightHandSide(tt, y, d); }, 0.0, U,
      o);
  cv.advanceTo(t);
  return cv.state()[3 * 10 + 2] / cv.state()[3 * 10];
}
}  // namespace

TEST(HydroCooling, DryGasFollowsTheViscoelasticCoolingLaw) {
  const double kappa = 0.1, theta0 = 0.1;
  const RestitutionClosure dry = RestitutionClosure::dry(kappa);
  const double n = kNu / kDisk;
  const double B = 2 * std::sqrt(std::numbers::pi) * kappa * std::tgamma(2.1) * std::pow(4.0, 0.1) *
                   pairCorrelation(kNu) * n * kD;  // d(theta)/dt = -B theta^(8/5) (per mass)
  for (double t : {0.02, 0.1, 0.3}) {
    const double th_pde = pdeTheta(dry, theta0, t);
    EXPECT_NEAR(th_pde / rk4(dry, theta0, t, 100000), 1.0, 1e-6) << "t = " << t;
    const double leading = theta0 * std::pow(1 + 0.6 * B * std::pow(theta0, 0.6) * t, -5.0 / 3.0);
    EXPECT_NEAR(th_pde / leading, 1.0, 0.07) << "t = " << t;
  }
}

TEST(HydroCooling, WetGasCoolsWithTheErfcClosureAndEndsCompletelyInelastic) {
  const double q = 2580 * kD / (9 * 1e-3), v_c = 40 / q, theta0 = 0.05;
  const RestitutionClosure wet = RestitutionClosure::wet(0.91, v_c);
  for (double t : {0.01, 0.05, 0.3}) {
    const double th_pde = pdeTheta(wet, theta0, t);
    EXPECT_NEAR(th_pde / rk4(wet, theta0, t, 100000), 1.0, 1e-6) << "t = " << t;
  }
  // Late: y = v_c / sqrt(4 theta) >> 1, Phi_W -> 1. The PDE's own cooling rate (central
  // difference over +-0.05 s, truncation ~ (0.05 / t)^2 ~ 3e-4) equals Haff's with e = 0.
  const double th = pdeTheta(wet, theta0, 3.0);
  ASSERT_GT(v_c / std::sqrt(4 * th), 3.0);
  const double rate = (pdeTheta(wet, theta0, 3.05) - pdeTheta(wet, theta0, 2.95)) / 0.1;
  const double haff_e0 =
      -(4 / std::sqrt(std::numbers::pi)) * kNu * pairCorrelation(kNu) * std::pow(th, 1.5) / kD;
  EXPECT_NEAR(rate / haff_e0, 1.0, 2e-3);
}
