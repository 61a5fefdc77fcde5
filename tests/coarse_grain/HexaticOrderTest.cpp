// Bond-orientational order psi6 (coarse_grain/HexaticOrder.hpp) on synthetic packings.
// Expected values: triangular lattice, all bonds at multiples of 60 degrees, |psi6| = 1;
// square lattice, bonds at multiples of 90 degrees, 1 - 1 + 1 - 1 = 0; random packings, the
// mean step of an n-step random walk W_n / n (Borwein et al., Can. J. Math. 64, 961 (2012));
// a lattice with Gaussian position noise, exp(-36 sigma^2 / a^2) (bond-angle noise).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "coarse_grain/HexaticOrder.hpp"

using granwave::hexaticOrder;
using granwave::neighboursWithin;

namespace {

constexpr double d = 0.002;  // paper, Table I
constexpr double pi = std::numbers::pi;

struct Packing {
  std::vector<double> x, z;
};

// nx by nz triangular lattice of spacing a (odd rows shifted by a/2), bonds at 0, 60, ...
// degrees, rotated by `angle` about the first particle.
Packing triangular(int nx, int nz, double a, double angle = 0.0) {
  Packing p;
  for (int r = 0; r < nz; ++r) {
    for (int i = 0; i < nx; ++i) {
      const double x = (i + 0.5 * (r % 2)) * a + 0.5 * a, z = r * a * std::sqrt(3.0) / 2;
      p.x.push_back(std::cos(angle) * x - std::sin(angle) * z);
      p.z.push_back(std::sin(angle) * x + std::cos(angle) * z + 0.5 * a);
    }
  }
  return p;
}

Packing square(int nx, int nz, double a) {
  Packing p;
  for (int r = 0; r < nz; ++r)
    for (int i = 0; i < nx; ++i) p.x.push_back((i + 0.5) * a), p.z.push_back((r + 0.5) * a);
  return p;
}

// Uniform numbers in [0, 1) from the raw engine (fixed seed, portable across libraries).
double uniform(std::mt19937_64& rng) { return (rng() >> 11) * 0x1.0p-53; }

// True if a disk at (x, z) overlaps none of the disks of `p` in the buckets around (ix, iz).
bool fits(const Packing& p, const std::vector<std::vector<int>>& bucket, int nbx, int nbz, double x,
          double z, int ix, int iz) {
  for (int jz = std::max(0, iz - 1); jz <= std::min(nbz - 1, iz + 1); ++jz)
    for (int jx = std::max(0, ix - 1); jx <= std::min(nbx - 1, ix + 1); ++jx)
      for (int k : bucket[static_cast<std::size_t>(jz) * nbx + jx])
        if (std::hypot(x - p.x[k], z - p.z[k]) < d) return false;
  return true;
}

// Random sequential addition of disks of diameter d in a w x h box with walls, until
// `attempts` trial positions have been drawn (near the jamming coverage 0.547 of 2D RSA,
// Feder, J. Theor. Biol. 87, 237 (1980)).
Packing randomSequentialAddition(double w, double h, long attempts, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const int nbx = static_cast<int>(w / d), nbz = static_cast<int>(h / d);
  std::vector<std::vector<int>> bucket(static_cast<std::size_t>(nbx) * nbz);
  Packing p;
  for (long t = 0; t < attempts; ++t) {
    const double x = 0.5 * d + uniform(rng) * (w - d), z = 0.5 * d + uniform(rng) * (h - d);
    const int ix = std::min(nbx - 1, static_cast<int>(x / (w / nbx)));
    const int iz = std::min(nbz - 1, static_cast<int>(z / (h / nbz)));
    if (!fits(p, bucket, nbx, nbz, x, z, ix, iz)) continue;
    bucket[static_cast<std::size_t>(iz) * nbx + ix].push_back(static_cast<int>(p.x.size()));
    p.x.push_back(x);
    p.z.push_back(z);
  }
  return p;
}

// Mean step of an n-step planar random walk with unit steps, divided by n: W_n / n
// (Borwein, Straub, Wan, Zudilin 2012: W_2 = 4/pi, W_3 = 1.57460, W_4 = 1.79909,
// W_5 = 2.00816, W_6 = 2.19386); n >= 7 by the large-n form sqrt(pi n) / 2.
double randomBondPsi6(int n) {
  static const double W[] = {0, 1, 4 / pi, 1.57460, 1.79909, 2.00816, 2.19386};
  return (n <= 6 ? W[n] : std::sqrt(pi * n) / 2) / n;
}

}  // namespace

