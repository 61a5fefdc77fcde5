#include "studies/surface_waves/SurfaceWaveRunReader.hpp"

#include <cmath>

#include "coarse_grain/FieldsReader.hpp"
#include "coarse_grain/SurfaceWavesFile.hpp"
#include "studies/run_files/RunOutputs.hpp"
#include "studies/statistics/Measurement.hpp"

namespace granwave {

namespace {

// RMS(v_x) of the phase-averaged fields over the rows of area fraction >= 0.1 at every phase:
// the paper's order parameter for the layer as a whole.
double layerRmsVx(const PhaseProfiles& p) {
  const PhaseFields& f = p.pooled;
  double sum = 0;
  int n = 0;
  for (int k = 0; k < p.phases(); ++k)
    for (int j = 0; j < p.rows(); ++j) {
      const double v = p.at(f.profile_rms_velocity_x, k, j);
      if (p.at(f.profile_area_fraction, k, j) >= 0.1 && std::isfinite(v)) sum += v, ++n;
    }
  return n > 0 ? sum / n : NAN;
}

// Dissipation over the steady part (after the first fifth of the run, as the run's period):
// the energy lost per drive cycle over the mean kinetic energy, and the pair impacts' e_eff.
void readDissipation(const std::string& run_path, double frequency, SurfaceWaveRun& r) {
  const RunObservables o = readRunObservables(run_path);
  const std::vector<double>&time = o.time, &lost = o.dissipated_energy, &kinetic = o.kinetic_energy;
  const std::vector<double>&impact = o.pair_impact_energy, &loss = o.pair_impact_loss;
  const std::size_t n = time.size();
  if (n < 10 || lost.size() != n || kinetic.size() != n || impact.size() != n) return;
  const std::size_t first = n / 5, last = n - 1;
  double ke = 0;
  for (std::size_t i = first; i <= last; ++i) ke += kinetic[i];
  ke /= static_cast<double>(last - first + 1);
  const double cycles = (time[last] - time[first]) * frequency;
  r.loss_per_cycle = (lost[last] - lost[first]) / cycles / ke;
  const double de = impact[last] - impact[first], dl = loss[last] - loss[first];
  r.e_eff = de > 0 ? std::sqrt(std::max(0.0, 1.0 - dl / de)) : NAN;
}

// The spectrum's numbers of one run.
void readSpectrum(const SurfaceWaveAnalysis& s, SurfaceWaveRun& r) {
  r.spectrum = s.available;
  if (!s.available) return;
  r.amplitude_d = {s.amplitude_d, s.amplitude_error_d};
  // The wavelength of the windows that have a wave (a window without one holds noise).
  std::vector<double> lambda;
  for (const SurfaceWindow& w : s.windows)
    if (w.wave) lambda.push_back(w.wavelength_d);
  r.wavelength_d = meanAndStandardError(lambda);
  if (lambda.size() == 1) r.wavelength_d.error = 0;
  r.share = {s.subharmonic_share, s.subharmonic_share_error};
  r.noise_d = s.noise_d;
  r.windows = static_cast<int>(s.windows.size());
  r.wave_windows = s.waveWindows();
  r.standing_mode = s.standing_mode;
}

}  // namespace

SurfaceWaveRun readContinuumWaveRun(const RunRecord& rec, const SurfaceWavePoint& point) {
  SurfaceWaveRun r;
  r.point = point;
  r.label = rec.request.label;
  r.ok = rec.ok;
  r.rms_vx = r.e_eff = r.loss_per_cycle = NAN;  // not measured on the continuum
  if (!rec.ok) {
    r.failure = rec.message;
    return r;
  }
  readSpectrum(readSurfaceWaves(rec.hydroPath()), r);
  return r;
}

SurfaceWaveRun readSurfaceWaveRun(const RunRecord& rec, const SurfaceWavePoint& point) {
  SurfaceWaveRun r;
  r.point = point;
  r.label = rec.request.label;
  r.ok = rec.ok;
  if (!rec.ok) {
    r.failure = rec.message;
    return r;
  }
  readSpectrum(readSurfaceWaves(rec.fieldsPath()), r);
  const LayerPatterns lp = readLayerPatterns(rec.fieldsPath());
  r.period = lp.period;
  if (lp.available) {
    r.detector_wave = lp.surface_wave;
    r.detector_mode = lp.surface_wave_mode;
    r.detector_amplitude_d = lp.surface_wave_amplitude_d;
  }
  r.rms_vx = layerRmsVx(readFieldsFile(rec.fieldsPath()).profiles);
  readDissipation(rec.runPath(), point.frequency, r);
  return r;
}

}  // namespace granwave
