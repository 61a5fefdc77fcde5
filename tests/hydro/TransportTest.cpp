// Transport coefficients of inelastic hard disks, d = 2 (docs/hydro.md, "Closures"): the
// Garzo-Dufty table of docs/hydro.md ("Reference values"), the elastic Enskog (Gass) limit where
// the compact JR set (A) and GD (B) coincide, the dilute reference values, and the kinetic scales
// of the conventions table (collision frequency, mean free path, Haff time).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hydro/PairCorrelation.hpp"
#include "hydro/RestitutionClosure.hpp"
#include "hydro/TransportCoefficients.hpp"

using namespace granwave::hydro;

namespace {

constexpr double kPi = std::numbers::pi;
// Paper particles: sigma = 2 mm, m = 1.0807e-5 kg (conventions table).
const DiskGas kGas{1.0807e-5, 0.002};

double densityAt(double nu) { return kGas.mass * 4.0 * nu / (kPi * kGas.sigma * kGas.sigma); }

RestitutionAverages constantE(double e) { return {1.0 - e * e, 1.0 + e}; }

void expectPrinted(double value, double printed, double last_digit) {
  EXPECT_LE(std::abs(value - printed), 0.5 * last_digit * (1.0 + 1e-9))
      << "value " << value << " does not round to " << printed;
}

void expectRelative(double a, double b, double tol) { EXPECT_NEAR(a, b, tol * std::abs(b)); }

}  // namespace

TEST(DiskGas, AreaFractionAndDensity) {
  const double n = 4.0 * 0.5 / (kPi * 4e-6);
  EXPECT_NEAR(kGas.areaFraction(n), 0.5, 1e-15);
  EXPECT_NEAR(kGas.numberDensity(densityAt(0.5)), n, 1e-9 * n);
}

// docs/hydro.md ("Reference values"): (eta*, lambda_b*, kappa*) at e = 0.9 and in the elastic
// Enskog limit.
TEST(GarzoDufty, ReproducesTheTableOfSection1_5) {
  struct Row {
    double nu, eta, lambda_b, kappa, eta_el, lambda_b_el, kappa_el;
  };
  const Row rows[] = {{0.3, 1.63, 0.77, 1.88, 1.73, 0.81, 2.03},
                      {0.6, 6.63, 8.03, 6.63, 7.30, 8.45, 7.86}};
  for (const Row& r : rows) {
    SCOPED_TRACE(r.nu);
    const GarzoDuftyReduced gd = garzoDuftyReduced(r.nu, constantE(0.9));
    expectPrinted(gd.eta, r.eta, 0.01);
    expectPrinted(gd.lambda_b, r.lambda_b, 0.01);
    expectPrinted(gd.kappa, r.kappa, 0.01);
    const GarzoDuftyReduced el = garzoDuftyReduced(r.nu, constantE(1.0));
    expectPrinted(el.eta, r.eta_el, 0.01);
    expectPrinted(el.lambda_b, r.lambda_b_el, 0.01);
    expectPrinted(el.kappa, r.kappa_el, 0.01);
  }
}

TEST(GarzoDufty, ElasticLimitIsGassEnskog) {
  // e = 1: eta* = (1 + G)^2/chi + (8/pi) nu G, kappa* = (1 + 3G/2)^2/chi + (4/pi) nu G.
  for (double nu = 0.05; nu < 0.85; nu += 0.05) {
    const double chi = pairCorrelation(nu), G = nu * chi;
    const GarzoDuftyReduced el = garzoDuftyReduced(nu, constantE(1.0));
    expectRelative(el.eta, (1 + G) * (1 + G) / chi + 8.0 / kPi * nu * G, 1e-13);
    expectRelative(el.kappa, (1 + 1.5 * G) * (1 + 1.5 * G) / chi + 4.0 / kPi * nu * G, 1e-13);
    EXPECT_EQ(el.zeta, 0.0);
  }
}

TEST(GarzoDufty, DiluteLimitIsTheReferenceGas) {
  // nu -> 0, e = 1: eta* -> 1, kappa* -> 1, p* -> 1 (eta0, kappa0 are the dilute elastic values).
  const GarzoDuftyReduced el = garzoDuftyReduced(1e-12, constantE(1.0));
  EXPECT_NEAR(el.eta, 1.0, 1e-10);
  EXPECT_NEAR(el.kappa, 1.0, 1e-10);
  EXPECT_NEAR(el.p, 1.0, 1e-10);
}

