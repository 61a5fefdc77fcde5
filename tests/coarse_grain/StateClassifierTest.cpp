// Crystal / amorphous / liquid-like classification (coarse_grain/StateClassifier.hpp) on
// synthetic layers at one drive phase in consecutive cycles. Expected numbers: a rigid
// motion gives zero relative displacement (the neighbours move by the same vector);
// independent noise sigma per coordinate in each snapshot gives a displacement of
// sqrt(2) sigma per coordinate, sqrt(1 + 1/n) times more relative to the mean of n
// neighbours, and a mean modulus sqrt(pi/2) times that; random steps of length d give
// <delta> ~ d sqrt(1 + 1/n); psi6 as in HexaticOrderTest. Bonds (pairs closer than 1.2 d)
// break beyond 1.5 d: a rigid motion keeps all, bounded rattling keeps all whose distance
// cannot grow past 1.5 d, random walks of a diameter per cycle break most.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "coarse_grain/StateClassifier.hpp"

using granwave::classifyState;
using granwave::LayerState;
using granwave::meanRelativeDisplacement;
using granwave::Snapshot;
using granwave::StateResult;

namespace {

constexpr double d = 0.002;  // paper, Table I
constexpr double pi = std::numbers::pi;
constexpr double width = 20 * d;

double uniform(std::mt19937_64& rng) { return (rng() >> 11) * 0x1.0p-53; }

// 20 x 10 triangular lattice of spacing d in a box 20 d wide, resting on the plate.
Snapshot triangular() {
  Snapshot s;
  for (int r = 0; r < 10; ++r) {
    for (int i = 0; i < 20; ++i) {
      s.x.push_back((i + 0.5 * (r % 2)) * d + 0.5 * d);
      s.z.push_back(r * d * std::sqrt(3.0) / 2 + 0.5 * d);
    }
  }
  return s;
}

// Random sequential addition of disks in a 20 d x 12 d box (fixed seed; see
// HexaticOrderTest for the construction and its psi6).
Snapshot randomPacking() {
  std::mt19937_64 rng(99);
  Snapshot s;
  for (long t = 0; t < 200000; ++t) {
    const double x = 0.5 * d + uniform(rng) * (width - d), z = 0.5 * d + uniform(rng) * 11 * d;
    bool free = true;
    for (std::size_t k = 0; k < s.x.size() && free; ++k)
      free = std::hypot(x - s.x[k], z - s.z[k]) >= d;
    if (free) s.x.push_back(x), s.z.push_back(z);
  }
  return s;
}

// K snapshots: the layer translated rigidly by a different vector each cycle (flight
// height, drift), plus independent Gaussian noise of `sigma` (in d) per coordinate.
std::vector<Snapshot> rigidlyVibrating(const Snapshot& base, int K, double sigma) {
  std::mt19937_64 rng(17);
  std::vector<Snapshot> out;
  for (int c = 0; c < K; ++c) {
    Snapshot s = base;
    s.time = 0.1 * c;
    const double shift_x = 0.4 * d * std::sin(1.3 * c), shift_z = 3.0 * d * (c % 2);
    for (std::size_t j = 0; j < s.x.size(); ++j) {
      const double r = sigma * d * std::sqrt(-2 * std::log(uniform(rng) + 0x1.0p-54));
      const double phi = 2 * pi * uniform(rng);
      s.x[j] += shift_x + r * std::cos(phi);
      s.z[j] += shift_z + r * std::sin(phi);
    }
    out.push_back(s);
  }
  return out;
}

}  // namespace

TEST(StateClassifier, RigidlyVibratingLatticeIsCrystal) {
  // Collective shifts of up to 3 d cancel against the neighbours; noise 0.01 d leaves
  // <delta> ~ 0.02 d << 0.15 d, and psi6 ~ exp(-36e-4) = 0.996 > 0.7.
  const StateResult r = classifyState(rigidlyVibrating(triangular(), 6, 0.01), width, d, false);
  EXPECT_EQ(r.state, LayerState::crystal);
  EXPECT_LT(r.mean_relative_displacement_d, 0.05);
  EXPECT_GT(r.mean_collective_displacement_d, 1.0);  // the layer did move
  EXPECT_GT(r.mean_abs_psi6, 0.95);
  EXPECT_EQ(r.cycles, 6);
  EXPECT_EQ(r.bonds_kept_per_cycle, 1.0);
}

