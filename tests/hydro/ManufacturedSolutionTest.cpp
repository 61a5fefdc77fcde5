// Observed order of spatial accuracy on a manufactured state (physics-hydro.md 5.7). A smooth
// steady state with u = 0 under gravity - density falling exponentially, temperature rising
// linearly (monotone, so the limiter is not at an extremum) - is fed to the semi-discrete
// operator. Its exact value at cell centres is
//   d(rho)/dt = 0,  d(rho u)/dt = -p' - rho g,  dE/dt = (kappa_theta theta')' - D_c,
// with the derivatives of the closures taken by central differences at 1e-5 of the height
// (error ~1e-10, far below the truncation error). The truncation error (max over the
// interior, 6 cells from each wall left out: the wall layer is first order) must fall at
// second order: observed order >= 1.8 between 50, 100, 200 and 400 cells.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "HydroTestSupport.hpp"
#include "hydro/GranularHydro1D.hpp"

using namespace granwave::hydro;

namespace {
using test::kD;
using test::kMass;
constexpr double kL = 0.06;
const double kRho0 = 0.4 * kMass / test::kDisk;

double rhoStar(double z) { return kRho0 * std::exp(-z / (0.8 * kL)); }
double thetaStar(double z) { return 0.05 * (1 + z / kL); }
double dThetaStar(double) { return 0.05 / kL; }

struct Errors {
  double momentum, energy;
};

Errors truncationError(int cells) {
  const ConstitutiveModel m =
      test::beadModel(RestitutionClosure::dry(0.1), RestitutionClosure::dry(0.1));
  HydroGeometry g;
  g.cells = cells;
  g.height = kL;
  const GranularHydro1D pde(g, m);
  std::vector<double> U(pde.size()), R(pde.size());
  for (int i = 0; i < cells; ++i) {
    const double z = pde.cellCentre(i);
    U[3 * i] = rhoStar(z);
    U[3 * i + 2] = rhoStar(z) * thetaStar(z);
  }
  EXPECT_EQ(pde.rightHandSide(0.0, U.data(), R.data()), 0);
  const double dz = 1e-5 * kL;
  auto p = [&](double z) { return m.pressure(rhoStar(z), thetaStar(z)); };
  auto heat = [&](double z) {  // kappa_theta theta'
    return m.evaluate(rhoStar(z), thetaStar(z)).kappa_theta * dThetaStar(z);
  };
  Errors e{0, 0};
  double scale_m = 0, scale_e = 0;
  for (int i = 6; i + 6 < cells; ++i) {
    const double z = pde.cellCentre(i);
    const double exact_m = -(p(z + dz) - p(z - dz)) / (2 * dz) - rhoStar(z) * g.gravity;
    const double exact_e =
        (heat(z + dz) - heat(z - dz)) / (2 * dz) - m.evaluate(rhoStar(z), thetaStar(z)).cooling;
    e.momentum = std::max(e.momentum, std::abs(R[3 * i + 1] - exact_m));
    e.energy = std::max(e.energy, std::abs(R[3 * i + 2] - exact_e));
    scale_m = std::max(scale_m, std::abs(exact_m) + rhoStar(z) * g.gravity);
    scale_e = std::max(scale_e, std::abs(exact_e));
  }
  e.momentum /= scale_m;
  e.energy /= scale_e;
  return e;
}
}  // namespace

TEST(HydroAccuracy, SemiDiscreteOperatorIsSecondOrderOnASmoothManufacturedState) {
  Errors prev = truncationError(50);
  for (int cells : {100, 200, 400}) {
    const Errors e = truncationError(cells);
    const double pm = std::log2(prev.momentum / e.momentum);
    const double pe = std::log2(prev.energy / e.energy);
    std::printf("cells %d momentum %.3e (order %.2f) energy %.3e (order %.2f)\n", cells, e.momentum,
                pm, e.energy, pe);
    EXPECT_GE(pm, 1.8) << cells << " cells: momentum error " << e.momentum;
    EXPECT_GE(pe, 1.8) << cells << " cells: energy error " << e.energy;
    prev = e;
  }
}
