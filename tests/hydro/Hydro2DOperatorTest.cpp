// The 2D operator's right-hand side and Jacobian: a layer uniform in x is the 1D operator in
// every column (the horizontal terms vanish exactly), the forward-mode Jacobian equals central
// finite differences on a layer whose columns differ in every variable (periodic and between
// side walls, smooth and rough), and the cell masses change only by fluxes that cancel.
#include <gtest/gtest.h>

#include <cmath>

#include "Hydro2DTestSupport.hpp"

using namespace granwave::hydro;
using test::kD;
using test::kMass;
using test::wetModel;

namespace {

// Column i of the 2D rates equals the column operator's rates; no flux, no horizontal flow.
void expectColumnIsTheColumnOperator(const GranularHydro2D& op, const GranularHydro1D& pde,
                                     const std::vector<double>& dU, const std::vector<double>& dV,
                                     int i, bool rough) {
  for (int j = 0; j <= 16; ++j) {
    EXPECT_NEAR(dU[op.heightIndex(i, j)], dV[pde.heightIndex(j)], 1e-12);
    const double a = dV[pde.velocityIndex(j)];
    EXPECT_NEAR(dU[op.velocityIndex(i, j)], a, 1e-11 * (1 + std::abs(a))) << j;
    if (j == 16) break;
    const double s = dV[pde.temperatureIndex(j)];
    EXPECT_NEAR(dU[op.temperatureIndex(i, j)], s, 1e-11 * (1 + std::abs(s))) << j;
    if (rough) {
      EXPECT_NEAR(dU[op.rotationIndex(i, j)], dV[pde.rotationIndex(j)], 1e-9);
    }
    EXPECT_EQ(dU[op.fluxIndex(i, j)], 0.0);
    EXPECT_EQ(dU[op.horizontalVelocityIndex(i, j)], 0.0);
  }
}

}  // namespace

TEST(Hydro2DOperator, FlatLayerIsTheColumnOperatorInEveryColumn) {
  for (bool rough : {false, true}) {
    const ConstitutiveModel m = wetModel(rough);
    const HydroGeometry g = test::drivenBox(16);
    const double M = 300 * kMass / (30 * kD);
    const GranularHydro1D pde(g, m, M);
    const GranularHydro2D op(g, {4, 8 * kD, true}, m, std::vector<double>(4 * 16, M / 16));
    const std::vector<double> V = test::rumpledColumn(pde, 3);
    std::vector<double> U(op.size(), 0.0);
    for (int i = 0; i < 4; ++i) test::putColumn(op, pde, V, i, U);
    std::vector<double> dV(pde.size()), dU(op.size());
    const double t = 0.013;
    ASSERT_EQ(pde.rightHandSide(t, V.data(), dV.data()), 0);
    ASSERT_EQ(op.rightHandSide(t, U.data(), dU.data()), 0);
    for (int i = 0; i < 4; ++i) expectColumnIsTheColumnOperator(op, pde, dU, dV, i, rough);
  }
}

