// The 1D granular-hydrodynamics solver (hydro/GranularHydro1D + CVODE) against theory:
// Haff's law, mass conservation, hydrostatic balance, and its failure paths.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "HydroTestSupport.hpp"
#include "hydro/CvodeIntegrator.hpp"
#include "hydro/HydroSimulation.hpp"
#include "hydro/PairCorrelation.hpp"

using namespace granwave::hydro;

namespace {
using test::kD;
using test::kMass;

ConstitutiveModel model(RestitutionClosure pairs, RestitutionClosure walls) {
  return test::beadModel(pairs, walls);
}

std::vector<double> uniform(const GranularHydro1D& pde, double nu, double theta) {
  const double rho = nu * kMass / (std::numbers::pi * kD * kD / 4);
  std::vector<double> U(pde.size());
  for (int i = 0; i < pde.geometry().cells; ++i) {
    U[3 * i] = rho;
    U[3 * i + 1] = 0;
    U[3 * i + 2] = rho * theta;
  }
  return U;
}

CvodeIntegrator integrator(const GranularHydro1D& pde, const std::vector<double>& U, double rtol) {
  CvodeOptions o;
  o.rtol = rtol;
  o.atol.assign(U.size(), 1e-14);
  o.band_upper = o.band_lower = GranularHydro1D::kHalfBand;
  return CvodeIntegrator(
      [&pde](double t, const double* y, double* d) { return pde.rightHandSide(t, y, d); }, 0.0, U,
      o);
}
}  // namespace

TEST(HydroSolver, UniformGasCoolsByHaffsLaw) {
  // No gravity, no drive, elastic walls: the state stays uniform and
  // d(theta)/dt = -zeta theta, zeta = sqrt(pi) (1 - e^2) g2 n sigma sqrt(theta) (2D,
  // physics-hydro.md 1.4), so theta(t) = theta0 / (1 + t / tau)^2 with tau = 2 / zeta(theta0).
  // CVODE at rtol 1e-8: agreement to 1e-6 relative.
  HydroGeometry g;
  g.cells = 40;
  g.height = 30 * kD;
  g.gravity = 0;
  const double e = 0.9, nu = 0.3, theta0 = 0.1;
  const GranularHydro1D pde(
      g, model(RestitutionClosure::constant(e), RestitutionClosure::constant(1.0)));
  CvodeIntegrator cv = integrator(pde, uniform(pde, nu, theta0), 1e-8);
  const double n = nu / (std::numbers::pi * kD * kD / 4);
  const double zeta0 =
      std::sqrt(std::numbers::pi) * (1 - e * e) * pairCorrelation(nu) * n * kD * std::sqrt(theta0);
  const double tau = 2 / zeta0;
  for (double s : {0.5, 1.0, 3.0}) {
    cv.advanceTo(s * tau);
    const std::vector<double>& U = cv.state();
    const double theta = U[3 * 20 + 2] / U[3 * 20];
    EXPECT_NEAR(theta / (theta0 / ((1 + s) * (1 + s))), 1.0, 1e-6) << "t = " << s << " tau";
    EXPECT_NEAR(U[3 * 0 + 2] / U[3 * 0], theta, 1e-9 * theta);  // still uniform
  }
}

TEST(HydroSolver, DrivenLayerConservesMassToSolverTolerance) {
  // Flux form with zero mass flux through the walls: linear multistep methods preserve
  // linear invariants, so total mass is conserved to round-off and solver tolerance.
  HydroGeometry g;
  g.cells = 100;
  g.height = 30 * kD;
  g.omega = 2 * std::numbers::pi * 10;
  g.amplitude = 4 * 9.81 / (g.omega * g.omega);
  const GranularHydro1D pde(g, model(RestitutionClosure::dry(0.1), RestitutionClosure::dry(0.1)));
  HydroRunOptions o;
  o.max_cycles = 3;
  o.min_cycles = 3;
  HydroSimulation sim(pde, 300, 30 * kD, o);
  const HydroResult r = sim.run();
  EXPECT_NEAR(r.final_mass / r.initial_mass, 1.0, 1e-9);
  EXPECT_EQ(r.cycles, 3);
  EXPECT_GT(r.stats.steps, 0);
}