TEST(Transport, JenkinsRichmanEqualsGarzoDuftyForElasticDisks) {
  for (double nu = 0.01; nu < 0.85; nu += 0.04) {
    for (double theta : {1e-3, 0.1, 2.0}) {
      const double rho = densityAt(nu);
      const TransportCoefficients a = jenkinsRichmanTransport(kGas, rho, theta, constantE(1.0));
      const TransportCoefficients b = garzoDuftyTransport(kGas, rho, theta, constantE(1.0));
      expectRelative(a.p, b.p, 1e-13);
      expectRelative(a.eta, b.eta, 1e-13);
      expectRelative(a.lambda_b, b.lambda_b, 1e-13);
      expectRelative(a.kappa_theta, b.kappa_theta, 1e-13);
      EXPECT_EQ(a.D_c, 0.0);
      EXPECT_EQ(b.D_c, 0.0);
    }
  }
}

TEST(Transport, JenkinsRichmanIsTheDocumentedFormulaInRhoAndG) {
  // docs/hydro.md ("Closures", set A), written with 1/G: checks the finite-at-n=0 rewriting in the
  // code.
  const double nu = 0.45, theta = 0.07, e = 0.9;
  const double rho = densityAt(nu), G = nu * pairCorrelation(nu), s = kGas.sigma;
  const double base = rho * s * std::sqrt(theta);
  const TransportCoefficients t = jenkinsRichmanTransport(kGas, rho, theta, constantE(e));
  expectRelative(t.p, rho * theta * (1 + (1 + e) * G), 1e-14);
  expectRelative(t.eta, std::sqrt(kPi) / 8 * base * (1 / G + 2 + (1 + 8 / kPi) * G), 1e-13);
  expectRelative(t.lambda_b, (1 + e) / std::sqrt(kPi) * base * G, 1e-13);
  expectRelative(t.kappa_theta, std::sqrt(kPi) / 2 * base * (1 / G + 3 + (2.25 + 4 / kPi) * G),
                 1e-13);
  expectRelative(t.D_c, 4 / std::sqrt(kPi) * (1 - e * e) * rho * G * std::pow(theta, 1.5) / s,
                 1e-13);
}

TEST(Transport, InelasticGarzoDuftyIsBelowTheElasticSet) {
  // The elastic-coefficient set (A) overestimates eta by 5-10 % and kappa by 8-20 %
  // at e = 0.9, nu = 0.3-0.6.
  for (double nu : {0.3, 0.6}) {
    const double rho = densityAt(nu);
    const auto a = jenkinsRichmanTransport(kGas, rho, 0.1, constantE(0.9));
    const auto b = garzoDuftyTransport(kGas, rho, 0.1, constantE(0.9));
    EXPECT_GT(a.eta / b.eta, 1.05);
    EXPECT_LT(a.eta / b.eta, 1.11);
    EXPECT_GT(a.kappa_theta / b.kappa_theta, 1.07);
    EXPECT_LT(a.kappa_theta / b.kappa_theta, 1.20);
    expectRelative(a.p, b.p, 1e-14);
    expectRelative(a.D_c, b.D_c, 1e-13);
  }
}

TEST(Transport, DiluteLimitIsFiniteAndIndependentOfDensity) {
  // eta -> eta0, kappa_theta -> 4 eta0 = m kappa0 as n -> 0 (no 0 * inf at rho = 0).
  const double theta = 0.2, eta0 = referenceViscosity(kGas, theta);
  expectRelative(eta0, 1.0 / (2.0 * kGas.sigma) * std::sqrt(kGas.mass * kGas.mass * theta / kPi),
                 1e-15);
  for (double rho : {0.0, 1e-12}) {
    const auto a = jenkinsRichmanTransport(kGas, rho, theta, constantE(1.0));
    const auto b = garzoDuftyTransport(kGas, rho, theta, constantE(1.0));
    EXPECT_NEAR(a.eta, eta0, 1e-9 * eta0);
    EXPECT_NEAR(b.eta, eta0, 1e-9 * eta0);
    EXPECT_NEAR(a.kappa_theta, 4.0 * eta0, 4e-9 * eta0);
    EXPECT_NEAR(b.kappa_theta, 4.0 * eta0, 4e-9 * eta0);
  }
}

