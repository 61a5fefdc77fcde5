// The layer's surface from its coarse-grained area fraction (coarse_grain/LayerSurface.hpp),
// on synthetic particle surfaces of known shape: triangular packings cut at a flat or a
// sinusoidal height, with and without grains flying above them. Expected values are the
// geometry of the packing; tolerances are derived in each test.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "coarse_grain/LayerSurface.hpp"
#include "coarse_grain/SurfaceProfile.hpp"
#include "coarse_grain/SurfaceWaveDetector.hpp"

namespace granwave {
namespace {

constexpr double d = 0.002;                  // paper, Table I
const double kRow = std::sqrt(3.0) / 2 * d;  // row spacing of a triangular packing

// A triangular packing on a plate at `plate`: rows j = 0, 1, ... with centres at
// plate + d/2 + j kRow (odd rows shifted by d/2), every disk kept whose top lies below
// plate + top(x). Columns of width d over `width`.
template <class Top>
Snapshot packing(double width, double plate, Top top) {
  Snapshot s;
  s.plate_height = plate;
  const int per_row = static_cast<int>(std::lround(width / d));
  for (int j = 0; j < 200; ++j) {
    const double z = 0.5 * d + j * kRow;
    bool any = false;
    for (int i = 0; i < per_row; ++i) {
      const double x = (i + 0.5 * (j % 2) + 0.25) * d;
      if (z + 0.5 * d > top(x)) continue;
      s.x.push_back(x);
      s.z.push_back(plate + z);
      any = true;
    }
    if (!any && z > 100 * d) break;
  }
  return s;
}

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return s / static_cast<double>(v.size());
}

}  // namespace

TEST(LayerSurface, FlatPackingEndsHalfARowAboveItsTopCentres) {
  // Eight rows: top centres at d/2 + 7 kRow. The disk centres' point density falls to half
  // its bulk value half a row spacing above them, (sqrt 3 / 4) d = 0.433 d (header). The
  // Gaussian kernel (s = d/2) resolves the rows only by exp(-2 pi^2 s^2 / kRow^2) = 1e-3 of
  // their density, and linear interpolation between bins of d/4 on the erf-shaped edge errs
  // by at most (dz)^2 / (8 sqrt(2 pi) s^2 / s) ~ 0.01 d: every column within 0.03 d.
  const double width = 60 * d;
  const Snapshot s = packing(width, 0.0031, [](double) { return 0.5 * d + 7 * kRow + 0.6 * d; });
  const LayerSurface surf = layerSurface(s, width, d, true);
  const double expected = 0.5 * d + 7 * kRow + 0.25 * std::sqrt(3.0) * d;
  ASSERT_EQ(surf.profile.columns(), 60);
  EXPECT_EQ(surf.thin_columns, 0);
  // A triangular packing of disks covers pi / (2 sqrt 3) = 0.9069 of the plane.
  EXPECT_NEAR(surf.bulk_area_fraction, std::numbers::pi / (2 * std::sqrt(3.0)), 0.01);
  for (int i = 0; i < 60; ++i) EXPECT_NEAR(surf.profile.height[i], expected, 0.03 * d) << i;
}

TEST(LayerSurface, SinusoidalSurfaceGivesItsModeAmplitudeAndWavelength) {
  // Cut at h(x) = 6 d + 2 d cos(2 pi x / 40 d) in a periodic box of 120 d: mode 3. Each
  // column's top row lies 0 to kRow below the cut's best row, an error uniform over a row
  // (sigma = kRow / sqrt 12 = 0.25 d) if it is uncorrelated with the wave, so the mode's
  // amplitude carries sigma sqrt(2 / 120) = 0.032 d of it; the kernel smooths the wave by
  // exp(-k^2 s^2 / 2) = 0.997. Expected 2 d within 3 x 0.032 d = 0.1 d.
  const double width = 120 * d, amplitude = 2 * d;
  const double k = 2 * std::numbers::pi / (40 * d);
  const Snapshot s =
      packing(width, -0.004, [&](double x) { return 6 * d + amplitude * std::cos(k * x); });
  const LayerSurface surf = layerSurface(s, width, d, true);
  const SurfaceSpectrum sp = surfaceSpectrum(surf.profile);
  EXPECT_EQ(sp.dominant_mode, 3);
  EXPECT_DOUBLE_EQ(sp.wavelength_d, 40.0);
  EXPECT_NEAR(sp.amplitude_d, 2.0 * std::exp(-0.5 * k * k * 0.25 * d * d), 0.1);
  // The crest sits at x = 0: the mode's phase (refered to x = 0) is 0 within the amplitude's
  // relative error, 0.1 / 2 rad.
  EXPECT_NEAR(std::arg(sp.mode[3]), 0.0, 0.05);
}

