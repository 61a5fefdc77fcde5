// The report's section on the 2D continuum beside the particles ([continuum]): figures,
// tables and prose only.
#include <fmt/format.h>

#include <cmath>

#include "studies/surface_waves/SurfaceWavesReport.hpp"

namespace granwave {

namespace {

// std::string arguments: assigning short literals to the Series' strings trips GCC 12's
// false -Wrestrict (PR 105329).
Series styled(Series s, std::string marker, std::string linestyle) {
  s.marker = std::move(marker);
  s.linestyle = std::move(linestyle);
  return s;
}

std::string waveText(const SurfaceWaveSummary& s) {
  if (s.ok == 0) return "no run finished";
  return fmt::format("{:.0f} % of {}, mode {}, lambda {} d, amplitude {} d", 100 * s.wave_fraction,
                     s.windows, s.standing_mode, s.waves() ? format(s.wavelength_d, 1) : "–",
                     format(s.amplitude_d));
}

std::string onsetCell(const SurfaceWaveOnset& o) {
  if (o.gamma_c.valid()) return format(o.gamma_c);
  return o.bound == "no runs" ? "– (no run finished)" : "Gamma_c " + o.bound;
}

Table pointsTable(const SurfaceWavesConfig& c, const SurfaceWavesResults& r) {
  Table t;
  t.title = "The 2D continuum and the particles at the same points";
  t.columns = {"point",
               "continuum: f/2 wave in windows",
               "particles: f/2 wave in windows",
               "lambda continuum / particles",
               "CPU-s per cycle: continuum, particles (ratio)",
               "continuum runs (remaps)"};
  for (const ContinuumWavePair& p : r.continuum) {
    const double ratio = p.continuum_cpu_per_cycle / p.particles_cpu_per_cycle;
    t.rows.push_back(
        {pointName(c, p.continuum.point), waveText(p.continuum), waveText(p.particles),
         p.wavelength_ratio.valid() ? format(p.wavelength_ratio) : "– (not both waving)",
         fmt::format("{}, {} ({})", formatNumber(p.continuum_cpu_per_cycle, 3),
                     formatNumber(p.particles_cpu_per_cycle, 3), formatNumber(ratio, 1)),
         fmt::format("{}/{} ({}){}", p.continuum.ok, p.continuum.seeds, p.remaps,
                     p.failure.empty() ? "" : "; failed: " + p.failure)});
  }
  return t;
}

Table onsetTable(const SurfaceWavesConfig& c, const SurfaceWavesResults& r) {
  Table t;
  t.title = "Onset over the continuum's Gamma, each model";
  t.columns = {"variant", "W (d)", "continuum Gamma_c", "particles Gamma_c"};
  for (std::size_t i = 0; i + 1 < r.continuum_onsets.size(); i += 2) {
    const SurfaceWaveOnset &m = r.continuum_onsets[i], &p = r.continuum_onsets[i + 1];
    t.rows.push_back({c.variants[m.variant].name,
                      formatCompact(m.width_d) + (m.periodic ? " periodic" : " walls"),
                      onsetCell(m), onsetCell(p)});
  }
  return t;
}

// Both models' cost per cycle against the width over the points of one variant, Gamma and
// boundary; false when none has both costs.
bool addCostSeries(const SurfaceWavesResults& r, const SurfaceWavePoint& like,
                   const std::string& name, const char* color, Figure& fig) {
  std::vector<double> w, model, particles;
  for (const ContinuumWavePair& p : r.continuum) {
    const SurfaceWavePoint& q = p.continuum.point;
    if (q.variant != like.variant || q.gamma != like.gamma || q.periodic != like.periodic ||
        !std::isfinite(p.continuum_cpu_per_cycle) || !std::isfinite(p.particles_cpu_per_cycle))
      continue;
    w.push_back(q.width_d);
    model.push_back(p.continuum_cpu_per_cycle);
    particles.push_back(p.particles_cpu_per_cycle);
  }
  if (w.empty()) return false;
  fig.series.push_back(styled(lineSeries(w, model, "continuum, " + name, color), "o", "-"));
  fig.series.push_back(styled(lineSeries(w, particles, "particles, " + name, color), "s", "--"));
  return true;
}

// CPU seconds per drive cycle against the box width, both models, per variant, Gamma and
// boundary.
Figure costFigure(const SurfaceWavesConfig& c, const SurfaceWavesResults& r) {
  Figure fig;
  fig.title = "Cost per drive cycle against the box width";
  fig.xlabel = "W (d)";
  fig.ylabel = "CPU-s per cycle";
  fig.yscale = "log";
  const char* colors[] = {"tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple"};
  int n = 0;
  for (int v : c.continuum.variants)
    for (const std::string& b : c.continuum.boundaries)
      for (double g : c.continuum.gammas) {
        SurfaceWavePoint like;
        like.variant = v;
        like.gamma = g;
        like.periodic = b == "periodic";
        const std::string name =
            fmt::format("{}, Gamma {}, {}", c.variants[v].name, formatCompact(g), b);
        if (addCostSeries(r, like, name, colors[n % 5], fig)) ++n;
      }
  return fig;
}

}  // namespace

void addContinuum(const SurfaceWavesConfig& c, const SurfaceWavesResults& r, Report& report) {
  if (r.continuum.empty()) return;
  const ContinuumWavesConfig& k = c.continuum;
  std::string seeds;
  for (int s : k.seeds) seeds += fmt::format("{}{}", seeds.empty() ? "" : ", ", s);
  ReportSection& sec = report.section(
      "The 2D continuum beside the particles",
      fmt::format(
          "The 2D granular hydrodynamics of docs/hydro.md (\"The 2D model\"): the same "
          "closures and restitution laws as the particles' scene, nothing fitted to the "
          "particles, in the same box (periodic or between side walls) at f = {} Hz, {} of {} "
          "cells each, {} "
          "cycles from the scene's start (hydro.start) with seeded column masses (seeds {}). Its "
          "surface is measured by the particles' rule (studies/hydro_run/ContinuumSurface.hpp) "
          "and its spectrum taken over the run's second half in windows of 10 cycles, with the "
          "particles' wave criterion. The particles at each point are the runs of the scans "
          "above where the point is one of theirs, else runs of their own. Cost: each model's "
          "CPU seconds (user + sys of its runs) per drive cycle it integrated.",
          formatCompact(k.frequency),
          k.columns > 0 ? fmt::format("{} columns", k.columns) : "one column per 4 d of the width",
          k.cells, k.cycles, seeds));
  sec.add(pointsTable(c, r));
  if (!r.continuum_onsets.empty()) sec.add(onsetTable(c, r));
  if (k.widths_d.size() > 1) sec.add(costFigure(c, r));
}

}  // namespace granwave
