// The Lagrangian granular-hydrodynamics operator (hydro/GranularHydro1D) against theory:
// Haff's law, the exact discrete hydrostatic equilibrium of a resting layer, conservation of
// total energy and the energy budget of a driven layer, positivity of the temperature, the
// side-wall sink, and the CVODE wrapper's failure paths.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "HydroTestSupport.hpp"
#include "hydro/CvodeIntegrator.hpp"
#include "hydro/HydroSimulation.hpp"
#include "hydro/SettledLayer.hpp"

using namespace granwave::hydro;
using test::kD;
using test::kMass;

namespace {

// zeta = sqrt(pi) (1 - e^2) g2 n sigma sqrt(theta), the 2D Enskog cooling rate (Haff 1983;
// docs/hydro.md, "Cooling").
double haffRate(const ConstitutiveModel& m, double e, double nu, double theta) {
  return std::sqrt(std::numbers::pi) * (1 - e * e) * m.pair_correlation.g2(nu) * nu / test::kDisk *
         kD * std::sqrt(theta);
}

// The elastic energy stored in a wall contact at a gap: the integral of its stress out to the
// end of its range (Simpson, 2000 panels).
double wallEnergy(const GranularHydro1D& pde, double gap) {
  const double end = pde.regularisation().wall_contact_range * kD * 1.2;
  if (gap >= end) return 0;
  const int n = 2000;
  const double h = (end - gap) / n;
  double sum = 0;
  for (int k = 0; k <= n; ++k) {
    const double w = k == 0 || k == n ? 1 : (k % 2 ? 4 : 2);
    sum += w * pde.contactStress(gap + k * h, 0, 0, 0);
  }
  return sum * h / 3;
}

// Kinetic + internal + potential + wall-contact energy (kg m/s^2 = J/m): what an elastic
// closed system conserves (its contact pressure is nil below the contact onset).
double totalEnergy(const GranularHydro1D& pde, const std::vector<double>& U) {
  const int N = pde.cells();
  const double mc = pde.cellMass(), g = pde.geometry().gravity;
  double E = wallEnergy(pde, U[pde.heightIndex(0)]) +
             wallEnergy(pde, pde.geometry().height - U[pde.heightIndex(N)]);
  for (int j = 0; j <= N; ++j) {
    const double m = j == 0 || j == N ? 0.5 * mc : mc, u = U[pde.velocityIndex(j)];
    E += 0.5 * m * u * u + m * g * U[pde.heightIndex(j)];
    if (j < N) E += mc * pde.temperature(U.data(), j);
  }
  return E;
}

}  // namespace

TEST(HydroSolver, UniformGasCoolsAtHaffsRateInEveryCell) {
  // A uniform gas at rest with elastic walls and no gravity: nothing moves, and every cell
  // cools at d(theta)/dt = -zeta theta. Exact for the operator but for the 5e-8 by which the
  // closures' packing-mapped density differs from the cell's (GranularHydro1D::cellView):
  // asserted to 1e-7.
  const double e = 0.9, nu = 0.3, theta = 0.1;
  const ConstitutiveModel m =
      test::beadModel(RestitutionClosure::constant(e), RestitutionClosure::constant(1.0));
  const test::Column c = test::uniformGas(m, 40, 30 * kD, nu, theta);
  std::vector<double> R(c.U.size());
  ASSERT_EQ(c.pde->rightHandSide(0.0, c.U.data(), R.data()), 0);
  const GranularHydro1D::CellView v = c.pde->cellView(c.U.data(), 20);  // as the closures see it
  const double rate = -haffRate(m, e, m.areaFraction(v.rho), v.theta) * v.theta;
  for (int i = 0; i < 40; ++i) {
    EXPECT_NEAR(c.pde->temperatureRate(c.U.data(), R.data(), i) / rate, 1.0, 1e-7) << "cell " << i;
    EXPECT_LT(std::abs(R[c.pde->velocityIndex(i)]), 1e-9 * 9.81) << "node " << i;
  }
}

TEST(HydroSolver, UniformGasFollowsHaffsLawInTime) {
  // Integrated: theta(t) = theta0/(1 + t/tau)^2, tau = 2/zeta(theta0). The walls are a stiff
  // contact, not rigid: as the pressure falls 16-fold by t = 3 tau the contact lets the gas
  // expand by 2 x 0.009 sigma in 30 sigma (6e-4 of its volume), which cools it adiabatically
  // and slows its collisions, each by ~1e-3: asserted to 5e-3 (rtol 1e-8).
  const double e = 0.9, nu = 0.3, theta0 = 0.1;
  const ConstitutiveModel m =
      test::beadModel(RestitutionClosure::constant(e), RestitutionClosure::constant(1.0));
  const test::Column c = test::uniformGas(m, 40, 30 * kD, nu, theta0);
  const double rho = test::cellDensity(*c.pde, c.U, 20);
  const double tau = 2 / haffRate(m, e, m.areaFraction(rho), theta0);
  CvodeIntegrator cv = test::integrator(*c.pde, c.U, 1e-8);
  for (double s : {0.5, 1.0, 3.0}) {
    cv.advanceTo(s * tau);
    const double theta = c.pde->temperature(cv.state().data(), 20);
    EXPECT_NEAR(theta / (theta0 / ((1 + s) * (1 + s))), 1.0, 5e-3) << "t = " << s << " tau";
  }
}

