// The compiled SUNDIALS kernels (hydro/SundialsKernels.hpp) against SUNDIALS's own: every
// vector operation CVODE calls, on random vectors with zeros and both signs, gives exactly
// SUNDIALS's result (same arithmetic in the same order), including the constraint mask and
// minimum quotient on every kind of constraint; the band matrix's operations agree on the band
// and a clone keeps the compiled operations; the band LU solver solves as SUNLinSol_Band does.
#include <gtest/gtest.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_band.h>
#include <sunmatrix/sunmatrix_band.h>

#include <cmath>
#include <random>
#include <vector>

#include "hydro/SundialsKernels.hpp"

using granwave::hydro::bandLuSolver;
using granwave::hydro::useCompiledKernels;

namespace {

constexpr int kN = 302;

class SundialsKernels : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_EQ(SUNContext_Create(nullptr, &ctx_), 0); }
  void TearDown() override {
    for (N_Vector v : vectors_) N_VDestroy(v);
    SUNContext_Free(&ctx_);
  }
  // A pair of equal random vectors: SUNDIALS's kernels and the compiled ones.
  struct Pair {
    N_Vector own, compiled;
  };
  Pair pair(unsigned seed, bool with_zeros = true) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> U(-2, 2);
    Pair p{N_VNew_Serial(kN, ctx_), N_VNew_Serial(kN, ctx_)};
    vectors_.push_back(p.own);
    vectors_.push_back(p.compiled);
    useCompiledKernels(p.compiled);
    for (int i = 0; i < kN; ++i) {
      double v = U(rng);
      if (with_zeros && i % 17 == 3) v = 0.0;
      NV_Ith_S(p.own, i) = NV_Ith_S(p.compiled, i) = v;
    }
    return p;
  }
  // Constraint codes CVODE accepts and ones it ignores (|c| <= 0.5).
  Pair constraints() {
    Pair p = pair(99);
    const double codes[] = {0.0, 1.0, -1.0, 2.0, -2.0, 0.3, -0.4};
    for (int i = 0; i < kN; ++i) NV_Ith_S(p.own, i) = NV_Ith_S(p.compiled, i) = codes[i % 7];
    return p;
  }
  static void expectSame(N_Vector a, N_Vector b) {
    for (int i = 0; i < kN; ++i) {
      const double x = NV_Ith_S(a, i), y = NV_Ith_S(b, i);
      if (std::isnan(x))
        EXPECT_TRUE(std::isnan(y)) << i;
      else
        EXPECT_EQ(x, y) << i;
    }
  }
  SUNContext ctx_ = nullptr;
  std::vector<N_Vector> vectors_;
};

}  // namespace

TEST_F(SundialsKernels, ElementwiseOperationsAreSundialsToTheBit) {
  Pair x = pair(1), y = pair(2), z = pair(3);
  const double coefficients[][2] = {{1, 1},   {1, -1},  {-1, 1},   {0.3, 0.3}, {0.3, -0.3},
                                    {1, 0.7}, {0.7, 1}, {-1, 0.7}, {0.7, -1},  {0.2, 0.9}};
  for (const auto& c : coefficients) {
    N_VLinearSum(c[0], x.own, c[1], y.own, z.own);
    N_VLinearSum(c[0], x.compiled, c[1], y.compiled, z.compiled);
    expectSame(z.own, z.compiled);
    N_VLinearSum(c[0], x.own, c[1], z.own, z.own);  // z = a x + b z, in place
    N_VLinearSum(c[0], x.compiled, c[1], z.compiled, z.compiled);
    expectSame(z.own, z.compiled);
  }
  Pair w = pair(4, false);
  N_VConst(0.25, z.own), N_VConst(0.25, z.compiled), expectSame(z.own, z.compiled);
  N_VProd(x.own, y.own, z.own), N_VProd(x.compiled, y.compiled, z.compiled);
  expectSame(z.own, z.compiled);
  N_VDiv(x.own, w.own, z.own), N_VDiv(x.compiled, w.compiled, z.compiled);
  expectSame(z.own, z.compiled);
  for (double c : {1.0, -1.0, 0.37}) {
    N_VScale(c, x.own, z.own), N_VScale(c, x.compiled, z.compiled);
    expectSame(z.own, z.compiled);
  }
  N_VAbs(x.own, z.own), N_VAbs(x.compiled, z.compiled), expectSame(z.own, z.compiled);
  N_VInv(w.own, z.own), N_VInv(w.compiled, z.compiled), expectSame(z.own, z.compiled);
  N_VAddConst(x.own, 0.5, z.own), N_VAddConst(x.compiled, 0.5, z.compiled);
  expectSame(z.own, z.compiled);
  N_VCompare(0.8, x.own, z.own), N_VCompare(0.8, x.compiled, z.compiled);
  expectSame(z.own, z.compiled);
  EXPECT_EQ(N_VInvTest(x.own, z.own), N_VInvTest(x.compiled, z.compiled));
  expectSame(z.own, z.compiled);
  EXPECT_EQ(N_VInvTest(w.own, z.own), N_VInvTest(w.compiled, z.compiled));
  expectSame(z.own, z.compiled);
}

