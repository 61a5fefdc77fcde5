// Surface height h(x) of a layer (coarse_grain/SurfaceProfile.hpp): top particle centre
// + d/2 above the plate per column; empty columns from their neighbours. Every expected value
// is the definition evaluated by hand on a small synthetic snapshot.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "coarse_grain/SurfaceProfile.hpp"

using granwave::Snapshot;
using granwave::SurfaceProfile;
using granwave::surfaceProfile;
using granwave::SurfaceProfileOptions;

namespace {

constexpr double d = 0.002;  // paper, Table I

void add(Snapshot& s, double x, double z) {
  s.x.push_back(x);
  s.z.push_back(z);
}

// Columns of `height_in_d[i]` particles stacked on the plate at x = (i + 1/2) d.
Snapshot stackedColumns(const std::vector<int>& height_in_d, double plate) {
  Snapshot s;
  s.plate_height = plate;
  for (std::size_t i = 0; i < height_in_d.size(); ++i)
    for (int k = 0; k < height_in_d[i]; ++k) add(s, (i + 0.5) * d, plate + (k + 0.5) * d);
  return s;
}

}  // namespace

TEST(SurfaceProfile, StackedColumnsGiveTheirHeightAboveThePlate) {
  // Column i holds n_i particles: top centre at plate + (n_i - 1/2) d, so h_i = n_i d,
  // whatever the plate position (here 3.7 mm above its mid-stroke).
  const std::vector<int> n = {3, 4, 5, 4, 3, 2};
  const Snapshot s = stackedColumns(n, 0.0037);
  const SurfaceProfile p = surfaceProfile(s, 6 * d, d, false);
  ASSERT_EQ(p.columns(), 6);  // default: L_x / d columns
  EXPECT_DOUBLE_EQ(p.column_width, d);
  EXPECT_EQ(p.empty_columns, 0);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(p.height[i], n[i] * d, 1e-15) << "column " << i;
  EXPECT_NEAR(p.columnCentre(2), 2.5 * d, 1e-18);
  EXPECT_NEAR(p.width(), 6 * d, 1e-18);
}

TEST(SurfaceProfile, TopmostParticleCountsNotTheOrderOfTheArrays) {
  Snapshot s;
  add(s, 0.5 * d, 2.5 * d);
  add(s, 0.5 * d, 0.5 * d);
  add(s, 0.7 * d, 1.5 * d);
  add(s, 1.5 * d, 0.5 * d);
  const SurfaceProfile p = surfaceProfile(s, 2 * d, d, false);
  EXPECT_NEAR(p.height[0], 3.0 * d, 1e-15);
  EXPECT_NEAR(p.height[1], 1.0 * d, 1e-15);
}

TEST(SurfaceProfile, SingleEmptyColumnTakesTheAverageOfItsNeighbours) {
  // Column 2 empty between heights 4 d and 6 d: (4 + 6) / 2 = 5 d.
  const Snapshot s = stackedColumns({3, 4, 0, 6, 3}, 0.0);
  const SurfaceProfile p = surfaceProfile(s, 5 * d, d, false);
  EXPECT_EQ(p.empty_columns, 1);
  EXPECT_NEAR(p.height[2], 5.0 * d, 1e-15);
}

TEST(SurfaceProfile, RunOfEmptyColumnsIsInterpolatedLinearly) {
  // Columns 1-3 empty between 2 d and 6 d: 3 d, 4 d, 5 d.
  const Snapshot s = stackedColumns({2, 0, 0, 0, 6}, 0.0);
  const SurfaceProfile p = surfaceProfile(s, 5 * d, d, false);
  EXPECT_EQ(p.empty_columns, 3);
  EXPECT_NEAR(p.height[1], 3.0 * d, 1e-15);
  EXPECT_NEAR(p.height[2], 4.0 * d, 1e-15);
  EXPECT_NEAR(p.height[3], 5.0 * d, 1e-15);
}