TEST(HydroSolver, ClosedElasticGasConservesTotalEnergy) {
  // Elastic particles and walls under gravity, started with a velocity field: kinetic,
  // internal, potential and wall-contact energy are exchanged, their sum is conserved by the
  // semi-discrete operator (the stresses' work on the nodes is the cells' heating, the
  // dashpot's work heats the wall cell). rtol 1e-8: 1e-6 of the energy.
  const ConstitutiveModel m =
      test::beadModel(RestitutionClosure::constant(1.0), RestitutionClosure::constant(1.0));
  test::Column c = test::uniformGas(m, 40, 30 * kD, 0.2, 0.05, 9.81);
  for (int j = 1; j < 40; ++j)
    c.U[c.pde->velocityIndex(j)] = 0.2 * std::sin(std::numbers::pi * j / 40);
  const double E0 = totalEnergy(*c.pde, c.U);
  CvodeIntegrator cv = test::integrator(*c.pde, c.U, 1e-8);
  cv.advanceTo(0.05);
  EXPECT_NEAR(totalEnergy(*c.pde, cv.state()) / E0, 1.0, 1e-6);
}

TEST(HydroSolver, EnergyBudgetOfADrivenLayerClosesExactly) {
  // A dry layer in flight (both boundary nodes away from the walls): the rate of kinetic +
  // internal + contact-elastic energy equals the work of the effective gravity minus the
  // collisional cooling, d/dt E = -g_eff sum m_j u_j - sum D_c l_i, with the contact
  // pressure's elastic energy changing at -sum p_c du_i. An identity of the operator (1e-9).
  ConstitutiveModel m = test::beadModel(RestitutionClosure::dry(0.1), RestitutionClosure::dry(0.1));
  const HydroGeometry g = test::paperGeometry(40);
  const GranularHydro1D pde(g, m, 300 * kMass / (30 * kD));
  CvodeIntegrator cv = test::integrator(pde, settledLayer(pde, 1e-3 * 9.81 * kD), 1e-6);
  // Find a moment of flight: the bottom node clear of the plate, the top clear of the lid.
  double t = 0.3;
  for (;; t += 0.002) {
    cv.advanceTo(t);
    const auto& y = cv.state();
    if (y[pde.heightIndex(0)] > 0.5 * kD && y[pde.heightIndex(40)] < g.height - 0.5 * kD) break;
    ASSERT_LT(t, 0.6) << "no flight found";
  }
  const std::vector<double> U = cv.state();
  std::vector<double> R(U.size());
  ASSERT_EQ(pde.rightHandSide(t, U.data(), R.data()), 0);
  const double mc = pde.cellMass();
  double rate = 0, work = 0, loss = 0, scale = 0;
  for (int j = 0; j <= 40; ++j) {
    const double mj = j == 0 || j == 40 ? 0.5 * mc : mc;
    const double u = U[pde.velocityIndex(j)];
    rate += mj * u * R[pde.velocityIndex(j)];
    work -= pde.effectiveGravity(t) * mj * u;
    scale += std::abs(mj * u * R[pde.velocityIndex(j)]);
  }
  for (int i = 0; i < 40; ++i) {
    const GranularHydro1D::CellView c = pde.cellView(U.data(), i);  // as the closures see it
    const double length = U[pde.heightIndex(i + 1)] - U[pde.heightIndex(i)];
    const double du = U[pde.velocityIndex(i + 1)] - U[pde.velocityIndex(i)];
    rate += mc * pde.temperatureRate(U.data(), R.data(), i) -
            m.contact.pressure(m.areaFraction(c.rho)) * du;
    loss += m.evaluate(c.rho, c.theta).cooling * length;
  }
  EXPECT_NEAR(rate, work - loss, 1e-9 * scale);
}

