// The space-time spectrum of a surface h(x, t) (coarse_grain/SurfaceWaveSpectrum.hpp) on
// synthetic surfaces of known waves, the surface recorder on snapshots (and through a
// checkpoint), and the /surface group of the fields file.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "coarse_grain/SurfaceRecorder.hpp"
#include "coarse_grain/SurfaceWaveSpectrum.hpp"
#include "coarse_grain/SurfaceWavesFile.hpp"
#include "h5/AtomicFile.hpp"
#include "h5/File.hpp"
#include "tests/h5/ScratchDir.hpp"

namespace granwave {
namespace {

constexpr double d = 0.002;
constexpr int kM = 20;  // phases per cycle
const double kPi = std::numbers::pi;

// h(x_i, c, phi) = 5 d + shape(x_i, c, phi) on n columns of width d, `cycles` cycles.
template <class Shape>
SurfaceSeries series(int n, bool periodic, int cycles, Shape shape) {
  SurfaceSeries s;
  s.columns = n;
  s.records_per_cycle = kM;
  s.cycles = cycles;
  s.column_width = d;
  s.diameter = d;
  s.periodic_x = periodic;
  for (int c = 0; c < cycles; ++c)
    for (int phi = 0; phi < kM; ++phi) {
      for (int i = 0; i < n; ++i) s.height.push_back(5 * d + shape((i + 0.5) * d, c, phi));
      s.bulk_area_fraction.push_back(0.8);
    }
  return s;
}

// A recorder of 4 records per cycle over 10 columns of width d, keeping `keep` cycles.
SurfaceRecorderConfig recorderConfig(int keep, bool periodic) {
  SurfaceRecorderConfig cfg;
  cfg.records_per_cycle = 4;
  cfg.keep_cycles = keep;
  cfg.width = 10 * d;
  cfg.diameter = d;
  cfg.periodic_x = periodic;
  return cfg;
}

}  // namespace

TEST(SurfaceWaveSpectrum, StandingSubharmonicWaveGivesItsModeAmplitudeAndFullShare) {
  // h = A cos(pi m x / L) cos(pi t / T): a standing f/2 wave in mode m = 4 of a walled box of
  // 60 d (lambda = 2 L / m = 30 d). Its cycle-alternating part d(phi) = A cos(pi phi / M)
  // has the mean square A^2 / 2 over the M phases (amplitude sqrt(2 P) = A) and its crest A
  // at phi = 0; nothing is harmonic; the neighbours hold no power, so the wavenumber is mode
  // 4's exactly.
  const double A = 1.5 * d, L = 60 * d;
  const SurfaceSeries s = series(60, false, 40, [&](double x, int c, int phi) {
    return A * std::cos(kPi * 4 * x / L) * std::cos(kPi * (c + phi / double(kM)));
  });
  const SurfaceWaveAnalysis a = analyseSurfaceWaves(s);
  ASSERT_TRUE(a.available);
  ASSERT_EQ(a.windows.size(), 4u);
  EXPECT_EQ(a.standing_mode, 4);
  EXPECT_NEAR(a.wavelength_d, 30.0, 1e-9);
  EXPECT_NEAR(a.amplitude_d, 1.5, 1e-9);
  EXPECT_NEAR(a.subharmonic_share, 1.0, 1e-9);
  EXPECT_DOUBLE_EQ(a.wave_fraction, 1.0);
  EXPECT_EQ(a.waveWindows(), 4);
  EXPECT_TRUE(pooledWindowsWave(a.waveWindows(), static_cast<int>(a.windows.size())));
  EXPECT_NEAR(a.amplitude_error_d, 0.0, 1e-9);
  EXPECT_NEAR(a.windows[0].crest_d, 1.5, 1e-9);
  // The temporal spectrum of the mode: all power in the f/2 family (bins of f / W = f / 10:
  // f/2 at bin 5); a pure cos(pi t / T) puts A^2 / 2 there.
  EXPECT_NEAR(a.temporal_power[5], 0.5 * A * A, 1e-12);
  EXPECT_NEAR(a.temporal_power[10], 0.0, 1e-15);
}

TEST(SurfaceWaveSpectrum, HarmonicWaveIsLockedButNotSubharmonic) {
  // h = A cos(2 pi x / lambda) sin(2 pi t / T) in a periodic box of 64 d, lambda = 16 d (mode
  // 4): repeats every cycle. Share 0; the f/2 mode holds no power, so no wave.
  const double A = 2 * d;
  const SurfaceSeries s = series(64, true, 20, [&](double x, int c, int phi) {
    return A * std::cos(2 * kPi * x / (16 * d)) * std::sin(2 * kPi * (c + phi / double(kM)));
  });
  const SurfaceWaveAnalysis a = analyseSurfaceWaves(s);
  ASSERT_TRUE(a.available);
  for (const SurfaceWindow& w : a.windows) {
    EXPECT_EQ(w.dominant_mode, 4);
    EXPECT_NEAR(w.subharmonic_share, 0.0, 1e-12);
    EXPECT_NEAR(w.harmonic_amplitude_d, 2.0, 1e-9);
    EXPECT_FALSE(w.wave);
  }
}

TEST(SurfaceWaveSpectrum, WhiteNoiseHasTheNoiseFloorOfItsVarianceAndNoWave) {
  // Independent roughness sigma = 0.3 d per column and record, walls, n = 60 columns. A DCT
  // mode carries (2/n)^2 (n/2) sigma^2 = 2 sigma^2 / n of it, and the window's alternating
  // mean over W = 10 cycles 1/W of that: noise floor sigma sqrt(2 / (n W)) = 0.0548 d. The
  // estimate pools 20 phases x 8 residual degrees of freedom per window and 8 windows (1280),
  // so it is within 3 / sqrt(2 x 1280) = 6 % of it.
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 0.3 * d);
  const SurfaceSeries s = series(60, false, 80, [&](double, int, int) { return noise(rng); });
  const SurfaceWaveAnalysis a = analyseSurfaceWaves(s);
  ASSERT_TRUE(a.available);
  EXPECT_NEAR(a.noise_d, 0.3 * std::sqrt(2.0 / 600.0), 0.06 * 0.3 * std::sqrt(2.0 / 600.0));
  EXPECT_DOUBLE_EQ(a.wave_fraction, 0.0);
  EXPECT_EQ(a.waveWindows(), 0);
  EXPECT_FALSE(pooledWindowsWave(a.waveWindows(), static_cast<int>(a.windows.size())));
  EXPECT_FALSE(pooledWindowsWave(0, 0));  // no windows: nothing measured, no wave
  EXPECT_LT(a.amplitude_d, 0.5);
}

