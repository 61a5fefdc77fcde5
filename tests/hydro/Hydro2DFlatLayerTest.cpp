// A flat layer (no perturbation) in the 2D solver is the 1D solver's layer: every column is
// GranularHydro1D exactly (Hydro2DOperatorTest), so the whole run, with its own solver (BDF
// Newton-Krylov with the column preconditioner against the 1D banded direct solve), must give
// the 1D centre-of-mass trajectory, its period and the same impact front (docs/hydro.md,
// "The 2D model").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "HydroTestSupport.hpp"
#include "hydro/GranularHydro2D.hpp"
#include "hydro/HydroSimulation.hpp"
#include "hydro/HydroSimulation2D.hpp"

using namespace granwave::hydro;
using test::kD;
using test::kMass;

namespace {

using test::paperGeometry;  // the paper's dry scene's box and drive, ramped over two cycles

// The smallest P in 1..4 for which the last P cycles of the centre of mass repeat the P before
// to `tolerance` of its excursion (HydroSimulation's criterion), 0 if none.
int periodOf(const std::vector<double>& com, int M, double tolerance) {
  const auto [lo, hi] = std::minmax_element(com.begin(), com.end());
  const double excursion = *hi - *lo;
  const int n = static_cast<int>(com.size());
  for (int P = 1; P <= 4; ++P) {
    if (2 * P * M > n) break;
    double worst = 0;
    for (int k = n - P * M; k < n; ++k) worst = std::max(worst, std::abs(com[k] - com[k - P * M]));
    if (worst <= tolerance * excursion) return P;
  }
  return 0;
}

}  // namespace

TEST(Hydro2DFlatLayer, FollowsThe1DCentreOfMassTrajectoryAndPeriod) {
  // Both solvers at rtol 1e-6 on 40 cells per column, from the layer spread over the box: the
  // two integrations differ by their error control only (~rtol x the cycles' growth), so the
  // trajectories must agree far inside the 1 % of the excursion; 1 % is asserted.
  const ConstitutiveModel m =
      test::beadModel(RestitutionClosure::dry(0.1), RestitutionClosure::dry(0.1));
  const HydroGeometry g = paperGeometry(40);
  const double M = 300 * kMass / (30 * kD);
  const int cycles = 10, phases = 50;

  const GranularHydro1D pde(g, m, M);
  HydroRunOptions o1;
  o1.cvode.rtol = 1e-6;
  o1.samples_per_cycle = phases;
  o1.min_cycles = cycles;
  o1.max_cycles = cycles;
  o1.start = HydroRunOptions::Start::Spread;
  const HydroResult one = HydroSimulation(pde, o1).run();
  ASSERT_EQ(one.cycles, cycles);

  const int columns = 3;
  const GranularHydro2D op(g, {columns, 30 * kD, true}, m,
                           std::vector<double>(columns * g.cells, M / g.cells));
  Hydro2DRunOptions o2;
  o2.rtol = 1e-6;
  o2.samples_per_cycle = phases;
  o2.cycles = cycles;
  o2.spread = true;
  const Hydro2DResult two = HydroSimulation2D(op, o2).run();
  ASSERT_EQ(two.com_per_phase.size(), one.com_per_phase.size());

  const std::vector<double>& a = one.com_per_phase;
  const auto [lo, hi] = std::minmax_element(a.begin() + 2 * phases, a.end());
  const double excursion = *hi - *lo;
  ASSERT_GT(excursion, kD);  // the layer flies
  double worst = 0;
  for (std::size_t k = 0; k < a.size(); ++k)
    worst = std::max(worst, std::abs(two.com_per_phase[k] - a[k]));
  RecordProperty("com_difference_over_excursion", std::to_string(worst / excursion));
  EXPECT_LT(worst, 0.01 * excursion);

  const int period1 = periodOf(a, phases, 0.02);
  ASSERT_GT(period1, 0) << "the 1D layer is periodic after " << cycles << " cycles";
  EXPECT_EQ(periodOf(two.com_per_phase, phases, 0.02), period1);
}
