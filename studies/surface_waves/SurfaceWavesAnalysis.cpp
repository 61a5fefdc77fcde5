#include "studies/surface_waves/SurfaceWavesAnalysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "coarse_grain/FieldsReader.hpp"
#include "coarse_grain/SurfaceWaveSpectrum.hpp"
#include "coarse_grain/SurfaceWavesFile.hpp"
#include "studies/surface_waves/SurfaceWaveContinuum.hpp"
#include "studies/surface_waves/SurfaceWaveOnset.hpp"
#include "studies/surface_waves/SurfaceWaveRunReader.hpp"
#include "studies/wave_analysis/WaveMomentumRatio.hpp"

namespace granwave {

bool SurfaceWaveSummary::waves() const { return pooledWindowsWave(wave_windows, windows); }

namespace {

bool samePoint(const SurfaceWavePoint& a, const SurfaceWavePoint& b) {
  return a.variant == b.variant && a.width_d == b.width_d && a.periodic == b.periodic &&
         a.rows == b.rows && a.frequency == b.frequency && a.gamma == b.gamma;
}

Measurement seedMean(const std::vector<double>& v) {
  Measurement m = meanAndStandardError(v);
  if (m.valid() && !std::isfinite(m.error)) m.error = 0;  // one seed: no spread to quote
  return m;
}

SurfaceWaveSummary summary(const std::vector<const SurfaceWaveRun*>& runs) {
  SurfaceWaveSummary s;
  s.point = runs.front()->point;
  s.seeds = static_cast<int>(runs.size());
  std::vector<Measurement> amp, lambda, share;
  std::vector<double> rms, eff, loss;
  std::map<int, int> modes;
  for (const SurfaceWaveRun* r : runs) {
    if (!r->ok || !r->spectrum) continue;
    ++s.ok;
    amp.push_back(r->amplitude_d);
    if (r->wavelength_d.valid()) lambda.push_back(r->wavelength_d);
    share.push_back(r->share);
    rms.push_back(r->rms_vx);
    eff.push_back(r->e_eff);
    loss.push_back(r->loss_per_cycle);
    s.wave_windows += r->wave_windows;
    s.windows += r->windows;
    s.detector_votes += r->detector_wave;
    ++modes[r->standing_mode];
  }
  if (s.ok == 0) return s;
  s.wave_fraction = s.windows > 0 ? static_cast<double>(s.wave_windows) / s.windows : 0;
  s.amplitude_d = combine(amp);
  s.wavelength_d = combine(lambda);
  s.share = combine(share);
  s.rms_vx = seedMean(rms);
  s.e_eff = seedMean(eff);
  s.loss_per_cycle = seedMean(loss);
  int most = 0;
  for (const auto& [m, n] : modes)
    if (n > most) most = n, s.standing_mode = m;
  return s;
}

// r_x = RMS(v_x)_dry / RMS(v_x)_wet of the variants named "dry" and "wet" in the base box,
// per (f, Gamma), mean and standard error over the seeds (WaveMomentumRatio: over the wet
// layer's strong impact wave).
std::vector<MomentumRatioPoint> momentumRatios(const SurfaceWavesConfig& c, const RunSet& runs,
                                               const std::vector<SurfaceWaveSummary>& onset) {
  std::vector<MomentumRatioPoint> out;
  const int dry = c.variantIndex("dry"), wet = c.variantIndex("wet");
  if (dry < 0 || wet < 0) return out;
  for (double f : c.frequencies)
    for (double g : c.gammas) {
      MomentumRatioPoint p{f, g, {}, 0, 0};
      std::vector<double> per_seed;
      for (int seed : c.seeds) {
        const SurfaceWavePoint a{dry, c.width_d, c.periodic, c.rows, f, g, seed};
        const SurfaceWavePoint b{wet, c.width_d, c.periodic, c.rows, f, g, seed};
        const RunRecord &rd = runs.get(c.label(a)), &rw = runs.get(c.label(b));
        if (!rd.ok || !rw.ok) continue;
        const Measurement r =
            waveMomentumRatio(readFieldsFile(rd.fieldsPath()), readFieldsFile(rw.fieldsPath()), {});
        if (r.valid()) per_seed.push_back(r.value);
      }
      p.r_x = seedMean(per_seed);
      for (const SurfaceWaveSummary& s : onset) {
        if (s.point.frequency != f || s.point.gamma != g) continue;
        if (s.point.variant == dry) p.dry_wave_fraction = s.wave_fraction, p.dry_waves = s.waves();
        if (s.point.variant == wet) p.wet_wave_fraction = s.wave_fraction, p.wet_waves = s.waves();
      }
      out.push_back(p);
    }
  return out;
}

void splitRatios(SurfaceWavesResults& r) {
  std::vector<double> waves, control;
  for (const MomentumRatioPoint& p : r.r_x) {
    if (!p.r_x.valid()) continue;
    (p.control() ? control : waves).push_back(p.r_x.value);
  }
  r.r_x_waves = meanAndStandardError(waves);
  r.r_x_control = meanAndStandardError(control);
}

// Box modes against Faraday waves: a Faraday wave keeps its wavelength as the box grows, a
// box mode's scales with the box (lambda = 2 L / m or L / m at a fixed small m).
std::string widthVerdict(const SurfaceWavesConfig& c, const std::vector<SurfaceWaveSummary>& w) {
  std::string out;
  for (int v : c.width_variants)
    for (const std::string& b : c.boundaries) {
      std::vector<const SurfaceWaveSummary*> wavy;
      for (const SurfaceWaveSummary& s : w)
        if (s.point.variant == v && s.point.periodic == (b == "periodic") && s.waves() &&
            s.wavelength_d.valid())
          wavy.push_back(&s);
      std::string what;
      if (wavy.size() < 2) {
        what = fmt::format("waves in {} of {} widths: not enough to tell", wavy.size(),
                           c.widths_d.size());
      } else {
        const SurfaceWaveSummary &a = *wavy[wavy.size() - 2], &z = *wavy.back();
        const double sig = sigmaDistance(z.wavelength_d, a.wavelength_d);
        const double ratio = z.wavelength_d.value / a.wavelength_d.value;
        const double boxes = z.point.width_d / a.point.width_d;
        what = fmt::format(
            "lambda {} d at W = {} d and {} d at W = {} d ({:.1f} sigma apart; ratio {:.2f} for "
            "a box {:.1f} times wider): {}",
            format(a.wavelength_d, 1), formatCompact(a.point.width_d), format(z.wavelength_d, 1),
            formatCompact(z.point.width_d), sig, ratio, boxes,
            std::abs(sig) <= 2 ? "the wavelength is the layer's own (Faraday wave)"
            : std::abs(ratio - boxes) < std::abs(ratio - 1) ? "it scales with the box (box mode)"
                                                            : "neither fixed nor box-bound");
      }
      out += fmt::format("{}{}, {}: {}", out.empty() ? "" : "; ", c.variants[v].name, b, what);
    }
  return out;
}

std::vector<ExampleSpectrum> examples(const SurfaceWavesConfig& c, const RunSet& set,
                                      const std::vector<SurfaceWaveRun>& runs) {
  std::vector<ExampleSpectrum> out;
  for (std::size_t v = 0; v < c.variants.size(); ++v) {
    const SurfaceWaveRun* best = nullptr;
    for (const SurfaceWaveRun& r : runs)
      if (r.point.variant == static_cast<int>(v) && r.ok && r.spectrum &&
          (!best || r.amplitude_d.value > best->amplitude_d.value))
        best = &r;
    if (!best) continue;
    const SurfaceWaveAnalysis a = readSurfaceWaves(set.get(best->label).fieldsPath());
    ExampleSpectrum e;
    e.label = best->label;
    e.wavenumber = a.mode_wavenumber;
    e.power_subharmonic = a.power_subharmonic;
    e.power_harmonic = a.power_harmonic;
    e.power_broadband = a.power_broadband;
    e.frequency_over_f = a.frequency_over_f;
    e.temporal_power = a.temporal_power;
    e.recent_height = a.recent_height;
    e.columns = a.columns;
    e.records = a.recent_records;
    e.records_per_cycle = a.records_per_cycle;
    e.width_d = a.width / a.diameter;
    e.diameter = a.diameter;
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace

std::vector<SurfaceWaveSummary> summarise(const std::vector<SurfaceWaveRun>& runs,
                                          const std::vector<SurfaceWavePoint>& points,
                                          int first_seed) {
  std::vector<SurfaceWaveSummary> out;
  for (const SurfaceWavePoint& p : points) {
    if (p.seed != first_seed) continue;
    std::vector<const SurfaceWaveRun*> same;
    for (const SurfaceWaveRun& r : runs)
      if (samePoint(r.point, p)) same.push_back(&r);
    if (!same.empty()) out.push_back(summary(same));
  }
  return out;
}

SurfaceWavesResults analyseSurfaceWavesStudy(const SurfaceWavesConfig& c, const RunSet& runs) {
  SurfaceWavesResults r;
  std::vector<SurfaceWavePoint> all = c.onsetPoints();
  for (const auto& scan : {c.widthPoints(), c.depthPoints(), c.continuumParticlePoints()})
    all.insert(all.end(), scan.begin(), scan.end());
  for (const SurfaceWavePoint& p : all) {
    const std::string label = c.label(p);
    bool seen = false;
    for (const SurfaceWaveRun& x : r.runs) seen = seen || x.label == label;
    if (seen) continue;
    const RunRecord& rec = runs.get(label);
    r.runs.push_back(readSurfaceWaveRun(rec, p));
    r.cpu_seconds += rec.cpu;
    r.failed_runs += !rec.ok;
  }
  const int first = c.seeds.front();
  r.onset = summarise(r.runs, c.onsetPoints(), first);
  r.widths = summarise(r.runs, c.widthPoints(), first);
  r.depths = summarise(r.runs, c.depthPoints(), first);
  r.onsets = waveOnsets(c, r.onset);
  r.dissipation = variantDissipation(c, r.onset, r.onsets);
  rankCorrelation(r.dissipation, r.rank_correlation, r.ranked_variants);
  r.r_x = momentumRatios(c, runs, r.onset);
  splitRatios(r);
  r.width_verdict = widthVerdict(c, r.widths);
  r.examples = examples(c, runs, r.runs);
  r.continuum = continuumBesideParticles(c, runs, r.runs);
  r.continuum_onsets = continuumOnsets(c, r.continuum);
  for (const SurfaceWavePoint& p : c.continuumPoints()) {
    const RunRecord& rec = runs.get(c.continuumLabel(p));
    r.cpu_seconds += rec.cpu;
    r.failed_runs += !rec.ok;
  }
  return r;
}

}  // namespace granwave
