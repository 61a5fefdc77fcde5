// The continuum's energy budget (GranularHydro1D::energyRates, HydroSimulation's phase
// budgets): the rates are the exact time derivative of the lab-frame energy along the
// operator's flow, and their integral over each phase closes the energy balance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "HydroTestSupport.hpp"
#include "hydro/HydroSimulation.hpp"
#include "hydro/SettledLayer.hpp"

namespace granwave::hydro {
namespace {

using test::kD;
using test::kMass;

// dE/dt along the flow by central differences in time: E(t + h, U + h R) - E(t - h, U - h R).
double energyDerivative(const GranularHydro1D& pde, double t, const std::vector<double>& U) {
  std::vector<double> R(U.size()), up(U.size()), down(U.size());
  EXPECT_EQ(pde.rightHandSide(t, U.data(), R.data()), 0);
  const double h = 1e-8;
  for (std::size_t k = 0; k < U.size(); ++k) {
    up[k] = U[k] + h * R[k];
    down[k] = U[k] - h * R[k];
  }
  return (pde.labEnergy(t + h, up.data()) - pde.labEnergy(t - h, down.data())) / (2 * h);
}

void expectRatesAreTheEnergysDerivative(const ConstitutiveModel& m) {
  const GranularHydro1D pde(test::paperGeometry(40), m, 300 * kMass / (30 * kD));
  CvodeIntegrator cv = test::integrator(pde, spreadLayer(pde, 1e-3 * 9.81 * kD), 1e-6);
  int checked = 0;
  for (double t = 0.05; t < 0.5; t += 0.011) {  // landing, rest, lift-off and flight
    cv.advanceTo(t);
    const std::vector<double>& U = cv.state();
    const GranularHydro1D::EnergyRates r = pde.energyRates(t, U.data());
    const double balance =
        r.plate_work - r.collisional_loss - r.friction_loss - r.wall_loss - r.side_wall_loss;
    const double scale =
        std::max({std::abs(r.plate_work), r.collisional_loss, r.wall_loss, r.friction_loss, 1e-6});
    EXPECT_NEAR(energyDerivative(pde, t, U) / scale, balance / scale, 1e-4) << "t = " << t;
    ++checked;
  }
  EXPECT_GT(checked, 30);
}

TEST(EnergyBudget, RatesAreTheTimeDerivativeOfTheLabEnergySmoothDisks) {
  // Central differences of E along the flow (step 1e-8 s): truncation ~1e-7 of the largest
  // power, round-off ~1e-6; asserted to 1e-4 of the largest power at 41 moments of a cycle.
  expectRatesAreTheEnergysDerivative(
      test::beadModel(RestitutionClosure::dry(0.1), RestitutionClosure::dry(0.1)));
}

TEST(EnergyBudget, RatesAreTheTimeDerivativeOfTheLabEnergyRoughParticlesWithSideWalls) {
  ConstitutiveModel m = test::beadModel(RestitutionClosure::dry(0.1), RestitutionClosure::dry(0.1));
  m.rough = RoughParticles{true, 0.5, 0.35, 0.4};
  m.side_wall_width = 30 * kD;
  expectRatesAreTheEnergysDerivative(m);
}

// The paper's drive on 300 dry beads in 60 cells, from the spread layer over 8 cycles, with
// the budget's quadratures: over each phase of the final window the residual E(end) -
// E(start) - (work - losses) below 5e-3 of the phase's largest term, and summed over the
// window below 1e-4 of the plate's throughput.
void expectPhaseBudgetsClose(const HydroRegularisation& walls, double rtol) {
  const ConstitutiveModel m =
      test::beadModel(RestitutionClosure::dry(0.1), RestitutionClosure::dry(0.1));
  const GranularHydro1D pde(test::paperGeometry(60), m, 300 * kMass / (30 * kD), walls, true);
  HydroRunOptions o;
  o.cvode.rtol = rtol;
  o.samples_per_cycle = 100;
  o.max_cycles = 8;
  o.min_cycles = 2;
  o.start = HydroRunOptions::Start::Spread;
  const HydroResult r = HydroSimulation(pde, o).run();
  ASSERT_FALSE(r.window.empty());
  // Hard walls: at least a landing and a lift-off in each cycle after the two of the ramp.
  if (walls.walls == WallModel::Hard) {
    EXPECT_GE(r.stats.events, 2 * (r.cycles - 2));
  }
  double residual = 0, throughput = 0, worst = 0;
  for (const HydroPhase& ph : r.window) {
    const PhaseBudget& b = ph.budget;
    const double largest =
        std::max({std::abs(b.plate_work), b.collisional_loss, b.wall_loss, 1e-12});
    EXPECT_LT(std::abs(b.closure()), 5e-3 * largest) << "t = " << ph.time;
    worst = std::max(worst, std::abs(b.closure()) / largest);
    residual += b.closure();
    throughput += std::abs(b.plate_work);
  }
  EXPECT_LT(std::abs(residual), 1e-4 * throughput);
  ::testing::Test::RecordProperty("worst_phase_closure", std::to_string(worst));
}

TEST(EnergyBudget, PhaseBudgetsCloseToTheIntegrationTolerance) {
  // The rates integrated by CVODE with the layer (quadratures outside the error test): over
  // each phase the residual is the integration error of the layer's own unknowns at rtol
  // 1e-6: largest in the landing phase, where the plate's force rises within the phase
  // (measured 1.6-1.9e-3 of the plate's work there, below 1e-5 elsewhere).
  expectPhaseBudgetsClose({}, 1e-6);
}

TEST(EnergyBudget, PhaseBudgetsCloseThroughHardWallLandingsAndLiftOffs) {
  // Hard walls (WallModel::Hard): the landing's loss of the node's motion heats the wall cell
  // (no energy leaves), the wall's impulse and the held node's reaction do the plate's work.
  // The node's instant stop is sharper than the spring's landing: at rtol 1e-6 the landing
  // phase's residual was 1.7e-2 of the plate's work; at rtol 1e-8 it is within the bounds
  // (measured 2.2e-3 of the landing phase's plate work, against 5e-3 asserted).
  HydroRegularisation hard;
  hard.walls = WallModel::Hard;
  expectPhaseBudgetsClose(hard, 1e-8);
}

}  // namespace
}  // namespace granwave::hydro
