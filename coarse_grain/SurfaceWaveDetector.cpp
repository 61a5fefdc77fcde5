#include "coarse_grain/SurfaceWaveDetector.hpp"

#include <fftw3.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace granwave {

namespace {

void checkProfile(const SurfaceProfile& p) {
  if (p.columns() < 2)
    throw std::invalid_argument("surface spectrum needs at least 2 columns, got " +
                                std::to_string(p.columns()));
  if (!(p.diameter > 0) || !(p.column_width > 0))
    throw std::invalid_argument(
        "surface spectrum: profile has no positive diameter or column width (build it with "
        "surfaceProfile)");
}

// Mode coefficients a_m (see the header) of the mean-removed profile. FFTW_ESTIMATE plans
// do not measure timings, so the result is deterministic.
std::vector<std::complex<double>> modeCoefficients(const SurfaceProfile& p, double mean) {
  const int n = p.columns();
  std::vector<double> x(p.height);
  for (double& v : x) v -= mean;
  if (!p.periodic_x) {
    // DCT-II: Y_m = 2 sum_j x_j cos(pi m (j + 1/2) / n); a pure mode of amplitude A gives
    // Y_m = A n.
    std::vector<double> y(n);
    fftw_plan plan = fftw_plan_r2r_1d(n, x.data(), y.data(), FFTW_REDFT10, FFTW_ESTIMATE);
    fftw_execute(plan);
    fftw_destroy_plan(plan);
    std::vector<std::complex<double>> a(n);
    for (int m = 1; m < n; ++m) a[m] = y[m] / n;
    return a;
  }
  // DFT: Y_m = sum_j x_j exp(-2 pi i j m / n); a pure mode of amplitude A gives |Y_m| = A n/2
  // (A n at the Nyquist mode m = n/2). The factor exp(-i pi m / n) refers the phase to the
  // column centres x_j = (j + 1/2) w instead of the column edges.
  std::vector<std::complex<double>> y(n / 2 + 1);
  fftw_plan plan =
      fftw_plan_dft_r2c_1d(n, x.data(), reinterpret_cast<fftw_complex*>(y.data()), FFTW_ESTIMATE);
  fftw_execute(plan);
  fftw_destroy_plan(plan);
  std::vector<std::complex<double>> a(n / 2 + 1);
  for (int m = 1; m <= n / 2; ++m) {
    const double norm = (2 * m == n) ? 1.0 / n : 2.0 / n;
    a[m] = norm * y[m] * std::polar(1.0, -std::numbers::pi * m / n);
  }
  return a;
}

double meanOf(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return s / static_cast<double>(v.size());
}

// Largest mode number whose wavelength is at least min_wavelength d.
int highestAdmittedMode(const SurfaceProfile& p, int top, double min_wavelength) {
  int m = 0;
  while (m + 1 <= top && modeWavelength(p, m + 1) >= min_wavelength - 1e-12) ++m;
  return m;
}

}  // namespace

double modeWavelength(const SurfaceProfile& p, int m) {
  const double span = p.periodic_x ? p.width() : 2.0 * p.width();
  return span / m / p.diameter;
}

SurfaceSpectrum surfaceSpectrum(const SurfaceProfile& profile, const SurfaceWaveOptions& opt) {
  checkProfile(profile);
  SurfaceSpectrum s;
  s.mean_height = meanOf(profile.height);
  s.mode = modeCoefficients(profile, s.mean_height);
  const int top =
      highestAdmittedMode(profile, static_cast<int>(s.mode.size()) - 1, opt.min_wavelength);
  double best = 0;
  for (int m = 1; m <= top; ++m) {
    if (std::abs(s.mode[m]) > best) {
      best = std::abs(s.mode[m]);
      s.dominant_mode = m;
    }
  }
  if (s.dominant_mode > 0) {
    s.amplitude_d = best / profile.diameter;
    s.wavelength_d = modeWavelength(profile, s.dominant_mode);
  }
  return s;
}

SurfaceWaveResult detectStandingWave(const std::vector<SurfaceProfile>& cycles,
                                     const SurfaceWaveOptions& opt) {
  const int K = static_cast<int>(cycles.size());
  if (K < 2)
    throw std::invalid_argument(
        "standing-wave detection needs profiles from at least 2 consecutive cycles, got " +
        std::to_string(K));
  const SurfaceProfile& first = cycles.front();
  checkProfile(first);
  for (const SurfaceProfile& p : cycles) {
    if (p.columns() != first.columns() || p.periodic_x != first.periodic_x ||
        p.column_width != first.column_width || p.diameter != first.diameter)
      throw std::invalid_argument(
          "standing-wave detection: profiles differ in columns, width, diameter or boundary type");
  }

  std::vector<std::vector<std::complex<double>>> a;
  a.reserve(K);
  for (const SurfaceProfile& p : cycles) a.push_back(modeCoefficients(p, meanOf(p.height)));

  const int top =
      highestAdmittedMode(first, static_cast<int>(a.front().size()) - 1, opt.min_wavelength);
  SurfaceWaveResult r;
  r.cycles = K;
  double best = 0;
  for (int m = 1; m <= top; ++m) {
    double power = 0;
    for (int c = 0; c < K; ++c) power += std::norm(a[c][m]);
    if (power > best) {
      best = power;
      r.mode = m;
    }
  }
  if (r.mode == 0) return r;

  const int m = r.mode;
  r.wavelength_d = modeWavelength(first, m);
  r.amplitude_d = std::sqrt(best / K) / first.diameter;
  std::complex<double> alternating = 0;
  int flips = 0;
  for (int c = 0; c < K; ++c) {
    alternating += (c % 2 == 0 ? 1.0 : -1.0) * a[c][m];
    if (c + 1 < K && std::real(a[c + 1][m] * std::conj(a[c][m])) < 0) ++flips;
  }
  r.subharmonic_amplitude_d = std::abs(alternating) / K / first.diameter;
  r.alternation_fraction = static_cast<double>(flips) / (K - 1);
  r.detected =
      r.amplitude_d >= opt.amplitude_threshold && r.alternation_fraction >= opt.min_alternation;
  return r;
}

}  // namespace granwave
