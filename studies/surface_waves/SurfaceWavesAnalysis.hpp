#pragma once
// The numbers of the surface-waves study, written under /results/surface_waves
// (docs/studies.md): every run's wave (the space-time spectrum of its surface beside the
// stability study's yes/no detector), each point combined over seeds, the onset Gamma_c(f)
// per variant, the width and depth scans, r_x with its noise floor, and the dissipation axis.
#include <cmath>
#include <string>
#include <vector>

#include "h5/File.hpp"
#include "studies/contract/Study.hpp"
#include "studies/statistics/Measurement.hpp"
#include "studies/surface_waves/SurfaceWavesStudy.hpp"

namespace granwave {

// One run.
struct SurfaceWaveRun {
  SurfaceWavePoint point;
  std::string label, failure;
  bool ok = false, spectrum = false;
  // The spectrum (windows of 10 cycles): standing f/2 wave and temporal response.
  Measurement amplitude_d, wavelength_d, share;
  double noise_d = 0;
  int windows = 0, wave_windows = 0, standing_mode = 0;
  // The stability study's detector (one phase, 16 cycles).
  bool detector_wave = false;
  int detector_mode = 0, period = 0;
  double detector_amplitude_d = 0;
  // The paper's order parameter and the layer's dissipation over the steady part.
  double rms_vx = 0;          // m/s, RMS(v_x) over the dense rows and every phase
  double e_eff = 0;           // sqrt(1 - loss / impact energy) of the pair impacts
  double loss_per_cycle = 0;  // energy dissipated per cycle / mean kinetic energy
};

// One point over its seeds.
struct SurfaceWaveSummary {
  SurfaceWavePoint point;  // seed unused
  int seeds = 0, ok = 0, windows = 0, wave_windows = 0, detector_votes = 0, standing_mode = 0;
  double wave_fraction = 0;  // wave_windows / windows, pooled over seeds
  Measurement amplitude_d, wavelength_d, share, rms_vx, e_eff, loss_per_cycle;
  // Half the pooled windows or more hold a wave (coarse_grain/SurfaceWaveSpectrum.hpp,
  // pooledWindowsWave).
  bool waves() const;
};

struct SurfaceWaveOnset {
  int variant = 0;
  double frequency = 0, width_d = 0;
  bool periodic = true;
  Measurement gamma_c;  // invalid when no crossing; then `bound` says where it lies
  std::string bound;
};

struct MomentumRatioPoint {
  double frequency = 0, gamma = 0;
  Measurement r_x;
  double dry_wave_fraction = 0, wet_wave_fraction = 0;
  bool dry_waves = false, wet_waves = false;  // SurfaceWaveSummary::waves of each
  bool control() const { return !dry_waves && !wet_waves; }
};

struct VariantDissipation {
  int variant = 0;
  Measurement e_eff, loss_per_cycle, gamma_c;  // at the first frequency
  std::string gamma_c_bound;
};

// The spectrum of one run, for the report's figures.
struct ExampleSpectrum {
  std::string label;
  std::vector<double> wavenumber, power_subharmonic, power_harmonic, power_broadband;
  std::vector<double> frequency_over_f, temporal_power;
  std::vector<double> recent_height;  // [record][column], m
  int columns = 0, records = 0, records_per_cycle = 0;
  double width_d = 0, diameter = 0;
};

// The 2D continuum beside the particles at one point of [continuum] (SurfaceWaveContinuum.hpp).
struct ContinuumWavePair {
  SurfaceWaveSummary continuum, particles;
  // CPU seconds (user + sys of the run) per drive cycle, mean over the point's runs that
  // finished: the two models' cost in the same box.
  double continuum_cpu_per_cycle = NAN, particles_cpu_per_cycle = NAN;
  std::string failure;           // the first failed continuum run's message
  Measurement wavelength_ratio;  // continuum / particles, where both wave
  long long remaps = 0;          // vertical remaps of the continuum's runs, summed
};

struct SurfaceWavesResults {
  std::vector<SurfaceWaveRun> runs;
  std::vector<SurfaceWaveSummary> onset, widths, depths;
  std::vector<SurfaceWaveOnset> onsets;
  std::vector<MomentumRatioPoint> r_x;
  Measurement r_x_waves, r_x_control;  // mean and standard error over points
  std::vector<VariantDissipation> dissipation;
  double rank_correlation = 0;  // Spearman, Gamma_c against e_eff over variants with an onset
  int ranked_variants = 0;
  // The width scan's verdict: lambda at the two widest boxes agree (Faraday) or scale with L.
  std::string width_verdict;
  // The 2D continuum ([continuum]): per point beside the particles, and its onset per
  // variant and width over the continuum's Gamma.
  std::vector<ContinuumWavePair> continuum;
  std::vector<SurfaceWaveOnset> continuum_onsets;
  // The spectrum of the run with the strongest f/2 wave of each variant (for figures).
  std::vector<ExampleSpectrum> examples;
  double cpu_seconds = 0;
  int failed_runs = 0;
};

SurfaceWavesResults analyseSurfaceWavesStudy(const SurfaceWavesConfig& config, const RunSet& runs);
void writeSurfaceWavesResults(h5::File& file, const SurfaceWavesResults& results);

// Summary of the runs of `points` (several seeds each), in the order of their first seed.
std::vector<SurfaceWaveSummary> summarise(const std::vector<SurfaceWaveRun>& runs,
                                          const std::vector<SurfaceWavePoint>& points,
                                          int first_seed);

}  // namespace granwave
