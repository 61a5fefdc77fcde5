// The analytic (forward-mode differentiated) banded Jacobian of the operator against central
// finite differences of its right-hand side, on a state away from equilibrium in every
// variable (a wet layer in flight, compressed near the plate and dilute on top, hot and cold
// cells, both closure sets). Agreement is limited by the finite differences: a relative step
// 1e-6 gives errors ~1e-6 of each row's largest entry through the O(h^2) term and round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "HydroTestSupport.hpp"

using namespace granwave::hydro;
using test::kD;
using test::kMass;

namespace {

void expectJacobianMatchesFiniteDifferences(TransportSet transport) {
  ConstitutiveModel m =
      test::beadModel(RestitutionClosure::wet(0.91, 0.0698), RestitutionClosure::wet(0.91, 0.0698));
  m.transport = transport;
  m.side_wall_width = 30 * kD;
  HydroGeometry g;
  g.cells = 24;
  g.height = 30 * kD;
  g.omega = 2 * std::numbers::pi * 10;
  g.amplitude = 4 * 9.81 / (g.omega * g.omega);
  const GranularHydro1D pde(g, m, 300 * kMass / (30 * kD));
  const int N = g.cells, n = pde.size();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U01(0, 1);
  std::vector<double> U(n);
  double z = 0.02 * kD;  // the bottom node inside the plate's contact range
  for (int j = 0; j <= N; ++j) {
    U[pde.heightIndex(j)] = z;
    U[pde.velocityIndex(j)] = 0.5 * (U01(rng) - 0.5);
    if (j == N) break;
    const double nu = j < 6 ? 0.6 + 0.25 * U01(rng) : 0.02 + 0.5 * U01(rng);
    U[pde.temperatureIndex(j)] = pde.temperatureUnknown(0.05 * (0.01 + U01(rng)));
    z += pde.cellMass() / test::densityOf(nu);
  }
  std::vector<double> J(static_cast<std::size_t>(n) * n, 0.0);
  ASSERT_EQ(pde.jacobian(0.013, U.data(), [&](int r, int c, double v) { J[r * n + c] = v; }), 0);
  std::vector<double> row_max(n, 0.0);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) row_max[r] = std::max(row_max[r], std::abs(J[r * n + c]));
  std::vector<double> fp(n), fm(n);
  for (int c = 0; c < n; ++c) {
    const double h = 1e-6 * std::abs(U[c]) + 1e-12;
    std::vector<double> Up = U, Um = U;
    Up[c] += h;
    Um[c] -= h;
    ASSERT_EQ(pde.rightHandSide(0.013, Up.data(), fp.data()), 0);
    ASSERT_EQ(pde.rightHandSide(0.013, Um.data(), fm.data()), 0);
    for (int r = 0; r < n; ++r) {
      const double fd = (fp[r] - fm[r]) / (2 * h);
      EXPECT_NEAR(J[r * n + c], fd, 1e-5 * row_max[r])
          << pde.componentName(r) << " by " << pde.componentName(c);
    }
  }
}

}  // namespace

TEST(HydroJacobian, JenkinsRichmanJacobianEqualsFiniteDifferences) {
  expectJacobianMatchesFiniteDifferences(TransportSet::JenkinsRichman);
}

TEST(HydroJacobian, GarzoDuftyJacobianEqualsFiniteDifferences) {
  expectJacobianMatchesFiniteDifferences(TransportSet::GarzoDufty);
}
