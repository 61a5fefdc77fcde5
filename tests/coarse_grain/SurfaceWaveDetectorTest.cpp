// Standing subharmonic surface waves (coarse_grain/SurfaceWaveDetector.hpp) on synthetic
// surfaces. Expected mode numbers, wavelengths and amplitudes are those put into the
// synthetic profile (a pure mode is reproduced to round-off); noise levels are compared with
// the noise floor 2 sigma / sqrt(N) of a mode of N independent columns.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <stdexcept>

#include "coarse_grain/SurfaceProfile.hpp"
#include "coarse_grain/SurfaceWaveDetector.hpp"

using granwave::detectStandingWave;
using granwave::Snapshot;
using granwave::SurfaceProfile;
using granwave::surfaceSpectrum;
using granwave::SurfaceWaveResult;

namespace {

constexpr double d = 0.002;  // paper, Table I
constexpr double pi = std::numbers::pi;
constexpr int N = 30;  // L_x = 30 d (paper, Table I)
constexpr double L = N * d;

// Profile with h(x_i) = f(x_i) at column centres x_i = (i + 1/2) d.
SurfaceProfile profile(bool periodic, const std::function<double(double)>& f) {
  SurfaceProfile p;
  p.column_width = d;
  p.diameter = d;
  p.periodic_x = periodic;
  for (int i = 0; i < N; ++i) p.height.push_back(f((i + 0.5) * d));
  return p;
}

// Deterministic standard normal numbers (fixed seed; Box-Muller on the raw engine output so
// the values do not depend on the standard library's distributions).
class Gauss {
 public:
  explicit Gauss(std::uint64_t seed) : rng_(seed) {}
  double operator()() {
    const double u1 = ((rng_() >> 11) + 0.5) * 0x1.0p-53, u2 = (rng_() >> 11) * 0x1.0p-53;
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * pi * u2);
  }

 private:
  std::mt19937_64 rng_;
};

// K cycles of a mode-m wave with amplitude A, sign sign_per_cycle^c, plus grain noise sigma.
std::vector<SurfaceProfile> cycles(bool periodic, int m, double A, double sign_per_cycle,
                                   double sigma, int K, std::uint64_t seed = 7) {
  Gauss g(seed);
  std::vector<SurfaceProfile> out;
  double sign = 1;
  for (int c = 0; c < K; ++c, sign *= sign_per_cycle) {
    const double k = periodic ? 2.0 * pi * m / L : pi * m / L;
    out.push_back(profile(periodic, [&](double x) {
      return 8.0 * d + sign * A * std::cos(k * x + (periodic ? 0.4 : 0.0)) + sigma * d * g();
    }));
  }
  return out;
}

}  // namespace

TEST(SurfaceSpectrum, WallModeIsACosineWithZeroSlopeAtTheWalls) {
  // h = 8 d + 1.3 d cos(3 pi x / L): mode 3, three half wavelengths, lambda = 2 L / 3 = 20 d.
  const auto p =
      profile(false, [](double x) { return 8 * d + 1.3 * d * std::cos(3 * pi * x / L); });
  const auto s = surfaceSpectrum(p);
  EXPECT_EQ(s.dominant_mode, 3);
  EXPECT_NEAR(s.amplitude_d, 1.3, 1e-12);
  EXPECT_NEAR(s.wavelength_d, 20.0, 1e-12);
  EXPECT_NEAR(s.mean_height, 8 * d, 1e-15);
  for (int m = 1; m < N; ++m) {
    if (m == 3) continue;
    EXPECT_NEAR(std::abs(s.mode[m]), 0.0, 1e-15) << "mode " << m;
  }
}

TEST(SurfaceSpectrum, PeriodicModeKeepsAmplitudeAndPhase) {
  // h = 8 d + 0.8 d cos(2 pi 4 x / L + 0.7): mode 4, lambda = L / 4 = 7.5 d, and the phase
  // of a_4 (referred to column centres) is 0.7.
  const auto p =
      profile(true, [](double x) { return 8 * d + 0.8 * d * std::cos(2 * pi * 4 * x / L + 0.7); });
  const auto s = surfaceSpectrum(p);
  EXPECT_EQ(s.dominant_mode, 4);
  EXPECT_NEAR(s.amplitude_d, 0.8, 1e-12);
  EXPECT_NEAR(s.wavelength_d, 7.5, 1e-12);
  EXPECT_NEAR(std::arg(s.mode[4]), 0.7, 1e-12);
}

TEST(SurfaceSpectrum, LargerOfTwoModesDominates) {
  const auto p = profile(false, [](double x) {
    return 5 * d + 0.6 * d * std::cos(2 * pi * x / L) + 0.9 * d * std::cos(5 * pi * x / L);
  });
  const auto s = surfaceSpectrum(p);
  EXPECT_EQ(s.dominant_mode, 5);
  EXPECT_NEAR(s.amplitude_d, 0.9, 1e-12);
  EXPECT_NEAR(std::abs(s.mode[2]) / d, 0.6, 1e-12);
}

TEST(SurfaceSpectrum, GrainScaleRoughnessIsNotAWave) {
  // Alternating columns (+-1 d, lambda = 2 d, the sampling limit) are below
  // min_wavelength = 4 d; the weaker long mode 2 (lambda = 30 d) is the dominant wave.
  const auto p = profile(true, [](double x) {
    const int i = static_cast<int>(x / d);
    return 5 * d + (i % 2 == 0 ? 1.0 : -1.0) * d + 0.3 * d * std::cos(2 * pi * 2 * x / L);
  });
  const auto s = surfaceSpectrum(p);
  EXPECT_NEAR(std::abs(s.mode[N / 2]) / d, 1.0, 1e-12);  // present in the spectrum
  EXPECT_EQ(s.dominant_mode, 2);
  EXPECT_NEAR(s.amplitude_d, 0.3, 1e-12);
}