TEST(SurfaceProfile, EmptyColumnsAtAWallCopyTheNearestColumn) {
  // Zero slope at a vertical wall: columns 0 and 4-5 copy columns 1 and 3.
  const Snapshot s = stackedColumns({0, 3, 4, 5, 0, 0}, 0.0);
  const SurfaceProfile p = surfaceProfile(s, 6 * d, d, false);
  EXPECT_NEAR(p.height[0], 3.0 * d, 1e-15);
  EXPECT_NEAR(p.height[4], 5.0 * d, 1e-15);
  EXPECT_NEAR(p.height[5], 5.0 * d, 1e-15);
}

TEST(SurfaceProfile, PeriodicEmptyColumnsInterpolateAcrossTheBoundary) {
  // Periodic, columns 0 and 4-5 empty between column 3 (5 d) and column 1 (3 d), going
  // right from 3: 4 -> 5 - 2/4, 5 -> 5 - 2 * 2/4, 0 -> 5 - 3 * 2/4.
  const Snapshot s = stackedColumns({0, 3, 4, 5, 0, 0}, 0.0);
  const SurfaceProfile p = surfaceProfile(s, 6 * d, d, true);
  EXPECT_NEAR(p.height[4], 4.5 * d, 1e-15);
  EXPECT_NEAR(p.height[5], 4.0 * d, 1e-15);
  EXPECT_NEAR(p.height[0], 3.5 * d, 1e-15);
}

TEST(SurfaceProfile, PeriodicPositionsOutsideTheBoxAreWrapped) {
  Snapshot s;
  add(s, -0.5 * d, 2.5 * d);  // wraps to column 3 of 4
  add(s, 4.5 * d, 0.5 * d);   // wraps to column 0
  add(s, 1.5 * d, 0.5 * d);
  add(s, 2.5 * d, 0.5 * d);
  const SurfaceProfile p = surfaceProfile(s, 4 * d, d, true);
  EXPECT_EQ(p.empty_columns, 0);
  EXPECT_NEAR(p.height[3], 3.0 * d, 1e-15);
  EXPECT_NEAR(p.height[0], 1.0 * d, 1e-15);
}

TEST(SurfaceProfile, CentresOnTheRightWallBelongToTheLastColumn) {
  Snapshot s;
  add(s, 0.5 * d, 0.5 * d);
  add(s, 2.0 * d, 1.5 * d);  // x = L_x exactly
  const SurfaceProfile p = surfaceProfile(s, 2 * d, d, false);
  EXPECT_NEAR(p.height[1], 2.0 * d, 1e-15);
}

TEST(SurfaceProfile, ExplicitColumnCountSetsTheColumnWidth) {
  const Snapshot s = stackedColumns({1, 1, 1, 1, 1, 1}, 0.0);
  SurfaceProfileOptions opt;
  opt.n_columns = 3;
  const SurfaceProfile p = surfaceProfile(s, 6 * d, d, false, opt);
  ASSERT_EQ(p.columns(), 3);
  EXPECT_DOUBLE_EQ(p.column_width, 2 * d);
}

TEST(SurfaceProfile, NoParticleMeansZeroThicknessNotNaN) {
  const SurfaceProfile p = surfaceProfile(Snapshot{}, 4 * d, d, false);
  EXPECT_EQ(p.empty_columns, 4);
  for (double h : p.height) EXPECT_EQ(h, 0.0);
}

TEST(SurfaceProfile, RejectsBadGeometry) {
  EXPECT_THROW(surfaceProfile(Snapshot{}, 0.0, d, false), std::invalid_argument);
  EXPECT_THROW(surfaceProfile(Snapshot{}, 4 * d, -d, false), std::invalid_argument);
  Snapshot s;
  s.x = {0.001};
  EXPECT_THROW(surfaceProfile(s, 4 * d, d, false), std::invalid_argument);
}