TEST_F(SundialsKernels, ReductionsAreSundialsToTheBit) {
  Pair x = pair(5), y = pair(6), w = pair(7, false), mask = pair(8);
  EXPECT_EQ(N_VDotProd(x.own, y.own), N_VDotProd(x.compiled, y.compiled));
  EXPECT_EQ(N_VMaxNorm(x.own), N_VMaxNorm(x.compiled));
  EXPECT_EQ(N_VWrmsNorm(x.own, w.own), N_VWrmsNorm(x.compiled, w.compiled));
  EXPECT_EQ(N_VWrmsNormMask(x.own, w.own, mask.own),
            N_VWrmsNormMask(x.compiled, w.compiled, mask.compiled));
  EXPECT_EQ(N_VMin(x.own), N_VMin(x.compiled));
  EXPECT_EQ(N_VWL2Norm(x.own, w.own), N_VWL2Norm(x.compiled, w.compiled));
  EXPECT_EQ(N_VL1Norm(x.own), N_VL1Norm(x.compiled));
  EXPECT_EQ(N_VWSqrSumLocal(x.own, w.own), N_VWSqrSumLocal(x.compiled, w.compiled));
  EXPECT_EQ(N_VWSqrSumMaskLocal(x.own, w.own, mask.own),
            N_VWSqrSumMaskLocal(x.compiled, w.compiled, mask.compiled));
  EXPECT_EQ(N_VMinQuotient(x.own, y.own), N_VMinQuotient(x.compiled, y.compiled));
  Pair zeros = pair(9);
  N_VConst(0.0, zeros.own), N_VConst(0.0, zeros.compiled);  // no denominator at all
  EXPECT_EQ(N_VMinQuotient(x.own, zeros.own), N_VMinQuotient(x.compiled, zeros.compiled));
}

TEST_F(SundialsKernels, ConstraintMaskFollowsEveryConstraintCode) {
  Pair c = constraints(), m = pair(10);
  for (unsigned seed : {11u, 12u}) {
    Pair x = pair(seed);  // zeros and both signs against >, >=, <, <= 0 and no constraint
    const booleantype own = N_VConstrMask(c.own, x.own, m.own);
    EXPECT_EQ(own, N_VConstrMask(c.compiled, x.compiled, m.compiled));
    expectSame(m.own, m.compiled);
    EXPECT_EQ(own, SUNFALSE);
  }
  Pair positive = pair(13, false);
  for (int i = 0; i < kN; ++i) {
    const double ci = NV_Ith_S(c.own, i);
    const double v = std::abs(NV_Ith_S(positive.own, i)) * (ci < 0 ? -1.0 : 1.0);
    NV_Ith_S(positive.own, i) = NV_Ith_S(positive.compiled, i) = v;
  }
  EXPECT_EQ(N_VConstrMask(c.compiled, positive.compiled, m.compiled), SUNTRUE);
  EXPECT_EQ(N_VConstrMask(c.own, positive.own, m.own), SUNTRUE);
  expectSame(m.own, m.compiled);
}

TEST_F(SundialsKernels, FusedOperationsEqualTheirUnfusedDefinition) {
  Pair a = pair(14), b = pair(15), c = pair(16), z = pair(17);
  double coefficients[] = {1.0, -0.3, 0.7};
  N_Vector own[] = {a.own, b.own, c.own}, compiled[] = {a.compiled, b.compiled, c.compiled};
  N_VLinearCombination(3, coefficients, own, z.own);  // SUNDIALS: scale, then linear sums
  N_VLinearCombination(3, coefficients, compiled, z.compiled);
  expectSame(z.own, z.compiled);
  own[0] = z.own, compiled[0] = z.compiled;  // z = 1 z + ... in place
  N_VLinearCombination(3, coefficients, own, z.own);
  N_VLinearCombination(3, coefficients, compiled, z.compiled);
  expectSame(z.own, z.compiled);
  Pair y1 = pair(18), y2 = pair(19), z1 = pair(20), z2 = pair(21);
  double scales[] = {0.4, 1.0};
  N_Vector Yo[] = {y1.own, y2.own}, Zo[] = {z1.own, z2.own};
  N_Vector Yc[] = {y1.compiled, y2.compiled}, Zc[] = {z1.compiled, z2.compiled};
  N_VScaleAddMulti(2, scales, a.own, Yo, Zo);
  N_VScaleAddMulti(2, scales, a.compiled, Yc, Zc);
  expectSame(z1.own, z1.compiled);
  expectSame(z2.own, z2.compiled);
  double dots_own[2], dots_compiled[2];
  N_VDotProdMulti(2, a.own, Yo, dots_own);
  N_VDotProdMulti(2, a.compiled, Yc, dots_compiled);
  EXPECT_EQ(dots_own[0], dots_compiled[0]);
  EXPECT_EQ(dots_own[1], dots_compiled[1]);
}