TEST(HydroSolver, ElasticGasUnderGravitySettlesToHydrostaticBalance) {
  // e = 1, no drive: the steady state is isothermal with dp/dz = -rho g (physics-hydro.md
  // 7.6). The central difference of p over two cells is second-order accurate: residual
  // ~ (dz / H)^2 with the scale height H = theta F / g ~ 27 dz here, so 1.4e-3; asserted
  // below 2 (dz/H)^2 = 3e-3 in the bulk (nu > 0.05). Six cells at each wall are left out:
  // there the mirrored ghost state flattens the limited slopes, and a boundary layer of about
  // five cells (the reconstruction stencil) is out of balance by up to 23 % in its first cell,
  // with a spurious velocity of ~2e-3 m/s (docs/hydro.md, known limitation).
  HydroGeometry g;
  g.cells = 60;
  g.height = 20 * kD;
  const GranularHydro1D pde(
      g, model(RestitutionClosure::constant(1.0), RestitutionClosure::constant(1.0)));
  CvodeIntegrator cv = integrator(pde, uniform(pde, 0.1, 0.05), 1e-7);
  cv.advanceTo(3.0);
  const std::vector<double>& U = cv.state();
  const double h = pde.dz();
  double worst = 0, theta_min = 1e9, theta_max = 0;
  for (int i = 6; i + 6 < g.cells; ++i) {
    const double rho = U[3 * i], nu = rho / kMass * std::numbers::pi * kD * kD / 4;
    if (nu < 0.05) continue;
    const double th = U[3 * i + 2] / rho;
    theta_min = std::min(theta_min, th);
    theta_max = std::max(theta_max, th);
    auto p = [&](int k) { return pde.model().pressure(U[3 * k], U[3 * k + 2] / U[3 * k]); };
    const double residual = (p(i + 1) - p(i - 1)) / (2 * h) + rho * g.gravity;
    worst = std::max(worst, std::abs(residual) / (rho * g.gravity));
    EXPECT_LT(std::abs(U[3 * i + 1] / rho), 1e-4);  // at rest
  }
  const double H = theta_min * 1.5 / g.gravity;  // scale height with F ~ 1.5 at nu ~ 0.15
  EXPECT_LT(worst, 2 * (h / H) * (h / H));
  EXPECT_LT(theta_max / theta_min - 1, 2 * (h / H) * (h / H));  // isothermal
}

TEST(HydroSolver, ClosedElasticSystemConservesTotalEnergy) {
  // e = 1 everywhere and no drive: kinetic + internal + potential energy is constant. The
  // work of gravity uses the same mass fluxes that move the mass, so this holds to solver
  // tolerance (rtol 1e-8), not just to discretisation error.
  HydroGeometry g;
  g.cells = 60;
  g.height = 20 * kD;
  const GranularHydro1D pde(
      g, model(RestitutionClosure::constant(1.0), RestitutionClosure::constant(1.0)));
  const std::vector<double> U0 = uniform(pde, 0.1, 0.05);
  auto energy = [&](const std::vector<double>& U) {
    double e = 0;
    for (int i = 0; i < g.cells; ++i)
      e += (U[3 * i + 2] + U[3 * i] * g.gravity * pde.cellCentre(i)) * pde.dz();
    return e;
  };
  CvodeIntegrator cv = integrator(pde, U0, 1e-8);
  cv.advanceTo(1.0);
  EXPECT_NEAR(energy(cv.state()) / energy(U0), 1.0, 1e-6);
}

TEST(CvodeIntegrator, BadTolerancesAreRejectedBeforeIntegrating) {
  CvodeOptions o;
  o.rtol = -1;
  o.atol = {1e-8};
  auto f = [](double, const double*, double* d) {
    d[0] = 0;
    return 0;
  };
  EXPECT_THROW(CvodeIntegrator(f, 0, {1.0}, o), std::invalid_argument);
  o.rtol = 1e-6;
  o.atol = {0.0};
  EXPECT_THROW(CvodeIntegrator(f, 0, {1.0}, o), std::invalid_argument);
}

TEST(CvodeIntegrator, FailingRightHandSideGivesErrorNamingCallTimeStepAndComponent) {
  // dy/dt = -y, but the right-hand side fails for good after t = 0.5.
  CvodeOptions o;
  o.rtol = 1e-6;
  o.atol = {1e-10, 1e-10};
  auto f = [](double t, const double* y, double* d) {
    d[0] = -y[0];
    d[1] = -2 * y[1];
    return t > 0.5 ? -1 : 0;
  };
  CvodeIntegrator cv(f, 0, {1.0, 1.0}, o, [](int k) { return "variable " + std::to_string(k); });
  cv.advanceTo(0.4);
  EXPECT_NEAR(cv.state()[0], std::exp(-0.4), 1e-5);
  try {
    cv.advanceTo(1.0);
    FAIL() << "expected a CvodeError";
  } catch (const CvodeError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(e.call(), "CVode");
    EXPECT_NE(msg.find("CV_RHSFUNC_FAIL"), std::string::npos) << msg;
    EXPECT_NE(msg.find("at t = "), std::string::npos) << msg;
    EXPECT_NE(msg.find("last step"), std::string::npos) << msg;
    EXPECT_GT(e.time(), 0.4);
    EXPECT_LT(e.time(), 0.6);
  }
}