TEST(HexaticOrder, TriangularLatticeIsPerfectlyHexatic) {
  // Every particle, interior or on the edge, has all bonds at multiples of 60 degrees.
  const Packing p = triangular(20, 12, d);
  const auto h = hexaticOrder(p.x, p.z, 0.0, d, false);
  for (std::size_t j = 0; j < p.x.size(); ++j) EXPECT_NEAR(std::abs(h.psi6[j]), 1.0, 1e-12);
  EXPECT_NEAR(h.mean_abs_psi6, 1.0, 1e-12);
  EXPECT_NEAR(h.abs_mean_psi6, 1.0, 1e-12);
  EXPECT_EQ(h.neighbours[5 * 20 + 5], 6);  // an interior particle (row 5, column 5)
  EXPECT_EQ(h.neighbours[0], 2);           // corner with two bonds: left out of the means
  EXPECT_EQ(h.counted, 240 - 2);
}

TEST(HexaticOrder, RotatedLatticeKeepsModulusAndTurnsPhaseSixfold) {
  // Rotating the lattice by alpha turns every bond by alpha: psi6 -> psi6 exp(6 i alpha).
  const double alpha = 0.05;
  const Packing p = triangular(12, 12, d, alpha);
  const auto h = hexaticOrder(p.x, p.z, 0.0, d, false);
  EXPECT_NEAR(h.mean_abs_psi6, 1.0, 1e-12);
  EXPECT_NEAR(std::arg(h.psi6[30]), 6 * alpha, 1e-12);
}

TEST(HexaticOrder, DilatedLatticeWithinCutoffIsStillHexatic) {
  // Spacing 1.15 d (a layer dilated by 15 % in flight) is still inside the 1.2 d cutoff.
  const Packing p = triangular(10, 10, 1.15 * d);
  EXPECT_NEAR(hexaticOrder(p.x, p.z, 0.0, d, false).mean_abs_psi6, 1.0, 1e-12);
}

TEST(HexaticOrder, SquareLatticeHasNoHexaticOrder) {
  // Interior: four bonds at 90 degrees, exp(6 i k pi / 2) = 1, -1, 1, -1: psi6 = 0.
  // Edges (not corners): three bonds 1 - 1 + 1 -> 1/3. Corners: two bonds, left out.
  // Mean over an n x n lattice: 4 (n - 2) (1/3) / (n^2 - 4) = 0.0606 for n = 20.
  const int n = 20;
  const Packing p = square(n, n, d);
  const auto h = hexaticOrder(p.x, p.z, 0.0, d, false);
  for (int r = 1; r < n - 1; ++r)
    for (int i = 1; i < n - 1; ++i) EXPECT_NEAR(std::abs(h.psi6[r * n + i]), 0.0, 1e-12);
  EXPECT_NEAR(std::abs(h.psi6[5]), 1.0 / 3.0, 1e-12);  // bottom edge
  EXPECT_NEAR(h.mean_abs_psi6, 4.0 * (n - 2) / 3.0 / (n * n - 4), 1e-12);
}

TEST(HexaticOrder, RandomSequentialAdditionIsOrientationallyDisordered) {
  // RSA near jamming (fixed seed), 30 d x 20 d with walls. Bond angles are random apart from
  // excluded volume (two bonds of length < 1.2 d are at least 2 asin(1/2.4) = 49 degrees
  // apart), so <|psi6|> should be close to the random-walk value <W_n / n> over the
  // measured bond-number distribution (0.53 for 3 bonds, 0.45 for 4), far below the 1 of a
  // lattice. RSA is sparse (about 2 bonds per particle within 1.2 d); excluded volume spaces
  // the bonds more evenly than chance, which raises <|psi6|> a little: 0.45 - 0.65 expected.
  const Packing p = randomSequentialAddition(30 * d, 20 * d, 400000, 2024);
  const double coverage = p.x.size() * pi * d * d / 4 / (30 * d * 20 * d);
  EXPECT_GT(coverage, 0.5);  // RSA jamming: 0.547 (finite box and walls: a bit less)
  const auto h = hexaticOrder(p.x, p.z, 0.0, d, false);
  double random_bonds = 0;
  int counted = 0;
  for (int n : h.neighbours)
    if (n >= 3) random_bonds += randomBondPsi6(n), ++counted;
  random_bonds /= counted;
  EXPECT_EQ(counted, h.counted);
  EXPECT_GT(h.mean_abs_psi6, 0.45);
  EXPECT_LT(h.mean_abs_psi6, 0.65);
  EXPECT_NEAR(h.mean_abs_psi6, random_bonds, 0.1);
  // No common orientation: |<psi6>| ~ <|psi6|> / sqrt(counted) for random phases, somewhat
  // more because walls bias the bond angles of the particles next to them; a single
  // crystallite would give 1.
  EXPECT_LT(h.abs_mean_psi6, 0.3);
}

