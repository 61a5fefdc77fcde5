// /results/surface_waves of results.h5 (docs/studies.md, "surface-waves").
#include <fmt/format.h>

#include "studies/contract/StudyResults.hpp"
#include "studies/surface_waves/SurfaceWavesAnalysis.hpp"

namespace granwave {

namespace {

const std::string kRoot = "/results/surface_waves";

// One group per point of a scan: its parameters and numbers as attributes.
void writeSummaries(h5::File& f, const std::string& scan,
                    const std::vector<SurfaceWaveSummary>& points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const SurfaceWaveSummary& s = points[i];
    const std::string g = fmt::format("{}/{}/point_{:03d}", kRoot, scan, i);
    f.createGroup(g);
    putValue(f, g, "variant", s.point.variant);
    putValue(f, g, "width_d", s.point.width_d);
    putValue(f, g, "periodic", s.point.periodic);
    putValue(f, g, "rows", s.point.rows);
    putValue(f, g, "frequency", s.point.frequency);
    putValue(f, g, "gamma", s.point.gamma);
    putValue(f, g, "seeds", s.seeds);
    putValue(f, g, "runs_ok", s.ok);
    putValue(f, g, "windows", s.windows);
    putValue(f, g, "wave_fraction", s.wave_fraction);
    putValue(f, g, "wave_windows", s.wave_windows);
    putValue(f, g, "waves", s.waves());
    putValue(f, g, "detector_votes", s.detector_votes);
    putValue(f, g, "standing_mode", s.standing_mode);
    putMeasurement(f, g, "amplitude_d", s.amplitude_d);
    putMeasurement(f, g, "wavelength_d", s.wavelength_d);
    putMeasurement(f, g, "subharmonic_share", s.share);
    putMeasurement(f, g, "rms_vx", s.rms_vx);
    putMeasurement(f, g, "e_eff", s.e_eff);
    putMeasurement(f, g, "loss_per_cycle", s.loss_per_cycle);
  }
}

// A summary's spectrum numbers under `prefix` (continuum_ or particles_).
void putSpectrum(h5::File& f, const std::string& g, const std::string& prefix,
                 const SurfaceWaveSummary& s) {
  putValue(f, g, prefix + "runs_ok", s.ok);
  putValue(f, g, prefix + "windows", s.windows);
  putValue(f, g, prefix + "wave_fraction", s.wave_fraction);
  putValue(f, g, prefix + "wave_windows", s.wave_windows);
  putValue(f, g, prefix + "waves", s.waves());
  putValue(f, g, prefix + "standing_mode", s.standing_mode);
  putMeasurement(f, g, prefix + "amplitude_d", s.amplitude_d);
  putMeasurement(f, g, prefix + "wavelength_d", s.wavelength_d);
  putMeasurement(f, g, prefix + "subharmonic_share", s.share);
}

void writeContinuum(h5::File& f, const SurfaceWavesResults& r) {
  for (std::size_t i = 0; i < r.continuum.size(); ++i) {
    const ContinuumWavePair& p = r.continuum[i];
    const std::string g = fmt::format("{}/continuum/point_{:03d}", kRoot, i);
    f.createGroup(g);
    putValue(f, g, "variant", p.continuum.point.variant);
    putValue(f, g, "width_d", p.continuum.point.width_d);
    putValue(f, g, "periodic", p.continuum.point.periodic);
    putValue(f, g, "rows", p.continuum.point.rows);
    putValue(f, g, "frequency", p.continuum.point.frequency);
    putValue(f, g, "gamma", p.continuum.point.gamma);
    putValue(f, g, "continuum_seeds", p.continuum.seeds);
    putValue(f, g, "particles_seeds", p.particles.seeds);
    putSpectrum(f, g, "continuum_", p.continuum);
    putSpectrum(f, g, "particles_", p.particles);
    putValue(f, g, "continuum_cpu_per_cycle", p.continuum_cpu_per_cycle);
    putValue(f, g, "particles_cpu_per_cycle", p.particles_cpu_per_cycle);
    putValue(f, g, "continuum_remaps", static_cast<double>(p.remaps));
    putMeasurement(f, g, "wavelength_ratio", p.wavelength_ratio);
    f.writeStringAttribute(g, "continuum_failure", p.failure);
  }
  for (std::size_t i = 0; i < r.continuum_onsets.size(); ++i) {
    const SurfaceWaveOnset& o = r.continuum_onsets[i];
    const std::string g = fmt::format("{}/continuum_onsets/onset_{:03d}", kRoot, i);
    f.createGroup(g);
    f.writeStringAttribute(g, "model", i % 2 == 0 ? "continuum" : "particles");
    putValue(f, g, "variant", o.variant);
    putValue(f, g, "width_d", o.width_d);
    putValue(f, g, "periodic", o.periodic);
    putValue(f, g, "frequency", o.frequency);
    putMeasurement(f, g, "gamma_c", o.gamma_c);
    f.writeStringAttribute(g, "bound", o.bound);
  }
}

void writeOnsets(h5::File& f, const SurfaceWavesResults& r) {
  for (std::size_t i = 0; i < r.onsets.size(); ++i) {
    const SurfaceWaveOnset& o = r.onsets[i];
    const std::string g = fmt::format("{}/onsets/onset_{:03d}", kRoot, i);
    f.createGroup(g);
    putValue(f, g, "variant", o.variant);
    putValue(f, g, "frequency", o.frequency);
    putMeasurement(f, g, "gamma_c", o.gamma_c);
    f.writeStringAttribute(g, "bound", o.bound);
  }
  for (std::size_t i = 0; i < r.dissipation.size(); ++i) {
    const VariantDissipation& d = r.dissipation[i];
    const std::string g = fmt::format("{}/dissipation/variant_{:03d}", kRoot, i);
    f.createGroup(g);
    putValue(f, g, "variant", d.variant);
    putMeasurement(f, g, "e_eff", d.e_eff);
    putMeasurement(f, g, "loss_per_cycle", d.loss_per_cycle);
    putMeasurement(f, g, "gamma_c", d.gamma_c);
    f.writeStringAttribute(g, "gamma_c_bound", d.gamma_c_bound);
  }
  putValue(f, kRoot + "/dissipation", "rank_correlation", r.rank_correlation);
  putValue(f, kRoot + "/dissipation", "ranked_variants", r.ranked_variants);
}

void writeMomentumRatios(h5::File& f, const SurfaceWavesResults& r) {
  const std::string g = kRoot + "/r_x";
  f.createGroup(g);
  std::vector<double> freq, gamma, value, error, dry, wet, dry_waves, wet_waves;
  for (const MomentumRatioPoint& p : r.r_x) {
    freq.push_back(p.frequency);
    gamma.push_back(p.gamma);
    value.push_back(p.r_x.value);
    error.push_back(p.r_x.error);
    dry.push_back(p.dry_wave_fraction);
    wet.push_back(p.wet_wave_fraction);
    dry_waves.push_back(p.dry_waves);
    wet_waves.push_back(p.wet_waves);
  }
  putSeries(f, g + "/frequency", freq, "Hz");
  putSeries(f, g + "/gamma", gamma, "1");
  putSeries(f, g + "/r_x", value, "1");
  putSeries(f, g + "/r_x_error", error, "1");
  putSeries(f, g + "/dry_wave_fraction", dry, "1");
  putSeries(f, g + "/wet_wave_fraction", wet, "1");
  putSeries(f, g + "/dry_waves", dry_waves, "1");
  putSeries(f, g + "/wet_waves", wet_waves, "1");
  putMeasurement(f, g, "with_waves", r.r_x_waves);
  putMeasurement(f, g, "control_without_waves", r.r_x_control);
}

}  // namespace

void writeSurfaceWavesResults(h5::File& f, const SurfaceWavesResults& r) {
  f.createGroup(kRoot);
  for (const char* scan :
       {"onset", "widths", "depths", "onsets", "dissipation", "continuum", "continuum_onsets"})
    f.createGroup(kRoot + "/" + scan);
  writeSummaries(f, "onset", r.onset);
  writeSummaries(f, "widths", r.widths);
  writeSummaries(f, "depths", r.depths);
  writeOnsets(f, r);
  writeMomentumRatios(f, r);
  writeContinuum(f, r);
  f.writeStringAttribute(kRoot, "width_verdict", r.width_verdict);
  putValue(f, kRoot, "cpu_seconds", r.cpu_seconds);
  putValue(f, kRoot, "failed_runs", r.failed_runs);
}

}  // namespace granwave