TEST(StateClassifier, RigidlyMovingRandomPackingIsAmorphous) {
  // Caged (same rigid motion) but random bond angles: <|psi6|> ~ 0.4 - 0.6 < 0.7.
  const StateResult r = classifyState(rigidlyVibrating(randomPacking(), 6, 0.01), width, d, false);
  EXPECT_EQ(r.state, LayerState::amorphous);
  EXPECT_LT(r.mean_relative_displacement_d, 0.05);
  EXPECT_LT(r.mean_abs_psi6, 0.6);
}

TEST(StateClassifier, LatticeWithRandomStepsOfOneDiameterIsLiquidLike) {
  // Each particle steps by d in a random direction every cycle: relative to the mean step of
  // n neighbours, <delta> ~ d sqrt(1 + 1/n) ~ d, far above 0.15 d. The first snapshot is a
  // perfect lattice, so mobility, not psi6, makes the decision.
  std::mt19937_64 rng(23);
  std::vector<Snapshot> cycles = {triangular()};
  for (int c = 1; c < 5; ++c) {
    Snapshot s = cycles.back();
    for (std::size_t j = 0; j < s.x.size(); ++j) {
      const double phi = 2 * pi * uniform(rng);
      s.x[j] += d * std::cos(phi);
      s.z[j] += d * std::sin(phi);
    }
    cycles.push_back(s);
  }
  const StateResult r = classifyState(cycles, width, d, false);
  EXPECT_EQ(r.state, LayerState::liquid_like);
  EXPECT_LT(r.bonds_kept, 0.5);
  EXPECT_GT(r.mean_relative_displacement_d, 0.8);
  EXPECT_LT(r.mean_relative_displacement_d, 1.3);
}

TEST(StateClassifier, LargeRattlingInsideTheCageIsNotLiquid) {
  // Every particle sits at a random point within +-0.15 d (per coordinate) of its site in
  // each cycle, independently: per-cycle mobility about 0.17 d, above the 0.15 d dynamic
  // Lindemann threshold the classifier used before. But a pair at spacing 1.05 d can never be
  // farther apart than 1.05 d + 2 * 0.15 sqrt(2) d = 1.47 d < 1.5 d: no bond breaks, the
  // particles are caged, and psi6 ~ exp(-36 * 0.087^2 / 1.05^2) = 0.78 > 0.7: a crystal.
  Snapshot lattice = triangular();
  for (std::size_t j = 0; j < lattice.x.size(); ++j) {
    lattice.x[j] *= 1.05;
    lattice.z[j] *= 1.05;
  }
  std::mt19937_64 rng(31);
  std::vector<Snapshot> cycles;
  for (int c = 0; c < 16; ++c) {
    Snapshot s = lattice;
    for (std::size_t j = 0; j < s.x.size(); ++j) {
      s.x[j] += 0.3 * d * (uniform(rng) - 0.5);
      s.z[j] += 0.3 * d * (uniform(rng) - 0.5);
    }
    cycles.push_back(s);
  }
  const StateResult r = classifyState(cycles, 1.05 * width, d, false);
  EXPECT_GT(r.mean_relative_displacement_d, 0.15);
  EXPECT_EQ(r.bonds_kept, 1.0);
  EXPECT_EQ(r.state, LayerState::crystal);
}

