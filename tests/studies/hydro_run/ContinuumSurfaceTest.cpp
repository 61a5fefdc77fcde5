// The 2D continuum's surface by the particles' rule (studies/hydro_run/ContinuumSurface.hpp):
// on layers of known shape, the area fraction sampled on the surface's grid and the height
// where it falls through half its bulk value.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "studies/hydro_run/ContinuumSurface.hpp"

using namespace granwave;

namespace {

constexpr double d = 0.002;

// Columns of `cells` equal cells of area fraction `phi` from the plate up to heights[i].
hydro::Hydro2DPhase layer(const std::vector<double>& heights, int cells, double phi) {
  hydro::Hydro2DPhase ph;
  for (double h : heights) {
    for (int j = 0; j <= cells; ++j) ph.node_z.push_back(h * j / cells);
    for (int k = 0; k < cells; ++k) ph.area_fraction.push_back(phi);
  }
  return ph;
}

}  // namespace

TEST(ContinuumSurface, FlatLayerIsSampledCellByCellAndItsSurfaceIsItsTop) {
  // A blurred step crosses half its height at the step: the kernel is symmetric and the top
  // bin, half covered, holds half the bulk value, so the linear interpolation between bins
  // meets the crossing exactly (to round-off).
  const ContinuumColumns c{6, 10, 24 * d, true, d};
  const hydro::Hydro2DPhase ph = layer(std::vector<double>(6, 10 * d), 10, 0.8);
  const AreaFractionGrid g = continuumAreaFraction(ph, c);
  EXPECT_EQ(g.columns, 24);
  EXPECT_DOUBLE_EQ(g.dz, 0.25 * d);
  for (int i = 0; i < g.columns; ++i) {
    EXPECT_NEAR(g.at(i, 0), 0.4, 1e-12);   // the plate's bin, -0.125 to 0.125 d: half inside
    EXPECT_NEAR(g.at(i, 20), 0.8, 1e-12);  // 4.875 to 5.125 d, across a cell boundary
    EXPECT_NEAR(g.at(i, 40), 0.4, 1e-12);  // 9.875 to 10.125 d: half below the top
    EXPECT_DOUBLE_EQ(g.at(i, 41), 0.0);    // above the layer
  }
  const LayerSurface s = continuumSurface(ph, c);
  EXPECT_NEAR(s.bulk_area_fraction, 0.8, 1e-12);
  EXPECT_EQ(s.thin_columns, 0);
  for (double h : s.profile.height) EXPECT_NEAR(h, 10 * d, 1e-9 * d);
}

TEST(ContinuumSurface, EachSurfaceColumnTakesTheHeightOfTheContinuumColumnUnderIt) {
  // Continuum columns 4 d wide of heights 8, 12, 9, 11 d (periodic, 16 d): the two surface
  // columns in the middle of each lie 1.5 d (3 kernel widths) from its edges, so the kernel's
  // discrete weights leak a few 1e-4 of the neighbours' area into them, which moves the
  // half-bulk crossing by a few 1e-4 d (measured 1.8e-4 d): their height is the column's to
  // 1e-3 d.
  const ContinuumColumns c{4, 20, 16 * d, true, d};
  const std::vector<double> h = {8 * d, 12 * d, 9 * d, 11 * d};
  const LayerSurface s = continuumSurface(layer(h, 20, 0.7), c);
  ASSERT_EQ(s.profile.height.size(), 16u);
  for (int i = 0; i < 4; ++i)
    for (int inner : {1, 2}) EXPECT_NEAR(s.profile.height[4 * i + inner], h[i], 1e-3 * d) << i;
}

TEST(ContinuumSurface, NarrowContinuumColumnsAreAveragedOverEachSurfaceColumn) {
  // 60 continuum columns over 30 d, alternately 9 and 11 d high: each surface column (1 d)
  // holds two halves, area fraction 0.8 up to 9 d and 0.4 up to 11 d, a profile symmetric about
  // (10 d, 0.4): it falls through half the bulk value 0.8 at 10 d exactly, in every column (a
  // sample of one continuum column would give 9 or 11 d).
  const ContinuumColumns c{60, 10, 30 * d, true, d};
  std::vector<double> h;
  for (int i = 0; i < 60; ++i) h.push_back(i % 2 ? 11 * d : 9 * d);
  const LayerSurface s = continuumSurface(layer(h, 10, 0.8), c);
  ASSERT_EQ(s.profile.height.size(), 30u);
  for (double x : s.profile.height) EXPECT_NEAR(x, 10 * d, 1e-9 * d);
}

TEST(ContinuumSurface, PhaseThatDoesNotFitItsColumnsIsRefused) {
  const ContinuumColumns c{4, 10, 16 * d, true, d};
  EXPECT_THROW(continuumAreaFraction(layer({8 * d, 8 * d, 8 * d}, 10, 0.7), c),
               std::invalid_argument);
  EXPECT_THROW(continuumAreaFraction(layer(std::vector<double>(4, 8 * d), 9, 0.7), c),
               std::invalid_argument);
}