TEST_F(SundialsKernels, ClonesOfAVectorKeepTheCompiledKernels) {
  Pair x = pair(22);
  N_Vector clone = N_VClone(x.compiled);
  vectors_.push_back(clone);
  EXPECT_EQ(clone->ops->nvlinearsum, x.compiled->ops->nvlinearsum);
  EXPECT_NE(clone->ops->nvlinearsum, x.own->ops->nvlinearsum);
}

namespace {

// A random band matrix, diagonally weak enough that the LU pivots.
SUNMatrix randomBandMatrix(int n, int band, unsigned seed, SUNContext ctx) {
  SUNMatrix A = SUNBandMatrix(n, band, band, ctx);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int j = 0; j < n; ++j)
    for (int i = std::max(0, j - band); i <= std::min(n - 1, j + band); ++i)
      SM_ELEMENT_B(A, i, j) = i == j ? 0.1 * U(rng) : U(rng);
  return A;
}

void expectSameBand(SUNMatrix A, SUNMatrix B, int band) {
  const int n = static_cast<int>(SM_COLUMNS_B(A));
  for (int j = 0; j < n; ++j)
    for (int i = std::max(0, j - band); i <= std::min(n - 1, j + band); ++i)
      EXPECT_EQ(SM_ELEMENT_B(A, i, j), SM_ELEMENT_B(B, i, j)) << i << ", " << j;
}

}  // namespace

TEST_F(SundialsKernels, BandMatrixOperationsAgreeOnTheBandAndSurviveCloning) {
  const int band = 8;
  SUNMatrix own = randomBandMatrix(kN, band, 23, ctx_);
  SUNMatrix compiled = randomBandMatrix(kN, band, 23, ctx_);
  useCompiledKernels(compiled);
  SUNMatrix own_copy = SUNMatClone(own), compiled_copy = SUNMatClone(compiled);
  EXPECT_EQ(compiled_copy->ops->scaleaddi, compiled->ops->scaleaddi);  // CVODE's saved Jacobian
  EXPECT_EQ(compiled_copy->ops->clone, compiled->ops->clone);
  EXPECT_EQ(SUNMatCopy(own, own_copy), 0);
  EXPECT_EQ(SUNMatCopy(compiled, compiled_copy), 0);
  expectSameBand(own_copy, compiled_copy, band);
  EXPECT_EQ(SUNMatScaleAddI(-0.37, own), 0);
  EXPECT_EQ(SUNMatScaleAddI(-0.37, compiled), 0);
  expectSameBand(own, compiled, band);
  EXPECT_EQ(SUNMatZero(compiled), 0);
  for (sunindextype k = 0; k < SM_LDATA_B(compiled); ++k) EXPECT_EQ(SM_DATA_B(compiled)[k], 0.0);
  for (SUNMatrix M : {own, compiled, own_copy, compiled_copy}) SUNMatDestroy(M);
}

TEST_F(SundialsKernels, BandLuSolverSolvesAsSundialsBandSolver) {
  const int band = 8;
  SUNMatrix A = randomBandMatrix(kN, band, 24, ctx_), B = randomBandMatrix(kN, band, 24, ctx_);
  Pair rhs = pair(25), x = pair(26);
  SUNLinearSolver own = SUNLinSol_Band(rhs.own, A, ctx_);
  SUNLinearSolver compiled = bandLuSolver(B, ctx_);
  ASSERT_NE(compiled, nullptr);
  EXPECT_EQ(SUNLinSolGetType(compiled), SUNLINEARSOLVER_DIRECT);
  ASSERT_EQ(SUNLinSolInitialize(own), 0);
  ASSERT_EQ(SUNLinSolInitialize(compiled), 0);
  ASSERT_EQ(SUNLinSolSetup(own, A), 0);
  ASSERT_EQ(SUNLinSolSetup(compiled, B), 0);
  ASSERT_EQ(SUNLinSolSolve(own, A, x.own, rhs.own, 0.0), 0);
  ASSERT_EQ(SUNLinSolSolve(compiled, B, x.compiled, rhs.compiled, 0.0), 0);
  double largest = 0;
  for (int i = 0; i < kN; ++i) largest = std::max(largest, std::abs(NV_Ith_S(x.own, i)));
  for (int i = 0; i < kN; ++i)
    EXPECT_NEAR(NV_Ith_S(x.compiled, i), NV_Ith_S(x.own, i), 1e-12 * largest) << i;
  // A singular matrix is a recoverable failure (CVODE retries with a smaller step).
  SUNMatZero(B);
  EXPECT_EQ(SUNLinSolSetup(compiled, B), SUNLS_LUFACT_FAIL);
  EXPECT_GT(SUNLinSolLastFlag(compiled), 0);
  SUNLinSolFree(own);
  SUNLinSolFree(compiled);
  SUNMatDestroy(A);
  SUNMatDestroy(B);
}
