#pragma once
// The space-time spectrum of a layer's surface h(x, t) (SurfaceRecorder.hpp) and the surface
// wave it shows: dominant wavenumber, temporal response (subharmonic f/2 or harmonic f),
// standing-wave amplitude, each per window of cycles so that its error is the spread over
// windows (docs/classification.md, "Surface waves from the space-time spectrum").
//
// Space: every recorded profile is expanded in the modes its boundary allows (walls: cosines,
// periodic: Fourier; SurfaceWaveDetector.hpp, normalised so that |a_m| is a pure mode's
// amplitude). Time: a window of W consecutive cycles (W even) of M phases. For every mode m,
// the window's series a_m(c, phi) (cycle c, phase phi) splits exactly into
//
//   d(phi) = <(-1)^c a_m(c, phi)>_c          the odd multiples of f/2 (subharmonic family),
//   s(phi) = <a_m(c, phi)>_c                 the multiples of f, with the static part
//   s0 = <s(phi)>_phi                        (a heap that does not move) taken out,
//   r(c, phi) = a_m - (-1)^c d - s           everything not locked to the drive (broadband),
//
// which is the temporal DFT over the W M samples summed over those bins (Parseval). The
// noise in d and in s is sigma^2 / W, sigma^2(phi) = sum_c |r|^2 / (W - 2); the locked powers
// are bias-corrected by it: P_sub = <|d|^2>_phi - N, P_harm = <|s - s0|^2>_phi - N (>= 0).
//
//   dominant mode      m* maximises P_sub + P_harm (the locked, moving part of the surface);
//   response           subharmonic share P_sub / (P_sub + P_harm) at m*: 1 for a Faraday
//                      (period-doubled) wave, 0 for a wave repeating every cycle;
//   standing wave      the f/2 mode m_sub maximises P_sub; its amplitude sqrt(2 P_sub), that of
//                      the f/2 sinusoid of the same power (A for A cos(pi t / T), noise power
//                      removed), its noise floor sqrt(N), its crest max_phi |d(phi)| (the
//                      pattern's height at its strongest phase, not corrected for noise: the
//                      largest of M noisy values, biased up by a few noise floors), its
//                      wavenumber the P_sub-weighted mean of k over m_sub and its neighbours
//                      (modes are discrete: k = pi m / L with walls, 2 pi m / L periodic),
//                      lambda = 2 pi / k;
//   wave               amplitude >= amplitude_threshold and >= noise_factor x noise floor, and
//                      a subharmonic share of the f/2 mode >= 1/2. Under noise alone P_sub
//                      scatters about 0 by N sqrt(2 / n) over n independent phases (n >= 10
//                      for a layer that changes within a cycle), so an amplitude 3 noise floors
//                      up (P_sub = 4.5 N) is more than 6 of those standard deviations away.
//
// A standing f/2 wave locked to the drive (Melo, Umbanhowar & Swinney, PRL 72, 172 (1994);
// Clement et al., PRE 53, 2972 (1996)) has a large P_sub at a fixed position; a wave drifting
// or a pattern changing from cycle to cycle puts its power into r instead.
#include <complex>
#include <string>
#include <vector>

#include "coarse_grain/SurfaceRecorder.hpp"

namespace granwave {

struct SurfaceSpectrumOptions {
  int window_cycles = 10;            // W (even): per-window values give the errors
  double min_wavelength = 4.0;       // d, as SurfaceWaveOptions
  double amplitude_threshold = 0.5;  // d, as SurfaceWaveOptions: crest-to-trough one d
  double noise_factor = 3.0;         // the amplitude must stand this far above its noise
  int figure_cycles = 4;             // newest cycles of h(x, t) kept for figures
};

struct SurfaceWindow {
  long first_cycle = 0;
  int dominant_mode = 0;
  double subharmonic_share = 0;  // at the dominant mode; NaN if nothing is locked
  int standing_mode = 0;         // m_sub
  double amplitude_d = 0, noise_d = 0, crest_d = 0;  // of m_sub
  double harmonic_amplitude_d = 0;                   // max_phi |s - s0| of the dominant mode
  double wavenumber = 0, wavelength_d = 0;           // m^-1; d
  bool wave = false;
};

struct SurfaceWaveAnalysis {
  bool available = false;  // at least one whole window
  int columns = 0, records_per_cycle = 0, window_cycles = 0, cycles = 0;
  bool periodic_x = false;
  double width = 0, diameter = 0;
  std::vector<SurfaceWindow> windows;
  // Window means and standard errors (over windows) of the standing-wave quantities.
  double amplitude_d = 0, amplitude_error_d = 0, noise_d = 0;
  double wavelength_d = 0, wavelength_error_d = 0;
  double subharmonic_share = 0, subharmonic_share_error = 0;
  double wave_fraction = 0;  // windows with a wave
  int standing_mode = 0;     // the most frequent m_sub
  int waveWindows() const;   // windows with a wave, counted
  double mean_bulk_area_fraction = 0;
  // Spectra averaged over windows: per mode m = 0 .. modes - 1 (m = 0 unused), its wavenumber
  // and P_sub, P_harm, the broadband <|r|^2> (m^2); and the temporal power spectrum of the
  // most frequent dominant mode, per frequency / f (m^2 per bin, bins of f / W).
  std::vector<double> mode_wavenumber, power_subharmonic, power_harmonic, power_broadband;
  std::vector<double> frequency_over_f, temporal_power;
  // The newest figure_cycles cycles of h (m above the plate), [record][column].
  std::vector<double> recent_height;
  int recent_records = 0;
};

// Whether windows pooled over runs (seeds) hold a wave: at least half of them hold an f/2 wave,
// counted in whole windows (a sum of per-run fractions makes 6 of 12 fall below one half). A tie
// is a wave: where one seed waves in every window and the other in none, the point is bistable
// and its share, 1/2, is where the onset is placed (docs/studies.md).
bool pooledWindowsWave(int wave_windows, int windows);

// Throws std::invalid_argument for an odd or non-positive window.
SurfaceWaveAnalysis analyseSurfaceWaves(const SurfaceSeries& series,
                                        const SurfaceSpectrumOptions& options = {});

// The window for `cycles` pooled cycles: options.window_cycles, or for fewer than two such
// windows the largest even number of cycles that makes two, so that a short run still has a
// spread over windows; at least 4 (the noise of a window of W cycles has W - 2 degrees of
// freedom).
int surfaceWindowCycles(int cycles, const SurfaceSpectrumOptions& options = {});

// The one-line summary the commands print ("surface spectrum over ...", newline-terminated).
std::string surfaceSpectrumLine(const SurfaceWaveAnalysis& analysis);

}  // namespace granwave