TEST(SurfaceWaveSpectrum, NoisyWaveKeepsItsAmplitudeWithinTheNoise) {
  // A periodic f/2 wave of 1 d in mode 5 of 100 d (lambda 20 d), anywhere in x (phase 1 rad),
  // under roughness of 0.5 d. A complex mode carries 4 sigma^2 / n of it (noise floor
  // 2 x 0.5 / sqrt(100 x 10) = 0.032 d); with the noise power removed, sqrt(2 P_sub) scatters
  // by about that over the 20 phases: 1 d within 3 x 0.032 d and 3 standard errors.
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 0.5 * d);
  const SurfaceSeries s = series(100, true, 60, [&](double x, int c, int phi) {
    return d * std::cos(2 * kPi * 5 * x / (100 * d) + 1.0) *
               std::cos(kPi * (c + phi / double(kM))) +
           noise(rng);
  });
  const SurfaceWaveAnalysis a = analyseSurfaceWaves(s);
  EXPECT_EQ(a.standing_mode, 5);
  EXPECT_NEAR(a.noise_d, 2 * 0.5 / std::sqrt(1000.0), 0.1 * 0.032);
  EXPECT_NEAR(a.amplitude_d, 1.0, 3 * 0.032 + 3 * a.amplitude_error_d);
  EXPECT_NEAR(a.wavelength_d, 20.0, 0.5);
  EXPECT_DOUBLE_EQ(a.wave_fraction, 1.0);
  EXPECT_GT(a.subharmonic_share, 0.95);
}

TEST(SurfaceWaveSpectrum, OddWindowIsRefusedAndTooShortARunIsNotAvailable) {
  const SurfaceSeries s = series(30, false, 6, [](double, int, int) { return 0.0; });
  SurfaceSpectrumOptions odd;
  odd.window_cycles = 3;
  EXPECT_THROW(analyseSurfaceWaves(s, odd), std::invalid_argument);
  EXPECT_FALSE(analyseSurfaceWaves(s).available);  // 6 cycles < one window of 10
}