namespace {

// The full Jacobian J, its in-column part B, each row's largest |J|, and the rates at U +- h e_c.
struct JacobianProbe {
  const std::vector<double>& J;
  const std::vector<double>& B;
  const std::vector<double>& row_max;
  const std::vector<double>& fp;
  const std::vector<double>& fm;
};

// Column c of J against central differences; B is J within the column, zero outside it.
void expectJacobianColumn(const GranularHydro2D& op, const JacobianProbe& p, double h, int c) {
  const int n = op.size();
  for (int r = 0; r < n; ++r) {
    const double fd = (p.fp[r] - p.fm[r]) / (2 * h);
    ASSERT_NEAR(p.J[r * n + c], fd, 1e-5 * p.row_max[r] + 1e-12)
        << op.componentName(r) << " by " << op.componentName(c);
    const bool same_column = r / op.columnSize() == c / op.columnSize();
    ASSERT_EQ(p.B[r * n + c], same_column ? p.J[r * n + c] : 0.0);
    if (same_column && p.J[r * n + c] != 0) {
      ASSERT_LE(std::abs(r - c), op.halfBand()) << "outside the column band";
    }
  }
}

void expectJacobianMatchesFiniteDifferences(bool periodic, bool rough, int columns) {
  const ConstitutiveModel m = wetModel(rough);
  const HydroGeometry g = test::drivenBox(8);
  const double M = 300 * kMass / (30 * kD);
  const GranularHydro1D pde(g, m, M);
  const GranularHydro2D op(g, {columns, 2.0 * columns * kD, periodic}, m,
                           std::vector<double>(columns * 8, M / 8));
  const std::vector<double> U = test::rumpledLayer(op, pde, 11);
  const int n = op.size();
  const double t = 0.013;
  std::vector<double> J(static_cast<std::size_t>(n) * n, 0.0), B(J.size(), 0.0);
  ASSERT_EQ(op.jacobian(
                t, U.data(), [&](int r, int c, double v) { J[r * n + c] += v; }, false),
            0);
  ASSERT_EQ(op.jacobian(
                t, U.data(), [&](int r, int c, double v) { B[r * n + c] += v; }, true),
            0);
  std::vector<double> row_max(n, 0.0);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) row_max[r] = std::max(row_max[r], std::abs(J[r * n + c]));
  std::vector<double> fp(n), fm(n);
  for (int c = 0; c < n; ++c) {
    const double h = 1e-6 * std::abs(U[c]) + 1e-12;
    std::vector<double> Up = U, Um = U;
    Up[c] += h;
    Um[c] -= h;
    ASSERT_EQ(op.rightHandSide(t, Up.data(), fp.data()), 0);
    ASSERT_EQ(op.rightHandSide(t, Um.data(), fm.data()), 0);
    expectJacobianColumn(op, {J, B, row_max, fp, fm}, h, c);
  }
}

}  // namespace

TEST(Hydro2DOperator, PeriodicJacobianEqualsFiniteDifferences) {
  expectJacobianMatchesFiniteDifferences(true, false, 9);
}

TEST(Hydro2DOperator, SideWallJacobianEqualsFiniteDifferences) {
  expectJacobianMatchesFiniteDifferences(false, false, 8);
}

TEST(Hydro2DOperator, RoughJacobianOfFewColumnsEqualsFiniteDifferences) {
  expectJacobianMatchesFiniteDifferences(true, true, 3);
}

namespace {

// The sum over the 6 columns of layer k of what flows in minus what flows out (and in `scale`
// the sum of the magnitudes): zero when mass only moves between neighbours.
double fluxBalance(const GranularHydro2D& op, const std::vector<double>& dU, int k, bool periodic,
                   double& scale) {
  double total = 0;
  for (int i = 0; i < 6; ++i) {
    const double left =
        i > 0 ? dU[op.fluxIndex(i - 1, k)] : (periodic ? dU[op.fluxIndex(5, k)] : 0.0);
    const double right = op.wallFace(i) ? 0.0 : dU[op.fluxIndex(i, k)];
    total += left - right;
    scale += std::abs(left) + std::abs(right);
  }
  return total;
}

}  // namespace

TEST(Hydro2DOperator, CellMassesChangeOnlyByFluxesBetweenNeighbours) {
  const ConstitutiveModel m = wetModel(false);
  const HydroGeometry g = test::drivenBox(8);
  const double M = 300 * kMass / (30 * kD);
  const GranularHydro1D pde(g, m, M);
  for (bool periodic : {true, false}) {
    const GranularHydro2D op(g, {6, 12 * kD, periodic}, m, std::vector<double>(6 * 8, M / 8));
    const std::vector<double> U = test::rumpledLayer(op, pde, 5);
    std::vector<double> dU(op.size());
    ASSERT_EQ(op.rightHandSide(0.01, U.data(), dU.data()), 0);
    for (int k = 0; k < 8; ++k) {
      double scale = 0;
      const double total = fluxBalance(op, dU, k, periodic, scale);
      EXPECT_NEAR(total, 0.0, 1e-14 * scale) << "layer " << k;
    }
    for (int k = 0; k < 8 && !periodic; ++k) EXPECT_EQ(dU[op.fluxIndex(5, k)], 0.0);
  }
}