TEST(Transport, VelocityDependentClosureUsesThePhiFactors) {
  // With averages (Phi_W, Phi_P) from a closure, p = rho theta (1 + Phi_P G) and
  // D_c = zeta n T with zeta from Phi_W, for both sets.
  const RestitutionClosure wet = RestitutionClosure::wet(0.91, 0.0698);
  const double nu = 0.5, theta = 0.01, rho = densityAt(nu), G = nu * pairCorrelation(nu);
  const RestitutionAverages avg = wet.averages(theta);
  const CoolingRate zeta{kGas, wet};
  const double n = kGas.numberDensity(rho), T = kGas.mass * theta;
  for (const auto& t : {jenkinsRichmanTransport(kGas, rho, theta, avg),
                        garzoDuftyTransport(kGas, rho, theta, avg)}) {
    expectRelative(t.p, rho * theta * (1 + avg.phi_p * G), 1e-14);
    expectRelative(t.D_c, zeta(n, T) * n * T, 1e-13);
  }
  // GD at a velocity-dependent closure equals GD at constant e_eff except in the
  // collisional-transfer factors, which carry Phi_P: with Phi_P = 1 + e_eff they coincide.
  const double e_eff = avg.effectiveRestitution();
  const auto same = garzoDuftyReduced(nu, {avg.phi_w, 1.0 + e_eff});
  const auto ref = garzoDuftyReduced(nu, constantE(e_eff));
  expectRelative(same.eta, ref.eta, 1e-13);
  expectRelative(same.kappa, ref.kappa, 1e-13);
}

// Conventions table: at nu = 0.5, theta = 0.1 m^2/s^2, e = 0.9, sigma = 2 mm.
TEST(KineticScales, ConventionsTableNumbers) {
  const double nu = 0.5, theta = 0.1;
  const double n = 4.0 * nu / (kPi * kGas.sigma * kGas.sigma);
  const double omega = collisionFrequency(kGas, n, theta);
  expectPrinted(omega, 1.1e3, 0.1e3);                             // omega ~ 1.1e3 1/s
  expectPrinted(omega * 9.2e-6, 0.01, 0.01);                      // omega t_c ~ 0.01 (t_c = 9.2 us)
  expectPrinted(meanFreePath(kGas, n) / kGas.sigma, 0.18, 0.01);  // l ~ 0.18 sigma
  const CoolingRate zeta{kGas, RestitutionClosure::constant(0.9)};
  const double T = kGas.mass * theta;
  expectPrinted(zeta.haffTime(n, T), 19e-3, 1e-3);  // Haff time 2/zeta ~ 19 ms
  // zeta = sqrt(pi)(1 - e^2) g2 n sigma sqrt(T/m) = (1/2)(1 - e^2) chi nu0 (GD reduced).
  const double nu0 = 2 * std::sqrt(kPi) * n * kGas.sigma * std::sqrt(theta);
  expectRelative(zeta(n, T), garzoDuftyReduced(nu, constantE(0.9)).zeta * nu0, 1e-14);
  // Behind the paper's shocks, nu2 ~ 0.65, theta2 ~ 0.08: tau_H ~ 9 ms.
  const double n2 = 4.0 * 0.65 / (kPi * kGas.sigma * kGas.sigma);
  expectPrinted(zeta.haffTime(n2, kGas.mass * 0.08), 9e-3, 1e-3);
}

TEST(KineticScales, HaffLawFromTheCoolingRate) {
  // dT/dt = -zeta(T) T integrated with RK4: 1/sqrt(T) grows linearly with slope zeta0/(2 sqrt T0),
  // i.e. T = T0 / (1 + t/tau_H)^2.
  const CoolingRate zeta{kGas, RestitutionClosure::constant(0.9)};
  const double n = 4.0 * 0.3 / (kPi * kGas.sigma * kGas.sigma), T0 = kGas.mass * 0.1;
  const double tau = zeta.haffTime(n, T0);
  double T = T0;
  const int steps = 4000;
  const double dt = 5.0 * tau / steps;
  const auto rate = [&](double x) { return -zeta(n, x) * x; };
  for (int i = 0; i < steps; ++i) {
    const double k1 = rate(T), k2 = rate(T + 0.5 * dt * k1), k3 = rate(T + 0.5 * dt * k2),
                 k4 = rate(T + dt * k3);
    T += dt / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  expectRelative(T, T0 / 36.0, 1e-10);  // t = 5 tau
}
