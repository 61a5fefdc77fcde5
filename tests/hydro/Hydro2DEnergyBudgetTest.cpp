// The 2D operator's energy budget (GranularHydro2D::energyRates; HydroSimulation2D's phase
// budgets): the rates, with the walls' contact drift named, are the exact time derivative of
// the lab-frame energy along the operator's flow for layers whose columns differ (sloped
// interfaces, horizontal flow, mass moving between columns), pressed into the plate and the
// lid or in flight, and their integrals over the phases of a run close its energy balance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "Hydro2DTestSupport.hpp"
#include "hydro/HydroSimulation2D.hpp"
#include "hydro/Layer2DStart.hpp"

namespace granwave::hydro {
namespace {

using test::kD;
using test::kMass;

constexpr int kColumns = 8, kCells = 20;

// dE/dt along the flow: central differences E(t + h, U + h R) - E(t - h, U - h R) at h and
// h/2, Richardson-extrapolated (truncation O(h^4)).
double energyDerivative(const GranularHydro2D& op, double t, const std::vector<double>& U) {
  std::vector<double> R(U.size());
  EXPECT_EQ(op.rightHandSide(t, U.data(), R.data()), 0);
  auto central = [&](double h) {
    std::vector<double> up(U), down(U);
    for (int k = 0; k < op.layerSize(); ++k) {
      up[k] += h * R[k];
      down[k] -= h * R[k];
    }
    return (op.labEnergy(t + h, up.data()) - op.labEnergy(t - h, down.data())) / (2 * h);
  };
  const double h = 2e-8;
  return (4 * central(h / 2) - central(h)) / 3;
}

// A layer in flight in a box 0.2 m high: the 1D test column lifted one diameter, each column
// shifted by up to 0.3 d and tilted by up to 0.5 d over its height, horizontal velocities of
// 0.3 m/s varying along x, and mass moved between the columns.
std::vector<double> tiltedLayerInFlight(const GranularHydro2D& op, const GranularHydro1D& pde) {
  std::vector<double> U(op.size(), 0.0);
  const std::vector<double> V = test::rumpledColumn(pde, 3);
  for (int i = 0; i < op.columns(); ++i) {
    const double x = 2 * std::numbers::pi * i / op.columns();
    std::vector<double> W = V;
    for (int j = 0; j <= op.cells(); ++j)
      W[pde.heightIndex(j)] += kD * (1 + 0.3 * std::cos(x) + 0.5 * std::sin(x) * j / op.cells());
    test::putColumn(op, pde, W, i, U);
    for (int k = 0; k < op.cells(); ++k) {
      if (op.wallFace(i)) continue;
      U[op.horizontalVelocityIndex(i, k)] = 0.3 * std::cos(x + 0.1 * k);
      U[op.fluxIndex(i, k)] = 0.05 * pde.cellMass() * op.dx() * std::sin(x + 0.3 * k);
    }
  }
  return U;
}

struct BudgetCase {
  bool periodic, rough, in_flight;
};

void expectRatesAreTheEnergysDerivative(const BudgetCase& c) {
  const ConstitutiveModel m =
      c.rough ? test::wetModel(true)
              : test::beadModel(RestitutionClosure::dry(0.1), RestitutionClosure::dry(0.1));
  HydroGeometry g = test::drivenBox(kCells);
  if (c.in_flight) g.height = 0.2;
  const GranularHydro1D pde(g, m, 300 * kMass / (30 * kD));
  const GranularHydro2D op(g, {kColumns, 24 * kD, c.periodic}, m,
                           std::vector<double>(kColumns * kCells, pde.cellMass()));
  const std::vector<double> U =
      c.in_flight ? tiltedLayerInFlight(op, pde) : test::rumpledLayer(op, pde, 7);
  const double t = 0.013;
  const GranularHydro2D::EnergyRates r = op.energyRates(t, U.data());
  const double balance = r.plate_work - r.collisional_loss - r.friction_loss - r.wall_loss -
                         r.side_wall_loss + r.contact_drift;
  const double scale = std::max(
      {std::abs(r.plate_work), r.collisional_loss, r.friction_loss, r.wall_loss, r.side_wall_loss});
  EXPECT_NEAR(energyDerivative(op, t, U) / scale, balance / scale, 1e-6);
  if (c.in_flight) {  // no node within a wall's range: the smooth contact's tail only
    EXPECT_LT(std::abs(r.contact_drift), 1e-12 * scale);
  }
}

}  // namespace

TEST(Hydro2DEnergyBudget, RatesAndContactDriftAreTheLabEnergysDerivativeForPressedColumns) {
  // rumpledLayer: every column's own random state, its bottom node inside the plate's contact
  // range and its top pressed into the lid, random horizontal velocities and mass fluxes.
  // dE/dt is the physical rates plus the contact drift (the walls' elastic energy changed by
  // the boundary nodes' drift, which no force answers): without that term they differ by
  // 26-41 % of the largest power here; with it, measured at most 1.1e-9 of it (the
  // differences' truncation and round-off).
  expectRatesAreTheEnergysDerivative({true, false, false});
  expectRatesAreTheEnergysDerivative({false, false, false});
  expectRatesAreTheEnergysDerivative({true, true, false});
}

TEST(Hydro2DEnergyBudget, RatesAreTheLabEnergysDerivativeForATiltedLayerInFlight) {
  // No contact: gravity, collisions and the flow along sloped layers. With the drift as the
  // mean face velocity times the slope, the mass moved between columns changed the potential
  // energy by more than the nodes' drift did: 1.2e-4, 1.3e-5 and 2.5e-5 of the collisional
  // loss (the three cases); measured now at most 4e-8 of it.
  expectRatesAreTheEnergysDerivative({true, false, true});
  expectRatesAreTheEnergysDerivative({false, false, true});
  expectRatesAreTheEnergysDerivative({true, true, true});
}

TEST(Hydro2DEnergyBudget, PhaseBudgetsCloseOverAPerturbedRun) {
  // The paper's dry drive on 8 columns of 20 cells, column masses perturbed by 5 % RMS,
  // spread and falling from t = 0, rtol 1e-6, three cycles. Over each of the last 100 phases
  // the residual E(end) - E(start) - (work - losses) is the integration error and the contact
  // drift's integral (the bottom nodes' slopes while in contact are small here): asserted below
  // 5e-3 of the phase's largest term (work, a loss or the energy change; as the 1D budget's
  // test; measured at most 1.3e-3), and summed below 1e-4 of the plate's throughput
  // (measured 5e-6). The rates' error of the drift before the mass-flux weighting was too
  // small to show here (this test passed with it): the tests above are the sharp ones.
  const ConstitutiveModel m =
      test::beadModel(RestitutionClosure::dry(0.1), RestitutionClosure::dry(0.1));
  const GranularHydro2D op(test::drivenBox(kCells), {kColumns, 24 * kD, true}, m,
                           perturbedCellMasses(kColumns, kCells, 300 * kMass / (30 * kD), 0.05, 42),
                           {}, true);
  Hydro2DRunOptions o;
  o.rtol = 1e-6;
  o.samples_per_cycle = 50;
  o.cycles = 3;
  o.window_cycles = 2;
  const Hydro2DResult r = HydroSimulation2D(op, o).run();
  ASSERT_EQ(r.window.size(), 100u);
  double sum = 0, throughput = 0;
  for (const Hydro2DPhase& ph : r.window) {
    const PhaseBudget& b = ph.budget;
    const double largest = std::max(
        {std::abs(b.plate_work), b.collisional_loss, b.wall_loss, std::abs(b.energy_change)});
    EXPECT_LT(std::abs(b.closure()), 5e-3 * largest) << "t = " << ph.time;
    sum += b.closure();
    throughput += std::abs(b.plate_work);
  }
  EXPECT_GT(throughput, 0);
  EXPECT_LT(std::abs(sum), 1e-4 * throughput);
}

}  // namespace granwave::hydro
