// Observed order of spatial accuracy of the Lagrangian operator on a manufactured state: a
// smooth resting column under gravity, density falling exponentially and temperature rising
// linearly with height, is placed on N cells of equal mass (nodes where the cumulative mass
// is j M/N) and fed to the operator. Its exact values are
//   node:  du/dt = -(1/rho) dp/dz - g,
//   cell:  d(theta)/dt = (1/rho) d/dz(kappa_theta dtheta/dz) - D_c/rho,
// at the node's height and the cell's mass centre, with the closures' derivatives by central
// differences at 1e-5 of the height. The truncation error (max over the interior, 6 cells
// from each end left out: the free top and the contact at the plate are first order) must
// fall at second order. Measured between 100, 200 and 400 cells: momentum 1.76 and 1.88 (the
// coarse grid is pre-asymptotic), energy 1.90 and 1.88; asserted >= 1.7.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "HydroTestSupport.hpp"

using namespace granwave::hydro;
using test::kD;

namespace {
constexpr double kL = 0.06, kH = 0.8 * kL;
const double kRho0 = test::densityOf(0.4);

double rhoStar(double z) { return kRho0 * std::exp(-z / kH); }
double thetaStar(double z) { return 0.05 * (1 + z / kL); }
double massBelow(double z) { return kRho0 * kH * (1 - std::exp(-z / kH)); }
double heightOfMass(double M) { return -kH * std::log(1 - M / (kRho0 * kH)); }

struct Errors {
  double momentum, energy;
};

Errors truncationError(int cells) {
  const ConstitutiveModel m =
      test::beadModel(RestitutionClosure::dry(0.1), RestitutionClosure::dry(0.1));
  HydroGeometry g;
  g.cells = cells;
  g.height = 2 * kL;
  const double M = massBelow(kL);
  const GranularHydro1D pde(g, m, M);
  std::vector<double> U(pde.size(), 0.0), R(pde.size());
  for (int j = 0; j <= cells; ++j) {
    U[pde.heightIndex(j)] = heightOfMass(M * j / cells);
    if (j < cells)
      U[pde.temperatureIndex(j)] =
          pde.temperatureUnknown(thetaStar(heightOfMass(M * (j + 0.5) / cells)));
  }
  EXPECT_EQ(pde.rightHandSide(0.0, U.data(), R.data()), 0);
  const double dz = 1e-5 * kL;
  auto p = [&](double z) { return m.pressure(rhoStar(z), thetaStar(z)); };
  auto heat = [&](double z) {  // kappa_theta theta'
    return m.evaluate(rhoStar(z), thetaStar(z)).kappa_theta * 0.05 / kL;
  };
  Errors e{0, 0};
  double scale_m = 0, scale_e = 0;
  for (int i = 6; i + 6 < cells; ++i) {
    const double zn = U[pde.heightIndex(i)];
    const double exact_m = -(p(zn + dz) - p(zn - dz)) / (2 * dz) / rhoStar(zn) - g.gravity;
    const double zc = heightOfMass(M * (i + 0.5) / cells);
    const double exact_e = ((heat(zc + dz) - heat(zc - dz)) / (2 * dz) -
                            m.evaluate(rhoStar(zc), thetaStar(zc)).cooling) /
                           rhoStar(zc);
    e.momentum = std::max(e.momentum, std::abs(R[pde.velocityIndex(i)] - exact_m));
    e.energy = std::max(e.energy, std::abs(pde.temperatureRate(U.data(), R.data(), i) - exact_e));
    scale_m = std::max(scale_m, std::abs(exact_m) + g.gravity);
    scale_e = std::max(scale_e, std::abs(exact_e));
  }
  e.momentum /= scale_m;
  e.energy /= scale_e;
  return e;
}
}  // namespace

TEST(HydroAccuracy, SemiDiscreteOperatorIsSecondOrderOnASmoothManufacturedState) {
  Errors prev = truncationError(100);
  for (int cells : {200, 400}) {
    const Errors e = truncationError(cells);
    const double pm = std::log2(prev.momentum / e.momentum);
    const double pe = std::log2(prev.energy / e.energy);
    std::printf("cells %d momentum %.3e (order %.2f) energy %.3e (order %.2f)\n", cells, e.momentum,
                pm, e.energy, pe);
    EXPECT_GE(pm, 1.7) << cells << " cells: momentum error " << e.momentum;
    EXPECT_GE(pe, 1.7) << cells << " cells: energy error " << e.energy;
    prev = e;
  }
}
