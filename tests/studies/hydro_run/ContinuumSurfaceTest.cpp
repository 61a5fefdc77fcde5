// The 2D continuum's surface by the particles' rule (studies/hydro_run/ContinuumSurface.hpp):
// on layers of known shape, the area fraction sampled on the surface's grid and the height
// where it falls through half its bulk value.
#include <gtest/gtest.h>

#include <stdexcept>

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
  // A blurred step crosses half its height at the step (the Gaussian kernel is symmetric);
  // linear interpolation between bins 0.25 d apart errs by far less than 0.01 d there.
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
  for (double h : s.profile.height) EXPECT_NEAR(h, 10 * d, 0.01 * d);
}

TEST(ContinuumSurface, EachSurfaceColumnTakesTheHeightOfTheContinuumColumnUnderIt) {
  // Continuum columns 4 d wide of heights 8, 12, 9, 11 d (periodic, 16 d): the two surface
  // columns in the middle of each lie 1.5 d (3 kernel widths) from its edges, so the x blur
  // leaks 0.13 % of the neighbours' area into them: their height is the column's to 0.02 d.
  const ContinuumColumns c{4, 20, 16 * d, true, d};
  const std::vector<double> h = {8 * d, 12 * d, 9 * d, 11 * d};
  const LayerSurface s = continuumSurface(layer(h, 20, 0.7), c);
  ASSERT_EQ(s.profile.height.size(), 16u);
  for (int i = 0; i < 4; ++i)
    for (int inner : {1, 2}) EXPECT_NEAR(s.profile.height[4 * i + inner], h[i], 0.02 * d) << i;
}

TEST(ContinuumSurface, PhaseThatDoesNotFitItsColumnsIsRefused) {
  const ContinuumColumns c{4, 10, 16 * d, true, d};
  EXPECT_THROW(continuumAreaFraction(layer({8 * d, 8 * d, 8 * d}, 10, 0.7), c),
               std::invalid_argument);
  EXPECT_THROW(continuumAreaFraction(layer(std::vector<double>(4, 8 * d), 9, 0.7), c),
               std::invalid_argument);
}