TEST(SurfaceRecorder, KeepsWholeCyclesAndRestoresThroughACheckpoint) {
  // A flat layer of 3 rows whose plate moves: h stays the layer's thickness at every record.
  // The recorder saved after 7 cycles and restored into a new one records what one that saw
  // the whole run does.
  const SurfaceRecorderConfig cfg = recorderConfig(5, true);
  const auto snapshot = [&](std::uint64_t step) {
    Snapshot s;
    s.step = step;
    s.plate_height = 0.001 * std::sin(0.3 * static_cast<double>(step));
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 10; ++i) {
        s.x.push_back((i + 0.5 * (j % 2)) * d);
        s.z.push_back(s.plate_height + (0.5 + 0.866 * j) * d);
      }
    return s;
  };
  SurfaceRecorder whole(cfg), first(cfg), second(cfg);
  testing::ScratchDir dir;
  for (std::uint64_t k = 0; k < 41; ++k) {
    whole.observe(snapshot(k));
    if (k < 28) first.observe(snapshot(k));
    if (k == 27) {
      h5::File f = h5::File::create(dir.file("state.h5"));
      first.saveState(f, "/surface");
      f.close();
      const h5::File r = h5::File::openReadOnly(dir.file("state.h5"));
      second.restoreState(r, "/surface");
    }
    if (k >= 28) second.observe(snapshot(k));
  }
  const SurfaceSeries a = whole.series(), b = second.series();
  EXPECT_EQ(a.cycles, 5);  // cycles 5-9 whole; cycle 10 has one record
  EXPECT_EQ(a.first_cycle, 5);
  EXPECT_EQ(a.height, b.height);
  // The same layer at every record, up to the kernel's truncation at 3 s (its tails hold 0.3 %
  // of a disk's weight, and which side is cut depends on round-off of x / w at a column edge).
  for (double h : a.height) EXPECT_NEAR(h, a.height.front(), 1e-4 * d);
  EXPECT_EQ(whole.series(8).cycles, 2);
}

TEST(SurfaceRecorder, SurfacesMeasuredElsewhereAreKeptInPhaseOrderAndMustFitTheRecorder) {
  // A continuum hands over its surfaces (record): a cycle's records in phase order make it
  // whole; a record of the wrong column count, or outside a cycle's records, is refused.
  SurfaceRecorder r(recorderConfig(3, false));
  LayerSurface flat;
  flat.profile.height.assign(10, 3 * d);
  for (long c = 0; c < 4; ++c)
    for (int phase = 0; phase < 4; ++phase)
      if (c != 1 || phase != 2) r.record(c, phase, flat);  // cycle 1 misses a record
  const SurfaceSeries s = r.series();
  EXPECT_EQ(s.cycles, 2);  // cycles 2 and 3: cycle 1 is partial and breaks the run
  EXPECT_EQ(s.first_cycle, 2);
  EXPECT_EQ(s.height.size(), 2u * 4 * 10);
  LayerSurface narrow;
  narrow.profile.height.assign(9, 3 * d);
  EXPECT_THROW(r.record(4, 0, narrow), std::invalid_argument);
  EXPECT_THROW(r.record(3, 4, flat), std::invalid_argument);   // records 0-3 of a cycle
  EXPECT_THROW(r.record(-1, 0, flat), std::invalid_argument);  // no cycle before the run
}

TEST(SurfaceWaveSpectrum, ShortRunsGetTheLargestEvenWindowThatFitsTwiceButAtLeastFour) {
  // 10 cycles when two windows of 10 fit; else the largest even window that fits twice, and
  // never below 4 (the noise has W - 2 degrees of freedom): under 8 cycles, one window.
  EXPECT_EQ(surfaceWindowCycles(30), 10);
  EXPECT_EQ(surfaceWindowCycles(20), 10);
  EXPECT_EQ(surfaceWindowCycles(19), 8);
  EXPECT_EQ(surfaceWindowCycles(8), 4);
  EXPECT_EQ(surfaceWindowCycles(5), 4);
}

TEST(SurfaceWavesFile, RoundTripKeepsTheAnalysis) {
  const double A = d, L = 40 * d;
  const SurfaceSeries s = series(40, false, 20, [&](double x, int c, int phi) {
    return A * std::cos(kPi * 2 * x / L) * std::cos(kPi * (c + phi / double(kM)));
  });
  const SurfaceWaveAnalysis a = analyseSurfaceWaves(s);
  testing::ScratchDir dir;
  {
    h5::AtomicFile af(dir.file("fields.h5"));
    writeSurfaceWaves(af.file(), a);
    af.commit();
  }
  const SurfaceWaveAnalysis b = readSurfaceWaves(dir.file("fields.h5"));
  ASSERT_TRUE(b.available);
  EXPECT_EQ(b.windows.size(), a.windows.size());
  EXPECT_EQ(b.standing_mode, 2);
  EXPECT_DOUBLE_EQ(b.amplitude_d, a.amplitude_d);
  EXPECT_DOUBLE_EQ(b.wavelength_d, a.wavelength_d);
  EXPECT_EQ(b.power_subharmonic, a.power_subharmonic);
  EXPECT_EQ(b.recent_height, a.recent_height);
  EXPECT_EQ(b.windows[1].wave, a.windows[1].wave);
}

}  // namespace granwave
