#include "coarse_grain/SurfaceWaveSpectrum.hpp"

#include <fftw3.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>

#include "coarse_grain/SurfaceWaveDetector.hpp"

namespace granwave {

namespace {

using Complex = std::complex<double>;

// Mode coefficients a_m(c, phi) of a window, [(c M + phi) * modes + m], m = 0 .. modes - 1.
struct WindowModes {
  int W = 0, M = 0, modes = 0;
  std::vector<Complex> a;
  const Complex& at(int c, int phi, int m) const {
    return a[(static_cast<std::size_t>(c) * M + phi) * modes + m];
  }
};

SurfaceProfile profileOf(const SurfaceSeries& s, int c, int phi) {
  SurfaceProfile p;
  p.column_width = s.column_width;
  p.diameter = s.diameter;
  p.periodic_x = s.periodic_x;
  const auto first =
      s.height.begin() +
      static_cast<long>((static_cast<std::size_t>(c) * s.records_per_cycle + phi) * s.columns);
  p.height.assign(first, first + s.columns);
  return p;
}

WindowModes windowModes(const SurfaceSeries& s, int first, int W, int modes) {
  WindowModes w{W, s.records_per_cycle, modes, {}};
  w.a.resize(static_cast<std::size_t>(W) * w.M * modes);
  for (int c = 0; c < W; ++c)
    for (int phi = 0; phi < w.M; ++phi) {
      const SurfaceSpectrum sp = surfaceSpectrum(profileOf(s, first + c, phi));
      for (int m = 1; m < modes; ++m)
        w.a[(static_cast<std::size_t>(c) * w.M + phi) * modes + m] = sp.mode[m];
    }
  return w;
}

// The locked and unlocked parts of one mode over a window (see the header).
struct ModeParts {
  double p_sub = 0, p_harm = 0, broadband = 0, noise = 0;  // m^2, bias-corrected locked powers
  double amplitude = 0, harmonic_amplitude = 0;            // m
};

ModeParts modeParts(const WindowModes& w, int m) {
  ModeParts r;
  std::vector<Complex> d(w.M), s(w.M);
  Complex s0 = 0;
  for (int phi = 0; phi < w.M; ++phi) {
    for (int c = 0; c < w.W; ++c) {
      d[phi] += (c % 2 == 0 ? 1.0 : -1.0) * w.at(c, phi, m);
      s[phi] += w.at(c, phi, m);
    }
    d[phi] /= w.W;
    s[phi] /= w.W;
    s0 += s[phi];
  }
  s0 /= w.M;
  double sub = 0, harm = 0, resid = 0;
  for (int phi = 0; phi < w.M; ++phi) {
    sub += std::norm(d[phi]);
    harm += std::norm(s[phi] - s0);
    r.amplitude = std::max(r.amplitude, std::abs(d[phi]));
    r.harmonic_amplitude = std::max(r.harmonic_amplitude, std::abs(s[phi] - s0));
    for (int c = 0; c < w.W; ++c)
      resid += std::norm(w.at(c, phi, m) - (c % 2 == 0 ? 1.0 : -1.0) * d[phi] - s[phi]);
  }
  r.broadband = resid / (static_cast<double>(w.W) * w.M);
  r.noise = resid / (static_cast<double>(w.W - 2) * w.M) / w.W;
  r.p_sub = std::max(0.0, sub / w.M - r.noise);
  r.p_harm = std::max(0.0, harm / w.M - r.noise);
  return r;
}

double wavenumberOf(const SurfaceSeries& s, int m) {
  const double L = s.column_width * s.columns;
  return (s.periodic_x ? 2.0 : 1.0) * std::numbers::pi * m / L;
}

// Power spectrum |Y_j|^2 / L^2 of a_m over the window, j = 0 .. top (frequency j / W in f),
// positive and negative frequencies together.
std::vector<double> temporalPower(const WindowModes& w, int m, int top) {
  const int L = w.W * w.M;
  std::vector<Complex> in(L), out(L);
  for (int c = 0; c < w.W; ++c)
    for (int phi = 0; phi < w.M; ++phi) in[c * w.M + phi] = w.at(c, phi, m);
  fftw_plan plan =
      fftw_plan_dft_1d(L, reinterpret_cast<fftw_complex*>(in.data()),
                       reinterpret_cast<fftw_complex*>(out.data()), FFTW_FORWARD, FFTW_ESTIMATE);
  fftw_execute(plan);
  fftw_destroy_plan(plan);
  std::vector<double> p(top + 1);
  const double norm = 1.0 / (static_cast<double>(L) * L);
  for (int j = 0; j <= top && j < L; ++j)
    p[j] = norm * (std::norm(out[j]) + (j > 0 && j < L - j ? std::norm(out[L - j]) : 0.0));
  return p;
}

struct WindowResult {
  SurfaceWindow window;
  std::vector<ModeParts> parts;
  std::vector<double> temporal;
};

WindowResult analyseWindow(const SurfaceSeries& s, int first, const SurfaceSpectrumOptions& o,
                           int modes) {
  const WindowModes w = windowModes(s, first, o.window_cycles, modes);
  WindowResult r;
  r.parts.resize(modes);
  SurfaceWindow& win = r.window;
  win.first_cycle = s.first_cycle + first;
  double best_locked = -1, best_sub = -1;
  for (int m = 1; m < modes; ++m) {
    r.parts[m] = modeParts(w, m);
    const double locked = r.parts[m].p_sub + r.parts[m].p_harm;
    if (locked > best_locked) best_locked = locked, win.dominant_mode = m;
    if (r.parts[m].p_sub > best_sub) best_sub = r.parts[m].p_sub, win.standing_mode = m;
  }
  const ModeParts& dom = r.parts[win.dominant_mode];
  win.subharmonic_share = best_locked > 0 ? dom.p_sub / best_locked : NAN;
  const int ms = win.standing_mode;
  const ModeParts& st = r.parts[ms];
  win.amplitude_d = std::sqrt(2 * st.p_sub) / s.diameter;
  win.crest_d = st.amplitude / s.diameter;
  win.noise_d = std::sqrt(st.noise) / s.diameter;
  win.harmonic_amplitude_d = dom.harmonic_amplitude / s.diameter;
  double weight = 0, k = 0;
  for (int m = std::max(1, ms - 1); m <= std::min(modes - 1, ms + 1); ++m) {
    weight += r.parts[m].p_sub;
    k += r.parts[m].p_sub * wavenumberOf(s, m);
  }
  win.wavenumber = weight > 0 ? k / weight : wavenumberOf(s, ms);
  win.wavelength_d = 2 * std::numbers::pi / win.wavenumber / s.diameter;
  const double locked_ms = st.p_sub + st.p_harm;
  win.wave = win.amplitude_d >= o.amplitude_threshold &&
             win.amplitude_d >= o.noise_factor * win.noise_d && locked_ms > 0 &&
             st.p_sub >= 0.5 * locked_ms;
  r.temporal = temporalPower(w, win.dominant_mode, 3 * o.window_cycles);
  return r;
}

// Number of modes kept (0 .. modes - 1): the admitted wavelengths (>= min_wavelength).
int admittedModes(const SurfaceSeries& s, double min_wavelength) {
  SurfaceProfile p;
  p.column_width = s.column_width;
  p.diameter = s.diameter;
  p.periodic_x = s.periodic_x;
  p.height.assign(s.columns, 0.0);
  const int top = s.periodic_x ? s.columns / 2 : s.columns - 1;
  int m = 0;
  while (m + 1 <= top && modeWavelength(p, m + 1) >= min_wavelength - 1e-12) ++m;
  return m + 1;
}

// Mean and standard error of the finite values (error 0 for fewer than 2).
void meanError(const std::vector<double>& v, double& mean, double& error) {
  double sum = 0, sq = 0;
  int n = 0;
  for (double x : v)
    if (std::isfinite(x)) sum += x, sq += x * x, ++n;
  mean = n > 0 ? sum / n : NAN;
  error = n > 1 ? std::sqrt(std::max(0.0, (sq - sum * sum / n) / (n - 1)) / n) : 0.0;
}

// Window means of the standing-wave quantities, the averaged spectra and the mode counts.
void summarise(const std::vector<WindowResult>& windows, const SurfaceSeries& s,
               SurfaceWaveAnalysis& a) {
  const int modes = static_cast<int>(windows.front().parts.size());
  const double nw = static_cast<double>(windows.size());
  std::vector<double> amp, lambda, share;
  std::map<int, int> standing;
  a.mode_wavenumber.assign(modes, 0.0);
  a.power_subharmonic.assign(modes, 0.0);
  a.power_harmonic.assign(modes, 0.0);
  a.power_broadband.assign(modes, 0.0);
  a.temporal_power.assign(windows.front().temporal.size(), 0.0);
  for (const WindowResult& w : windows) {
    a.windows.push_back(w.window);
    amp.push_back(w.window.amplitude_d);
    lambda.push_back(w.window.wavelength_d);
    share.push_back(w.window.subharmonic_share);
    a.noise_d += w.window.noise_d / nw;
    ++standing[w.window.standing_mode];
    for (int m = 1; m < modes; ++m) {
      a.power_subharmonic[m] += w.parts[m].p_sub / nw;
      a.power_harmonic[m] += w.parts[m].p_harm / nw;
      a.power_broadband[m] += w.parts[m].broadband / nw;
    }
    for (std::size_t j = 0; j < w.temporal.size(); ++j) a.temporal_power[j] += w.temporal[j] / nw;
  }
  // Counted, not summed as 1 / nw per window: six sixths would sum to 0.9999999999999999.
  a.wave_fraction = a.waveWindows() / nw;
  for (int m = 0; m < modes; ++m) a.mode_wavenumber[m] = wavenumberOf(s, m);
  for (std::size_t j = 0; j < a.temporal_power.size(); ++j)
    a.frequency_over_f.push_back(static_cast<double>(j) / a.window_cycles);
  meanError(amp, a.amplitude_d, a.amplitude_error_d);
  meanError(lambda, a.wavelength_d, a.wavelength_error_d);
  meanError(share, a.subharmonic_share, a.subharmonic_share_error);
  int most = 0;
  for (const auto& [m, count] : standing)
    if (count > most) most = count, a.standing_mode = m;
}

}  // namespace

SurfaceWaveAnalysis analyseSurfaceWaves(const SurfaceSeries& s, const SurfaceSpectrumOptions& o) {
  if (o.window_cycles < 2 || o.window_cycles % 2 != 0)
    throw std::invalid_argument("surface spectrum: window_cycles must be even and >= 2, got " +
                                std::to_string(o.window_cycles));
  SurfaceWaveAnalysis a;
  a.columns = s.columns;
  a.records_per_cycle = s.records_per_cycle;
  a.window_cycles = o.window_cycles;
  a.cycles = s.cycles;
  a.periodic_x = s.periodic_x;
  a.width = s.column_width * s.columns;
  a.diameter = s.diameter;
  const int n_windows = s.cycles / o.window_cycles;
  if (n_windows < 1 || s.columns < 2) return a;
  const int modes = admittedModes(s, o.min_wavelength);
  if (modes < 2) return a;
  // The newest whole windows: the steady state is best established at the end.
  const int skip = s.cycles - n_windows * o.window_cycles;
  std::vector<WindowResult> windows;
  for (int w = 0; w < n_windows; ++w)
    windows.push_back(analyseWindow(s, skip + w * o.window_cycles, o, modes));
  a.available = true;
  summarise(windows, s, a);
  double bulk = 0;
  for (double b : s.bulk_area_fraction) bulk += b;
  a.mean_bulk_area_fraction = bulk / static_cast<double>(s.bulk_area_fraction.size());
  const int recent = std::min(o.figure_cycles, s.cycles) * s.records_per_cycle;
  a.recent_records = recent;
  a.recent_height.assign(s.height.end() - static_cast<long>(recent) * s.columns, s.height.end());
  return a;
}

int SurfaceWaveAnalysis::waveWindows() const {
  return static_cast<int>(
      std::count_if(windows.begin(), windows.end(), [](const SurfaceWindow& w) { return w.wave; }));
}

bool pooledWindowsWave(int wave_windows, int windows) {
  return windows > 0 && 2 * wave_windows >= windows;
}

int surfaceWindowCycles(int cycles, const SurfaceSpectrumOptions& o) {
  if (cycles >= 2 * o.window_cycles) return o.window_cycles;
  return std::max(4, cycles / 4 * 2);
}

std::string surfaceSpectrumLine(const SurfaceWaveAnalysis& s) {
  // The error is the spread over windows: with one window there is none to give.
  const bool spread = s.windows.size() >= 2;
  const auto pm = [&](double v, double e, int digits) {
    return spread ? fmt::format("{:.{}f} +- {:.{}f}", v, digits, e, digits)
                  : fmt::format("{:.{}f} +- n/a", v, digits);
  };
  return fmt::format(
      "surface spectrum over {} windows of {} cycles: f/2 wave in {:.0f} % of them; standing "
      "mode {} (lambda {} d), amplitude {} d (noise {:.2f} d), subharmonic share {}\n",
      s.windows.size(), s.window_cycles, 100 * s.wave_fraction, s.standing_mode,
      pm(s.wavelength_d, s.wavelength_error_d, 1), pm(s.amplitude_d, s.amplitude_error_d, 2),
      s.noise_d, pm(s.subharmonic_share, s.subharmonic_share_error, 2));
}

}  // namespace granwave
