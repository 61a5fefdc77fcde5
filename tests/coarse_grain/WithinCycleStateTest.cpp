// The within-cycle solid criterion (coarse_grain/WithinCycleState.hpp) on synthetic cycles.
// Expected numbers from geometry: a triangular slab of R rows and C columns of spacing d
// (walls, not periodic) has (3 C R - 2 C - 2 R + 1) * 2 / (C R) bonds per disk within 1.2 d:
// 6 inside, 4 at the top and bottom rows, fewer at the corners. A lattice dilated by 1.5
// (spacing 1.5 d > 1.2 d) has none. Its psi6 is 1 (HexaticOrderTest).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "coarse_grain/WithinCycleState.hpp"

using granwave::classifyWithinCycles;
using granwave::LayerState;
using granwave::meanCoordination;
using granwave::Snapshot;
using granwave::WithinCycleResult;

namespace {

constexpr double d = 0.002;  // paper, Table I
constexpr int kColumns = 20, kRows = 10;
constexpr double width = (kColumns + 1) * d;

// Triangular lattice of spacing a * d resting on a plate at `plate`.
Snapshot triangular(double a, double plate = 0) {
  Snapshot s;
  s.plate_height = plate;
  for (int r = 0; r < kRows; ++r)
    for (int i = 0; i < kColumns; ++i) {
      s.x.push_back((i + 0.5 * (r % 2)) * a * d + 0.5 * d);
      s.z.push_back(plate + r * a * d * std::sqrt(3.0) / 2 + 0.5 * d);
    }
  return s;
}

// Bonds per disk of a C x R triangular slab with offset rows: horizontal C - 1 per row,
// and 2 C - 1 between consecutive rows.
double slabCoordination() {
  const double bonds = kRows * (kColumns - 1) + (kRows - 1) * (2.0 * kColumns - 1);
  return 2 * bonds / (kColumns * kRows);
}

}  // namespace

TEST(WithinCycleState, CoordinationOfATriangularSlabCountsItsBonds) {
  EXPECT_NEAR(meanCoordination(triangular(1.0), 1.2 * d, width, false), slabCoordination(), 1e-12);
  EXPECT_EQ(meanCoordination(triangular(1.5), 1.2 * d, width, false), 0.0);
}

TEST(WithinCycleState, ALatticeCompactOnceACycleIsACrystalAtItsCompactPhase) {
  // Dilated (a gas to the coordination) at 3 of 4 phases, a lattice at phase 2.
  std::vector<std::vector<Snapshot>> cycles(6);
  for (auto& c : cycles) c = {triangular(1.5), triangular(1.5), triangular(1.0), triangular(1.5)};
  const WithinCycleResult r = classifyWithinCycles(cycles, width, 0.06, d, false);
  EXPECT_EQ(r.state, LayerState::crystal);
  EXPECT_EQ(r.crystal_share, 1.0);
  EXPECT_DOUBLE_EQ(r.compact_phase, 0.5);
  EXPECT_NEAR(r.coordination, slabCoordination(), 1e-12);
  EXPECT_NEAR(r.psi6, 1.0, 1e-12);
  EXPECT_EQ(r.cycles, 6);
}

TEST(WithinCycleState, ALayerNeverCompactIsLiquidLike) {
  std::vector<std::vector<Snapshot>> cycles(4, {triangular(1.5), triangular(1.3)});
  const WithinCycleResult r = classifyWithinCycles(cycles, width, 0.06, d, false);
  EXPECT_EQ(r.state, LayerState::liquid_like);
  EXPECT_EQ(r.liquid_share, 1.0);
  EXPECT_LT(r.coordination, 4.0);
}

TEST(WithinCycleState, TheMostFrequentCycleLabelWins) {
  // 3 compact cycles, 1 dilated: crystal in 3/4.
  std::vector<std::vector<Snapshot>> cycles(3, {triangular(1.0)});
  cycles.push_back({triangular(1.5)});
  const WithinCycleResult r = classifyWithinCycles(cycles, width, 0.06, d, false);
  EXPECT_EQ(r.state, LayerState::crystal);
  EXPECT_DOUBLE_EQ(r.crystal_share, 0.75);
  EXPECT_DOUBLE_EQ(r.liquid_share, 0.25);
}

TEST(WithinCycleState, CountsTheTopRowPressedAgainstTheLid) {
  // The slab's top row is at plate + 0.5 d + 9 sqrt(3)/2 d; a container of that height plus
  // 0.5 d puts the lid exactly on it (20 disks), one 0.2 d higher leaves a gap (none).
  const double top = (kRows - 1) * d * std::sqrt(3.0) / 2 + d;
  std::vector<std::vector<Snapshot>> cycles(2, {triangular(1.0, 0.01)});
  EXPECT_DOUBLE_EQ(classifyWithinCycles(cycles, width, top, d, false).lid_row, kColumns);
  EXPECT_DOUBLE_EQ(classifyWithinCycles(cycles, width, top, d, false).lid_row_cycles, 1.0);
  EXPECT_DOUBLE_EQ(classifyWithinCycles(cycles, width, top + 0.2 * d, d, false).lid_row, 0.0);
}

TEST(WithinCycleState, RejectsEmptyInputAndUnequalCycles) {
  EXPECT_THROW(classifyWithinCycles({}, width, 0.06, d, false), std::invalid_argument);
  std::vector<std::vector<Snapshot>> uneven = {{triangular(1.0)},
                                               {triangular(1.0), triangular(1.0)}};
  EXPECT_THROW(classifyWithinCycles(uneven, width, 0.06, d, false), std::invalid_argument);
  EXPECT_THROW(classifyWithinCycles({{triangular(1.0)}}, width, 0.06, 0.0, false),
               std::invalid_argument);
}