TEST(SurfaceSpectrum, FlatSurfaceHasNoDominantMode) {
  const auto s = surfaceSpectrum(profile(false, [](double) { return 4 * d; }));
  EXPECT_EQ(s.dominant_mode, 0);
  EXPECT_EQ(s.amplitude_d, 0.0);
}

TEST(StandingWave, AlternatingSinusoidIsDetectedWithItsModeAndAmplitude) {
  // Mode 2 with walls (lambda = L = 30 d), A = 1.5 d, sign flipping every cycle (f/2), grain
  // noise 0.05 d per column: amplitude 1.5 d within the noise floor 2 * 0.05 / sqrt(30).
  const SurfaceWaveResult r = detectStandingWave(cycles(false, 2, 1.5 * d, -1.0, 0.05, 12));
  EXPECT_TRUE(r.detected);
  EXPECT_EQ(r.mode, 2);
  EXPECT_NEAR(r.wavelength_d, 30.0, 1e-12);
  EXPECT_NEAR(r.amplitude_d, 1.5, 0.03);
  EXPECT_NEAR(r.subharmonic_amplitude_d, 1.5, 0.03);
  EXPECT_DOUBLE_EQ(r.alternation_fraction, 1.0);
  EXPECT_EQ(r.cycles, 12);
}

TEST(StandingWave, PeriodicStandingWaveAtAnyPositionIsDetected) {
  // Periodic box, mode 3 (lambda = 10 d) with its nodes shifted by a phase 0.4.
  const SurfaceWaveResult r = detectStandingWave(cycles(true, 3, 0.8 * d, -1.0, 0.05, 10));
  EXPECT_TRUE(r.detected);
  EXPECT_EQ(r.mode, 3);
  EXPECT_NEAR(r.wavelength_d, 10.0, 1e-12);
  EXPECT_NEAR(r.amplitude_d, 0.8, 0.03);
  EXPECT_DOUBLE_EQ(r.alternation_fraction, 1.0);
}

TEST(StandingWave, FlatNoisySurfaceIsNotAWave) {
  // Roughness sigma = 0.3 d per column, 20 cycles: each mode holds noise of rms amplitude
  // 2 sigma / sqrt(N) = 0.11 d; the largest of 14 admitted modes stays well below 0.5 d and
  // its sign flips at random (alternation about 1/2).
  const SurfaceWaveResult r = detectStandingWave(cycles(false, 1, 0.0, 1.0, 0.3, 20));
  EXPECT_FALSE(r.detected);
  EXPECT_LT(r.amplitude_d, 0.25);
  EXPECT_GT(r.alternation_fraction, 0.2);
  EXPECT_LT(r.alternation_fraction, 0.8);
  EXPECT_LT(r.subharmonic_amplitude_d, 0.1);  // f/2 part: noise / sqrt(K)
}

TEST(StandingWave, SinusoidRepeatingEveryCycleIsNotSubharmonic) {
  // A large mode (harmonic response, same sign each cycle): amplitude above threshold but no
  // sign alternation, so not a standing subharmonic wave.
  const SurfaceWaveResult r = detectStandingWave(cycles(false, 2, 1.5 * d, 1.0, 0.05, 12));
  EXPECT_FALSE(r.detected);
  EXPECT_EQ(r.mode, 2);
  EXPECT_NEAR(r.amplitude_d, 1.5, 0.03);
  EXPECT_DOUBLE_EQ(r.alternation_fraction, 0.0);
  EXPECT_LT(r.subharmonic_amplitude_d, 0.05);  // equal cycles cancel in <(-1)^c a(c)>
}

TEST(StandingWave, WeakAlternatingRippleIsBelowTheAmplitudeThreshold) {
  const SurfaceWaveResult r = detectStandingWave(cycles(false, 2, 0.3 * d, -1.0, 0.02, 12));
  EXPECT_FALSE(r.detected);
  EXPECT_DOUBLE_EQ(r.alternation_fraction, 1.0);
  EXPECT_NEAR(r.amplitude_d, 0.3, 0.02);
}

TEST(StandingWave, DetectedFromParticleSnapshots) {
  // End to end: one particle per column whose top follows 6 d + (-1)^c 1 d cos(2 pi x / L)
  // above a plate that is at a different height in each cycle (the plate is subtracted).
  std::vector<SurfaceProfile> profiles;
  for (int c = 0; c < 8; ++c) {
    Snapshot s;
    s.plate_height = 0.001 * c;
    const double sign = c % 2 == 0 ? 1.0 : -1.0;
    for (int i = 0; i < N; ++i) {
      const double x = (i + 0.5) * d;
      s.x.push_back(x);
      s.z.push_back(s.plate_height + 5.5 * d + sign * d * std::cos(2 * pi * x / L));
    }
    profiles.push_back(granwave::surfaceProfile(s, L, d, false));
  }
  const SurfaceWaveResult r = detectStandingWave(profiles);
  EXPECT_TRUE(r.detected);
  EXPECT_EQ(r.mode, 2);  // one full wavelength between walls = two half wavelengths
  EXPECT_NEAR(r.amplitude_d, 1.0, 1e-12);
}

TEST(StandingWave, RejectsTooFewOrMismatchedProfiles) {
  const auto one = cycles(false, 2, d, -1.0, 0.0, 1);
  EXPECT_THROW(detectStandingWave(one), std::invalid_argument);
  auto two = cycles(false, 2, d, -1.0, 0.0, 2);
  two[1].periodic_x = true;
  EXPECT_THROW(detectStandingWave(two), std::invalid_argument);
}
