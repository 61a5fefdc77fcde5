#include "studies/surface_waves/SurfaceWaveContinuum.hpp"

#include <cmath>

#include "studies/run_files/Hydro2DRunFile.hpp"
#include "studies/surface_waves/SurfaceWaveOnset.hpp"
#include "studies/surface_waves/SurfaceWaveRunReader.hpp"

namespace granwave {

namespace {

bool sameDrive(const SurfaceWavePoint& a, const SurfaceWavePoint& b) {
  return a.variant == b.variant && a.width_d == b.width_d && a.rows == b.rows &&
         a.frequency == b.frequency && a.gamma == b.gamma && a.periodic == b.periodic;
}

// Mean CPU seconds per drive cycle over the runs of `labels` that finished.
double cpuPerCycle(const RunSet& runs, const std::vector<std::string>& labels, int cycles) {
  double sum = 0;
  int n = 0;
  for (const std::string& label : labels) {
    const RunRecord& rec = runs.get(label);
    if (rec.ok) sum += rec.cpu, ++n;
  }
  return n > 0 ? sum / n / cycles : NAN;
}

// a / b with the relative errors added in quadrature.
Measurement ratio(const Measurement& a, const Measurement& b) {
  if (!a.valid() || !b.valid() || b.value == 0) return {};
  const double r = a.value / b.value;
  return {r, std::abs(r) * std::hypot(a.error / a.value, b.error / b.value)};
}

}  // namespace

std::vector<ContinuumWavePair> continuumBesideParticles(
    const SurfaceWavesConfig& c, const RunSet& runs,
    const std::vector<SurfaceWaveRun>& particle_runs) {
  const ContinuumWavesConfig& k = c.continuum;
  std::vector<SurfaceWaveRun> continuum_runs;
  for (const SurfaceWavePoint& p : c.continuumPoints())
    continuum_runs.push_back(readContinuumWaveRun(runs.get(c.continuumLabel(p)), p));
  const std::vector<SurfaceWaveSummary> model =
      summarise(continuum_runs, c.continuumPoints(), k.seeds.front());
  const std::vector<SurfaceWaveSummary> particles =
      summarise(particle_runs, c.continuumParticlePoints(), c.seeds.front());
  std::vector<ContinuumWavePair> out;
  for (const SurfaceWaveSummary& m : model) {
    ContinuumWavePair pair;
    pair.continuum = m;
    for (const SurfaceWaveSummary& s : particles)
      if (sameDrive(s.point, m.point)) pair.particles = s;
    std::vector<std::string> particle_labels;
    double model_cpu = 0, model_cycles = 0;
    for (const SurfaceWaveRun& r : continuum_runs) {
      if (!sameDrive(r.point, m.point)) continue;
      if (!r.ok && pair.failure.empty()) pair.failure = r.failure;
      if (!r.ok) continue;
      // The cycles the solver integrated (the duration is written to 6 digits, so a run of
      // 80 cycles at 15 Hz may integrate 79).
      const RunRecord& rec = runs.get(r.label);
      const Hydro2DSolverRecord solver = readHydro2DSolver(rec.hydroPath());
      pair.remaps += solver.remaps;
      model_cpu += rec.cpu;
      model_cycles += static_cast<double>(solver.cycles);
    }
    for (int seed : c.seeds) {
      SurfaceWavePoint q = m.point;
      q.seed = seed;
      particle_labels.push_back(c.label(q));
    }
    pair.continuum_cpu_per_cycle = model_cycles > 0 ? model_cpu / model_cycles : NAN;
    pair.particles_cpu_per_cycle = cpuPerCycle(runs, particle_labels, c.cycles);
    if (m.waves() && pair.particles.waves())
      pair.wavelength_ratio = ratio(m.wavelength_d, pair.particles.wavelength_d);
    out.push_back(pair);
  }
  return out;
}

std::vector<SurfaceWaveOnset> continuumOnsets(const SurfaceWavesConfig& c,
                                              const std::vector<ContinuumWavePair>& pairs) {
  const ContinuumWavesConfig& k = c.continuum;
  std::vector<SurfaceWaveSummary> model, particles;
  for (const ContinuumWavePair& p : pairs) {
    model.push_back(p.continuum);
    particles.push_back(p.particles);
  }
  std::vector<SurfaceWaveOnset> out;
  for (int v : k.variants)
    for (const std::string& b : k.boundaries)
      for (double w : k.widths_d) {
        const bool periodic = b == "periodic";
        out.push_back(waveOnset(k.gammas, v, k.frequency, w, periodic, model));
        out.push_back(waveOnset(k.gammas, v, k.frequency, w, periodic, particles));
      }
  return out;
}

}  // namespace granwave
