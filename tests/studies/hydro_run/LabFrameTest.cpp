// The continuum's plate-frame cells seen on the lab-frame rows (mapToLab): linear between cell
// centres, the outermost cells' values out to the layer's edges, nothing outside the layer,
// T = m theta, the plate's velocity added to the cells' own.
#include <gtest/gtest.h>

#include <cmath>

#include "studies/hydro_run/LabFrame.hpp"

namespace granwave {

TEST(LabFrame, PlateFrameCellsMapLinearlyOntoTheLabRowsInsideTheLayerOnly) {
  hydro::HydroPhase ph;
  ph.plate_height = 0.0005;
  ph.layer_bottom = 0;
  ph.layer_top = 0.006;
  ph.z = {0.001, 0.003, 0.005};  // cell centres above the plate, m
  ph.area_fraction = {0.6, 0.5, 0.4};
  ph.theta = {1.0, 2.0, 3.0};
  ph.u = {0.1, 0.2, 0.3};
  // Rows of d = 2 mm from -A = -1 mm: centres at 0, 2, 4, 6, 8, 10 mm, i.e. z' = z - 0.5 mm.
  const FieldGrid grid = FieldGrid::forContainer(0.004, 0.01, 0.001, 0.002);
  ASSERT_EQ(grid.nz, 6);
  const double mass = 2.0, plate_velocity = 0.05;
  std::vector<double> nu, T, uz;
  mapToLab(ph, 0.01, grid, plate_velocity, mass, nu, T, uz);
  ASSERT_EQ(nu.size(), 6u);
  // z' = -0.5 mm: below the plate, no particles.
  EXPECT_EQ(nu[0], 0.0);
  EXPECT_TRUE(std::isnan(T[0]) && std::isnan(uz[0]));
  // z' = 1.5 mm: a quarter of the way from the first cell centre to the second.
  EXPECT_NEAR(nu[1], 0.575, 1e-12);
  EXPECT_NEAR(T[1], mass * 1.25, 1e-12);
  EXPECT_NEAR(uz[1], 0.125 + plate_velocity, 1e-12);
  EXPECT_NEAR(nu[2], 0.475, 1e-12);
  // z' = 5.5 mm: above the last centre but inside the layer, the last cell's values.
  EXPECT_NEAR(nu[3], 0.4, 1e-12);
  EXPECT_NEAR(T[3], mass * 3.0, 1e-12);
  // z' = 7.5 and 9.5 mm: above the layer's top.
  for (int j : {4, 5}) {
    EXPECT_EQ(nu[static_cast<std::size_t>(j)], 0.0);
    EXPECT_TRUE(std::isnan(T[static_cast<std::size_t>(j)]));
  }
}

}  // namespace granwave