TEST(StateClassifier, BondsKeptCountsPairsThatStayWithinTheFirstShell) {
  // Three disks in a row at spacing d: bonds (0,1) and (1,2). Moving disk 2 out to 1.6 d
  // from disk 1 breaks one of the two.
  Snapshot before, after;
  before.x = {1 * d, 2 * d, 3 * d};
  before.z = {d, d, d};
  after = before;
  after.x[2] = 3.6 * d;
  EXPECT_DOUBLE_EQ(granwave::bondsKept(before, after, width, false, 1.2 * d, 1.5 * d), 0.5);
  EXPECT_DOUBLE_EQ(granwave::bondsKept(before, before, width, false, 1.2 * d, 1.5 * d), 1.0);
  // Across a periodic boundary the minimum image keeps the bond.
  Snapshot wrap = before;
  wrap.x = {0.4 * d, width - 0.5 * d, 10 * d};
  Snapshot wrapped = wrap;
  wrapped.x[0] += 0.2 * d;
  EXPECT_DOUBLE_EQ(granwave::bondsKept(wrap, wrapped, width, true, 1.2 * d, 1.5 * d), 1.0);
}

TEST(StateClassifier, SmallCageRattlingIsAHotCrystal) {
  // Noise 0.05 d per coordinate in each snapshot: displacement between cycles has
  // 0.05 sqrt(2) d per coordinate, relative to 6 neighbours sqrt(1 + 1/6) times that,
  // mean modulus sqrt(pi/2) * 0.0764 d = 0.096 d; no bond stretches by 0.3 d: a crystal.
  const StateResult r = classifyState(rigidlyVibrating(triangular(), 6, 0.05), width, d, false);
  EXPECT_EQ(r.state, LayerState::crystal);
  EXPECT_NEAR(r.mean_relative_displacement_d, 0.096, 0.015);
}

TEST(StateClassifier, PeriodicShiftAcrossTheBoundaryIsNotMobility) {
  // Periodic x: the lattice shifted by 0.7 d and wrapped into [0, L_x): particles that
  // crossed x = L_x reappear near 0 but moved only 0.7 d (minimum image).
  const Snapshot a = triangular();
  Snapshot b = a;
  for (double& x : b.x) x = std::fmod(x + 0.7 * d, width);
  EXPECT_NEAR(meanRelativeDisplacement(a, b, width, true, 1.5 * d), 0.0, 1e-12 * d);
  EXPECT_GT(meanRelativeDisplacement(a, b, width, false, 1.5 * d), 0.1 * d);  // walls: no image
}

TEST(StateClassifier, BondsKeptPerCycleAveragesTheConsecutivePairs) {
  // Lattice, lattice, the lattice dilated twofold, the same again. Over the whole series every
  // bond at d ends at 2 d > 1.5 d: B = 0. From one cycle to the next: 1 (unchanged), 0 (every
  // bond stretched to 2 d), 1 (the dilated lattice has no bond to lose): B1 = 2/3.
  Snapshot dilated = triangular();
  for (std::size_t j = 0; j < dilated.x.size(); ++j) {
    dilated.x[j] *= 2;
    dilated.z[j] *= 2;
  }
  const std::vector<Snapshot> cycles = {triangular(), triangular(), dilated, dilated};
  const StateResult r = classifyState(cycles, 2 * width, d, false);
  EXPECT_EQ(r.bonds_kept, 0.0);
  EXPECT_NEAR(r.bonds_kept_per_cycle, 2.0 / 3.0, 1e-15);
  EXPECT_EQ(r.state, LayerState::liquid_like);  // B decides, not B1
}

TEST(StateClassifier, RejectsTooFewSnapshotsOrDifferentParticles) {
  const Snapshot a = triangular();
  EXPECT_THROW(classifyState({a}, width, d, false), std::invalid_argument);
  Snapshot b = a;
  b.x.pop_back();
  b.z.pop_back();
  EXPECT_THROW(classifyState({a, b}, width, d, false), std::invalid_argument);
  EXPECT_THROW(classifyState({a, a}, width, 0.0, false), std::invalid_argument);
}

TEST(StateClassifier, StateNames) {
  EXPECT_EQ(granwave::toString(LayerState::crystal), "crystal");
  EXPECT_EQ(granwave::toString(LayerState::amorphous), "amorphous");
  EXPECT_EQ(granwave::toString(LayerState::liquid_like), "liquid-like");
}
