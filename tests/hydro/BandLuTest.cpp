// The band LU (hydro/BandLu.hpp) against a dense LU with partial pivoting (Eigen) on random
// band matrices: the continuum's layouts (kl = ku = 8 and 11, compiled with fixed loops) and
// others, including matrices that need row interchanges, and the zero-pivot report.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <vector>

#include "hydro/BandLu.hpp"

using granwave::hydro::bandLuFactor;
using granwave::hydro::bandLuSolve;

namespace {

struct Band {
  int n, kl, ku, ldab;
  std::vector<double> ab;
  Band(int n_, int kl_, int ku_) : n(n_), kl(kl_), ku(ku_), ldab(2 * kl_ + ku_ + 1) {
    ab.assign(static_cast<std::size_t>(n) * ldab, std::nan(""));  // fill-in rows: garbage
  }
  double& operator()(int i, int j) {
    return ab[static_cast<std::size_t>(j) * ldab + kl + ku + i - j];
  }
};

// A random band matrix with entries of both signs; `weak_diagonal` makes pivoting necessary.
Band randomBand(int n, int kl, int ku, bool weak_diagonal, std::mt19937& rng,
                Eigen::MatrixXd& dense) {
  std::uniform_real_distribution<double> U(-1, 1);
  Band b(n, kl, ku);
  dense = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = std::max(0, j - ku); i <= std::min(n - 1, j + kl); ++i) {
      double v = U(rng);
      if (i == j) v = weak_diagonal ? 0.1 * v : v + (v > 0 ? 1.0 : -1.0) * (kl + ku);
      b(i, j) = v;
      dense(i, j) = v;
    }
  return b;
}

void expectSolvesLikeDenseLu(int n, int kl, int ku, bool weak_diagonal, unsigned seed) {
  std::mt19937 rng(seed);
  Eigen::MatrixXd dense;
  Band band = randomBand(n, kl, ku, weak_diagonal, rng, dense);
  Eigen::VectorXd rhs = Eigen::VectorXd::Random(n);
  std::vector<int> pivots(n);
  ASSERT_EQ(bandLuFactor(band.ab.data(), band.ldab, n, kl, ku, pivots.data()), 0)
      << "n " << n << " kl " << kl << " ku " << ku;
  std::vector<double> x(rhs.data(), rhs.data() + n);
  bandLuSolve(band.ab.data(), band.ldab, n, kl, ku, pivots.data(), x.data());
  const Eigen::VectorXd expected = dense.partialPivLu().solve(rhs);
  const double scale = expected.cwiseAbs().maxCoeff();
  for (int i = 0; i < n; ++i)
    EXPECT_NEAR(x[i], expected[i], 1e-10 * scale)
        << "n " << n << " kl " << kl << " ku " << ku << " row " << i;
  // The factors are reusable: a second right-hand side with the same factorisation.
  const Eigen::VectorXd rhs2 = Eigen::VectorXd::Random(n);
  std::vector<double> x2(rhs2.data(), rhs2.data() + n);
  bandLuSolve(band.ab.data(), band.ldab, n, kl, ku, pivots.data(), x2.data());
  const Eigen::VectorXd residual = dense * Eigen::Map<Eigen::VectorXd>(x2.data(), n) - rhs2;
  EXPECT_LT(residual.cwiseAbs().maxCoeff(), 1e-10 * (1 + dense.cwiseAbs().maxCoeff() * x2.size()));
}

}  // namespace

TEST(BandLu, SolvesTheContinuumsLayoutsLikeADenseLu) {
  expectSolvesLikeDenseLu(302, 8, 8, false, 1);
  expectSolvesLikeDenseLu(402, 11, 11, false, 2);
}

TEST(BandLu, PivotsWhereTheDiagonalIsWeak) {
  expectSolvesLikeDenseLu(302, 8, 8, true, 3);
  expectSolvesLikeDenseLu(402, 11, 11, true, 4);
  expectSolvesLikeDenseLu(50, 3, 2, true, 5);
}

TEST(BandLu, HandlesAnyBandwidthAndSmallMatrices) {
  expectSolvesLikeDenseLu(30, 0, 2, false, 6);
  expectSolvesLikeDenseLu(30, 2, 0, false, 7);  // weak, it would be numerically singular
  expectSolvesLikeDenseLu(5, 8, 8, true, 8);    // band wider than the matrix
  expectSolvesLikeDenseLu(1, 0, 0, false, 9);
}

TEST(BandLu, ReportsTheFirstZeroPivot) {
  Band b(6, 1, 1);
  for (int j = 0; j < 6; ++j)
    for (int i = std::max(0, j - 1); i <= std::min(5, j + 1); ++i) b(i, j) = i == j ? 2.0 : 0.5;
  for (int i = 2; i <= 3; ++i) b(i, 2) = 0.0;  // column 2 is zero on and below the diagonal...
  b(1, 2) = 0.0;                               // ...and above it
  std::vector<int> pivots(6);
  EXPECT_EQ(bandLuFactor(b.ab.data(), b.ldab, 6, 1, 1, pivots.data()), 3);
}