TEST(HexaticOrder, NoisyLatticeFollowsTheBondAngleEstimate) {
  // Gaussian noise sigma = 0.05 d per coordinate: bond-angle noise sqrt(2) sigma / a,
  // |psi6| ~ exp(-18 (sqrt(2) sigma / a)^2) = exp(-36 * 0.0025) = 0.914.
  Packing p = triangular(20, 20, d);
  std::mt19937_64 rng(5);
  for (std::size_t j = 0; j < p.x.size(); ++j) {
    const double u1 = uniform(rng) + 0x1.0p-54, u2 = uniform(rng);
    const double r = 0.05 * d * std::sqrt(-2 * std::log(u1));
    p.x[j] += r * std::cos(2 * pi * u2);
    p.z[j] += r * std::sin(2 * pi * u2);
  }
  EXPECT_NEAR(hexaticOrder(p.x, p.z, 0.0, d, false).mean_abs_psi6, std::exp(-36 * 0.0025), 0.03);
}

TEST(HexaticOrder, PeriodicXGivesEdgeParticlesTheirFullShell) {
  // 20 x 10 triangular lattice in a periodic box of width 20 d: every particle of the
  // interior rows has 6 neighbours, including those at the ends of the rows; with walls the
  // row end that faces two particles of each neighbouring row (the right end of even rows,
  // the left end of odd rows, which are shifted by d/2) has 5, the other end 3.
  const Packing p = triangular(20, 10, d);
  const auto periodic = hexaticOrder(p.x, p.z, 20 * d, d, true);
  const auto walls = hexaticOrder(p.x, p.z, 20 * d, d, false);
  for (int r = 1; r < 9; ++r) {
    for (int i = 0; i < 20; ++i) EXPECT_EQ(periodic.neighbours[r * 20 + i], 6);
    EXPECT_EQ(walls.neighbours[r * 20 + (r % 2 == 0 ? 19 : 0)], 5);
    EXPECT_EQ(walls.neighbours[r * 20 + (r % 2 == 0 ? 0 : 19)], 3);
  }
  EXPECT_NEAR(periodic.mean_abs_psi6, 1.0, 1e-12);
}

TEST(HexaticOrder, CellListNeighboursMatchAllPairs) {
  // Reference: all N^2 pairs with the minimum image in x.
  const double w = 12 * d;
  Packing p = randomSequentialAddition(w, 10 * d, 20000, 3);
  for (double& x : p.x) x += 0.3 * d;  // some centres beyond x = L: wrapped by the search
  for (bool periodic : {false, true}) {
    const auto nb = neighboursWithin(p.x, p.z, 1.2 * d, w, periodic);
    for (std::size_t j = 0; j < p.x.size(); ++j) {
      std::vector<int> ref;
      for (std::size_t k = 0; k < p.x.size(); ++k) {
        double rx = p.x[k] - p.x[j];
        if (periodic) rx -= w * std::round(rx / w);
        if (k != j && std::hypot(rx, p.z[k] - p.z[j]) < 1.2 * d) ref.push_back(static_cast<int>(k));
      }
      EXPECT_EQ(nb[j], ref) << "particle " << j << (periodic ? " periodic" : " walls");
    }
  }
}

TEST(HexaticOrder, IsolatedParticlesAreLeftOut) {
  // Two particles far apart: no bonds, psi6 = 0, nothing counted, means 0 (not NaN).
  const std::vector<double> x = {0.5 * d, 10 * d}, z = {0.5 * d, 0.5 * d};
  const auto h = hexaticOrder(x, z, 0.0, d, false);
  EXPECT_EQ(h.counted, 0);
  EXPECT_EQ(h.mean_abs_psi6, 0.0);
  EXPECT_EQ(std::abs(h.psi6[0]), 0.0);
}

TEST(HexaticOrder, RejectsBadInput) {
  const std::vector<double> x = {0.0, d}, z = {0.0};
  EXPECT_THROW(hexaticOrder(x, z, 0.0, d, false), std::invalid_argument);
  EXPECT_THROW(hexaticOrder(x, x, 0.0, 0.0, false), std::invalid_argument);
  EXPECT_THROW(hexaticOrder(x, x, 0.0, d, true), std::invalid_argument);
}
