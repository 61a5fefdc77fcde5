// The vertical remap of the 2D layers (hydro/Layer2DRemap.hpp): it keeps every column's and
// every layer's mass and the lab-frame energy exactly, leaves a layer already at its shares as
// it is, and measures how thin the thinnest cell is.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "Hydro2DTestSupport.hpp"
#include "hydro/Layer2DRemap.hpp"

using namespace granwave::hydro;
using test::kD;
using test::kMass;
using test::wetModel;

namespace {

struct Masses {
  std::vector<double> column, layer;
};

Masses massesOf(const GranularHydro2D& op, const std::vector<double>& U) {
  Masses m{std::vector<double>(op.columns(), 0.0), std::vector<double>(op.cells(), 0.0)};
  for (int i = 0; i < op.columns(); ++i)
    for (int k = 0; k < op.cells(); ++k) {
      m.column[i] += op.cellMass(U.data(), i, k);
      m.layer[k] += op.cellMass(U.data(), i, k);
    }
  return m;
}

}  // namespace

namespace {

void expectRemapKeepsMassesAndEnergy(bool rough, bool periodic) {
  const ConstitutiveModel m = wetModel(rough);
  const HydroGeometry g = test::drivenBox(8);
  const double M = 300 * kMass / (30 * kD);
  const GranularHydro1D pde(g, m, M);
  const GranularHydro2D op(g, {6, 12 * kD, periodic}, m, std::vector<double>(6 * 8, M / 8));
  std::vector<double> U = test::rumpledLayer(op, pde, 7);
  const Masses before = massesOf(op, U);
  const double t = 0.013, E = op.labEnergy(t, U.data());
  ASSERT_LT(thinnestLayerShare(op, U.data()), 0.95);
  const std::vector<double> old = U;
  remapLayers(op, t, U);
  const Masses after = massesOf(op, U);
  const double total = std::accumulate(before.column.begin(), before.column.end(), 0.0);
  for (int i = 0; i < op.columns(); ++i) {
    EXPECT_NEAR(after.column[i], before.column[i], 1e-13 * total) << i;
    EXPECT_EQ(U[op.heightIndex(i, 0)], old[op.heightIndex(i, 0)]);
    EXPECT_EQ(U[op.heightIndex(i, op.cells())], old[op.heightIndex(i, op.cells())]);
    for (int k = 0; k < op.cells(); ++k)  // at its share of its column and layer
      EXPECT_NEAR(op.cellMass(U.data(), i, k), before.column[i] * before.layer[k] / total,
                  1e-12 * total);
  }
  for (int k = 0; k < op.cells(); ++k)
    EXPECT_NEAR(after.layer[k], before.layer[k], 1e-13 * total) << k;
  EXPECT_NEAR(thinnestLayerShare(op, U.data()), 1.0, 1e-9);
  EXPECT_NEAR(op.labEnergy(t, U.data()), E, 1e-12 * std::abs(E));
}

}  // namespace

TEST(Hydro2DRemap, KeepsEveryColumnsAndLayersMassAndTheLabEnergy) {
  for (bool rough : {false, true})
    for (bool periodic : {true, false}) {
      SCOPED_TRACE(std::string(rough ? "rough" : "smooth") + (periodic ? ", periodic" : ", walls"));
      expectRemapKeepsMassesAndEnergy(rough, periodic);
    }
}

TEST(Hydro2DRemap, LeavesALayerAtItsSharesAsItIs) {
  const ConstitutiveModel m = wetModel(false);
  const HydroGeometry g = test::drivenBox(8);
  const double M = 300 * kMass / (30 * kD);
  const GranularHydro1D pde(g, m, M);
  const GranularHydro2D op(g, {6, 12 * kD, true}, m, std::vector<double>(6 * 8, M / 8));
  std::vector<double> U = test::rumpledLayer(op, pde, 3);
  for (int i = 0; i < op.columns(); ++i)
    for (int k = 0; k < op.cells(); ++k) U[op.fluxIndex(i, k)] = 0.0;  // mu = mu0, equal shares
  const std::vector<double> old = U;
  EXPECT_NEAR(thinnestLayerShare(op, U.data()), 1.0, 1e-12);
  const double heat = remapLayers(op, 0.013, U);
  EXPECT_NEAR(heat, 0.0, 1e-12 * std::abs(op.labEnergy(0.013, old.data())));
  for (int c = 0; c < op.layerSize(); ++c)
    EXPECT_NEAR(U[c], old[c], 1e-12 * (1 + std::abs(old[c]))) << op.componentName(c);
}

TEST(Hydro2DRemap, ThinnestShareIsTheEmptiedCellsFractionOfItsShare) {
  const ConstitutiveModel m = wetModel(false);
  const HydroGeometry g = test::drivenBox(8);
  const double M = 300 * kMass / (30 * kD);
  const GranularHydro2D op(g, {4, 8 * kD, true}, m, std::vector<double>(4 * 8, M / 8));
  std::vector<double> U(op.size(), 0.0);
  // 0.9 of cell (1, 5)'s mass leaves through its right face into cell (2, 5): the cell keeps
  // mu = 0.1 M/8, its column M - 0.9 M/8, its layer all its 4 M/8; the whole layer is 4 M.
  U[op.fluxIndex(1, 5)] = 0.9 * (M / 8) * op.dx();
  const double mu = 0.1 * M / 8, column = 8 * M / 8 - 0.9 * M / 8, layer = 4 * M / 8;
  const double total = 4 * M;
  EXPECT_NEAR(thinnestLayerShare(op, U.data()), mu * total / (column * layer), 1e-12);
}

TEST(Hydro2DRemap, RefusesAColumnThatHasLostAllItsMass) {
  const ConstitutiveModel m = wetModel(false);
  const HydroGeometry g = test::drivenBox(8);
  const double M = 300 * kMass / (30 * kD);
  const GranularHydro2D op(g, {4, 8 * kD, true}, m, std::vector<double>(4 * 8, M / 8));
  std::vector<double> U(op.size(), 0.0);
  for (int k = 0; k < op.cells(); ++k) U[op.fluxIndex(1, k)] = (M / 8) * op.dx();  // all leaves
  EXPECT_THROW(remapLayers(op, 0.0, U), std::runtime_error);
}