TEST(CvodeIntegrator, ExceptionInRightHandSideIsReportedNotSwallowed) {
  CvodeOptions o;
  o.atol = {1e-10};
  auto f = [](double t, const double*, double* d) -> int {
    if (t > 0.1) throw std::runtime_error("closure out of range");
    d[0] = 1;
    return 0;
  };
  CvodeIntegrator cv(f, 0, {0.0}, o);
  try {
    cv.advanceTo(1.0);
    FAIL() << "expected a CvodeError";
  } catch (const CvodeError& e) {
    EXPECT_NE(std::string(e.what()).find("closure out of range"), std::string::npos) << e.what();
  }
}

TEST(HydroSolver, SideWallSinkRemovesTheKineticWallFlux) {
  // Uniform gas at t = 0: fluxes cancel in the middle cell, so its energy rate is
  // -D_c - D_side with D_side = (2 / L_x)(1 - e_w^2) p sqrt(theta / (2 pi)) for a constant
  // wall restitution e_w (physics-hydro.md 2.2): half-Maxwellian flux onto two side walls.
  HydroGeometry g;
  g.cells = 20;
  g.height = 20 * kD;
  g.gravity = 0;
  ConstitutiveModel m = model(RestitutionClosure::constant(1.0), RestitutionClosure::constant(0.8));
  m.side_wall_width = 30 * kD;
  const GranularHydro1D pde(g, m);
  const double nu = 0.3, theta = 0.05;
  const std::vector<double> U = uniform(pde, nu, theta);
  std::vector<double> R(U.size());
  ASSERT_EQ(pde.rightHandSide(0.0, U.data(), R.data()), 0);
  const double rho = U[3 * 10];
  const double p = m.pressure(rho, theta);
  const double expected =
      -2.0 / (30 * kD) * (1 - 0.8 * 0.8) * p * std::sqrt(theta / (2 * std::numbers::pi));
  EXPECT_NEAR(R[3 * 10 + 2] / expected, 1.0, 1e-9);  // e = 1 between particles: D_c = 0
}

TEST(HydroSolver, EnergyBudgetOfADrivenLayerClosesExactly) {
  // In the plate frame with E_tot = sum h (E_i + rho_i g_eff z_i), the discretisation gives
  //   sum_i h (dE_i/dt + g_eff z_i d(rho_i)/dt) = -(sum_i h (D_c + D_side)_i + D_w,bottom +
  //   D_w,lid)
  // exactly (summation by parts: gravity's work uses the face mass fluxes), for any state.
  // Checked on the state of a driven layer in mid-flight after 2.3 cycles (shocks, a gap
  // under the layer), with side walls: relative to the losses, to 1e-9.
  HydroGeometry g;
  g.cells = 100;
  g.height = 30 * kD;
  g.omega = 2 * std::numbers::pi * 10;
  g.amplitude = 4 * 9.81 / (g.omega * g.omega);
  ConstitutiveModel m = model(RestitutionClosure::dry(0.1), RestitutionClosure::dry(0.1));
  m.side_wall_width = 30 * kD;
  const GranularHydro1D pde(g, m);
  HydroRunOptions o;
  o.min_cycles = o.max_cycles = 3;
  HydroSimulation sim(pde, 300, 30 * kD, o);
  CvodeOptions co;
  co.atol.assign(pde.size(), 1e-12);
  co.band_upper = co.band_lower = GranularHydro1D::kHalfBand;
  CvodeIntegrator cv(
      [&pde](double t, const double* y, double* d) { return pde.rightHandSide(t, y, d); }, 0.0,
      sim.initialState(), co);
  const double t = 0.23;
  cv.advanceTo(t);
  const std::vector<double>& U = cv.state();
  std::vector<double> R(U.size());
  ASSERT_EQ(pde.rightHandSide(t, U.data(), R.data()), 0);
  const double h = pde.dz(), geff = pde.effectiveGravity(t);
  double lhs = 0, losses = 0;
  for (int i = 0; i < g.cells; ++i) {
    lhs += h * (R[3 * i + 2] + geff * pde.cellCentre(i) * R[3 * i]);
    const double rho = U[3 * i], u = U[3 * i + 1] / rho, theta = U[3 * i + 2] / rho - 0.5 * u * u;
    const LocalState l = m.evaluate(rho, theta);
    losses += h * (l.cooling + m.sideWallSink(l.p, theta));
    if (i == 0 || i == g.cells - 1) losses += m.wallDissipation(l.p, theta);
  }
  EXPECT_GT(losses, 0.0);
  EXPECT_NEAR(lhs / -losses, 1.0, 1e-9);
}
