// Heat conduction between the 2D operator's sloped columns (hydro/Layer2DTransport.hpp): the
// slopes' corrections to the two-point fluxes are built from other cells' temperatures, and
// must not drive heat out of a cell far colder than the cells it touches (a cold, packed
// column beside one that lands: docs/hydro.md, "Conduction on sloped layers").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "Hydro2DTestSupport.hpp"

using namespace granwave::hydro;
using test::kD;
using test::kMass;

namespace {

// A layer at rest (w = u = 0: no compression, no shear, no advection) whose columns differ in
// height and temperature profile: conduction is then the only power into a cold cell that does
// not vanish with its temperature (the collisional and wall losses go as theta^(3/2)).
std::vector<double> slopedLayerAtRest(const GranularHydro2D& op, const GranularHydro1D& pde,
                                      unsigned seed) {
  std::vector<double> U = test::rumpledLayer(op, pde, seed);
  for (int i = 0; i < op.columns(); ++i) {
    for (int j = 0; j <= op.cells(); ++j) U[op.velocityIndex(i, j)] = 0.0;
    for (int k = 0; k < op.cells(); ++k) U[op.horizontalVelocityIndex(i, k)] = 0.0;
  }
  return U;
}

}  // namespace

// Every cell in turn made 1e-9 times colder than the coldest other cell: its temperature rises.
// A conduction flux that lets the slope's correction outweigh the two-point difference fails
// this for some cells: without the correction's weight 3 of the 48 cells of each seed lose
// heat, ln theta falling at 5e11 to 2.5e13 per second (the rate grows as 1/theta).
TEST(Hydro2DConduction, CellFarColderThanEveryNeighbourWarmsOnSlopedLayers) {
  const ConstitutiveModel m = test::wetModel(false);
  const HydroGeometry g = test::drivenBox(8);
  const double M = 300 * kMass / (30 * kD);
  const GranularHydro1D pde(g, m, M);
  const GranularHydro2D op(g, {6, 12 * kD, true}, m, std::vector<double>(6 * 8, M / 8));
  for (unsigned seed : {5u, 11u}) {
    const std::vector<double> U = slopedLayerAtRest(op, pde, seed);
    double coldest = INFINITY;
    for (int c = 0; c < op.columns() * op.cells(); ++c)
      coldest = std::min(coldest, U[op.temperatureIndex(c / op.cells(), c % op.cells())]);
    for (int c = 0; c < op.columns() * op.cells(); ++c) {
      const int i = c / op.cells(), k = c % op.cells();
      std::vector<double> V = U, dV(op.size());
      V[op.temperatureIndex(i, k)] = coldest + std::log(1e-9);  // s = ln(theta / unit)
      ASSERT_EQ(op.rightHandSide(0.01, V.data(), dV.data()), 0);
      EXPECT_GE(dV[op.temperatureIndex(i, k)], 0.0)
          << "seed " << seed << ", cell (" << i << ", " << k << ")";
    }
  }
}