TEST(LayerSurface, GrainsFlyingAboveTheLayerDoNotMoveItsSurface) {
  // The same sinusoidal layer with 20 grains flying 3-10 d above it (2 % of the layer, a
  // saltating gas). A flyer 3 d up leaves a gap of 2 d where the layer's and the flyer's
  // kernels add to phi below 0.01, far below the half-bulk level 0.45: the crossing stops
  // at the layer. The top particle of the flyer's column (SurfaceProfile) jumps instead.
  const double width = 120 * d, k = 2 * std::numbers::pi / (40 * d);
  const auto top = [&](double x) { return 6 * d + 2 * d * std::cos(k * x); };
  const Snapshot layer = packing(width, 0.0, top);
  Snapshot with_flyers = layer;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> ux(0.0, width), uz(3 * d, 10 * d);
  for (int n = 0; n < 20; ++n) {
    const double x = ux(rng);
    with_flyers.x.push_back(x);
    with_flyers.z.push_back(top(x) + uz(rng));
  }
  const LayerSurface clean = layerSurface(layer, width, d, true);
  const LayerSurface noisy = layerSurface(with_flyers, width, d, true);
  const SurfaceProfile top_clean = surfaceProfile(layer, width, d, true);
  const SurfaceProfile top_noisy = surfaceProfile(with_flyers, width, d, true);
  double worst_layer = 0, worst_top = 0;
  for (int i = 0; i < 120; ++i) {
    worst_layer =
        std::max(worst_layer, std::abs(noisy.profile.height[i] - clean.profile.height[i]));
    worst_top = std::max(worst_top, std::abs(top_noisy.height[i] - top_clean.height[i]));
  }
  EXPECT_LT(worst_layer, 0.01 * d);
  EXPECT_GT(worst_top, 3 * d);  // the definition not chosen, for the record
  EXPECT_NEAR(surfaceSpectrum(noisy.profile).amplitude_d,
              surfaceSpectrum(clean.profile).amplitude_d, 0.01);
}

TEST(LayerSurface, ColumnsAtSideWallsKeepTheWholeDiskArea) {
  // A square packing between walls (5 rows of 30 disks at x = (i + 1/2) d, z = (j + 1/2) d):
  // the kernel's mass beyond a wall is mirrored back, and the mirror image of this packing is
  // its own continuation, so every column, the end ones too, has the bulk value and
  // ends half a row above the top centres, 5 d, within the 0.03 d of the flat test.
  Snapshot s;
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 30; ++i) {
      s.x.push_back((i + 0.5) * d);
      s.z.push_back((j + 0.5) * d);
    }
  const LayerSurface surf = layerSurface(s, 30 * d, d, false);
  // Rows one d apart seen through the kernel: a density modulated by 2 exp(-2 pi^2 s^2 / d^2)
  // = 2 exp(-pi^2 / 2) of its mean pi / 4, whose maximum is the bulk value.
  EXPECT_NEAR(surf.bulk_area_fraction,
              std::numbers::pi / 4 * (1 + 2 * std::exp(-std::numbers::pi * std::numbers::pi / 2)),
              0.002);
  for (int i = 0; i < 30; ++i) EXPECT_NEAR(surf.profile.height[i], 5 * d, 0.03 * d) << i;
}

TEST(LayerSurface, EmptyColumnsOfADeepTroughHaveNoLayer) {
  // A layer with a gap of 10 empty columns in the middle: those columns never reach half the
  // bulk value (the nearest disks are 5 d away), so h = 0 there and they are counted.
  const double width = 40 * d;
  Snapshot s = packing(width, 0.0, [](double x) {
    return (x > 15 * d && x < 25 * d) ? 0.0 : 0.5 * d + 3 * kRow + 0.6 * d;
  });
  const LayerSurface surf = layerSurface(s, width, d, true);
  EXPECT_GE(surf.thin_columns, 8);
  EXPECT_DOUBLE_EQ(surf.profile.height[20], 0.0);
  EXPECT_GT(mean(surf.profile.height), 2 * d);
}

TEST(LayerSurface, NoParticlesGiveZeroHeightAndBadInputIsRefused) {
  Snapshot empty;
  const LayerSurface surf = layerSurface(empty, 10 * d, d, false);
  EXPECT_EQ(surf.thin_columns, 10);
  for (double h : surf.profile.height) EXPECT_EQ(h, 0.0);
  EXPECT_THROW(layerSurface(empty, 0.0, d, false), std::invalid_argument);
  LayerSurfaceOptions bad;
  bad.fraction = 1.0;
  EXPECT_THROW(layerSurface(empty, 10 * d, d, false, bad), std::invalid_argument);
  Snapshot ragged;
  ragged.x = {d};
  EXPECT_THROW(layerSurface(ragged, 10 * d, d, false), std::invalid_argument);
}

}  // namespace granwave