// The solver's step is at most half a phase (solverOptions), which forces 2 M steps a cycle:
// with M = 6000 phases that alone is past the 10000 steps a cycle that mean "no progress", so
// the budget counts them on top (HydroSimulation::stepBudget). Checked cycle by cycle, so two
// cycles of the driven layer show it (as `granwave hydro` runs them: 20 cells, dry beads).
TEST(HydroSolver, FinePhaseResolutionRunsWithinTheStepBudget) {
  ConstitutiveModel m = test::beadModel(RestitutionClosure::dry(0.1), RestitutionClosure::dry(0.1));
  const GranularHydro1D pde(test::paperGeometry(20), m, 300 * kMass / (30 * kD));
  HydroRunOptions o;
  o.samples_per_cycle = 6000;
  o.max_cycles = 2;
  HydroResult r;
  ASSERT_NO_THROW(r = HydroSimulation(pde, o).run());
  ASSERT_EQ(r.steps_per_cycle.size(), 2U);
  for (long steps : r.steps_per_cycle) EXPECT_GT(steps, o.max_steps_per_cycle);
}

TEST(HydroSolver, TemperatureOfAColdCellAmongHotOnesDoesNotFall) {
  // Positivity by construction (docs/hydro.md): every sink of a cell's temperature vanishes
  // with it (pressure work, cooling, wall losses), while conduction from hotter neighbours
  // feeds it. A cell at 1e-14 m^2/s^2 inside a gas at 0.05: its rate is positive.
  const ConstitutiveModel m =
      test::beadModel(RestitutionClosure::wet(0.91, 0.0698), RestitutionClosure::wet(0.91, 0.0698));
  test::Column c = test::uniformGas(m, 40, 30 * kD, 0.5, 0.05);
  c.U[c.pde->temperatureIndex(20)] = c.pde->temperatureUnknown(1e-14);
  for (int j = 0; j <= 40; ++j)  // expanding everywhere: the pressure work cools
    c.U[c.pde->velocityIndex(j)] = 0.3 * (j - 20.0) / 20;
  std::vector<double> R(c.U.size());
  ASSERT_EQ(c.pde->rightHandSide(0.0, c.U.data(), R.data()), 0);
  EXPECT_GT(R[c.pde->temperatureIndex(20)], 0);
}

TEST(HydroSolver, SideWallSinkRemovesTheKineticWallFlux) {
  // Uniform elastic gas at rest: the middle cell's temperature falls only by the side-wall
  // sink D_side = (2 / L_x)(1 - e_w^2) p sqrt(theta / (2 pi)) for a constant wall restitution
  // e_w: half-Maxwellian flux onto two side walls (docs/hydro.md, "Walls").
  ConstitutiveModel m =
      test::beadModel(RestitutionClosure::constant(1.0), RestitutionClosure::constant(0.8));
  m.side_wall_width = 30 * kD;
  const double nu = 0.3, theta = 0.05;
  const test::Column c = test::uniformGas(m, 20, 20 * kD, nu, theta);
  std::vector<double> R(c.U.size());
  ASSERT_EQ(c.pde->rightHandSide(0.0, c.U.data(), R.data()), 0);
  const GranularHydro1D::CellView v = c.pde->cellView(c.U.data(), 10);
  const double p = m.evaluate(v.rho, v.theta).p_kinetic;
  const double expected =
      -2.0 / (30 * kD) * (1 - 0.8 * 0.8) * p * std::sqrt(v.theta / (2 * std::numbers::pi)) / v.rho;
  EXPECT_NEAR(c.pde->temperatureRate(c.U.data(), R.data(), 10) / expected, 1.0, 1e-7);  // as above
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

TEST(CvodeIntegrator, RefusedNonFiniteRatesAreCountedAndTheLastOneNamed) {
  // From t = 0.5 on, the rate of variable 1 is not finite and the right-hand side refuses it
  // (flag 1, as the operators do): CVODE shortens its step until it gives up, and the error
  // names the variable (after failed Newton iterations CVODE may have no local error to name).
  CvodeOptions o;
  o.atol = {1e-10, 1e-10};
  auto f = [](double t, const double* y, double* d) {
    d[0] = -y[0];
    d[1] = t > 0.5 ? std::numeric_limits<double>::quiet_NaN() : -y[1];
    return std::isfinite(d[1]) ? 0 : 1;
  };
  CvodeIntegrator cv(f, 0, {1.0, 1.0}, o, [](int k) { return "variable " + std::to_string(k); });
  try {
    cv.advanceTo(1.0);
    FAIL() << "expected a CvodeError";
  } catch (const CvodeError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(" right-hand side(s) not finite since the last output, the last in the "
                       "rate of variable 1"),
              std::string::npos)
        << msg;
    // CVODE retried: more than one refusal, counted from the last output (t = 0) on.
    const std::size_t semi = msg.rfind("; ");
    ASSERT_NE(semi, std::string::npos) << msg;
    EXPECT_GT(std::stol(msg.substr(semi + 2)), 1) << msg;
  }
}
