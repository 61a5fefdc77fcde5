// The wave-fronts study's report on its sweeps (docs/studies.md): the layer's depth N (Fig. 6a)
// with the velocity-jump fronts and the cost per answer, and the wet law's parameters
// (Fig. 6b).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "studies/contract/FailureReason.hpp"
#include "studies/wave_fronts/WaveFrontsReport.hpp"

namespace granwave {

namespace {

// Particles and hydro against a swept value, one law.
void sweepSeries(const std::vector<double>& x, const std::vector<SweepPoint>& points, int law,
                 Figure& fig) {
  std::vector<double> y, e, yh, eh;
  for (const SweepPoint& s : points) {
    y.push_back(s.ed.value);
    e.push_back(s.ed.error);
    yh.push_back(s.hydro.value);
    eh.push_back(s.hydro.error);
  }
  fig.series.push_back(errorSeries(x, y, e, std::string("ED ") + kLawNames[law], kLawColors[law]));
  Series hs = errorSeries(x, yh, eh, std::string("hydro ") + kLawNames[law], kLawColors[law]);
  hs.marker = "s";
  hs.linestyle = "--";
  fig.series.push_back(hs);
}

std::string hydroCell(const SweepPoint& s) {
  if (!s.hydro_ok) return "failed: " + shortReason(s.hydro_failure);
  return formatOr(s.hydro, "none: no T~g peak above 0.5 T0 rose from an impact");
}

std::string particleCell(const SweepPoint& s) {
  if (s.layer_period < 0) return "failed (Runs and cost gives why)";
  return formatOr(s.ed, "none: no T~g peak above 0.5 T0 rose from an impact");
}

// A plot whose every point is missing says so, instead of showing empty axes unexplained.
void noteEmpty(Figure& fig) {
  for (const Series& s : fig.series)
    for (double y : s.y)
      if (std::isfinite(y)) return;
  fig.caption += " No run gave a front speed here (the table says why): the plot is empty.";
}

// A measured caveat, stated only when the runs show it: in deep layers the T~g peak above the
// threshold jumps between the plate and the top of the layer, and a line through such an
// episode is not a front speed.
void deepLayerCaveat(const WaveFrontsResults& r, ReportSection& s) {
  Measurement fastest;
  for (int law = 0; law < kLaws; ++law)
    for (const SweepPoint& p : r.n_sweep[law])
      if (p.layer_period >= 0 && p.ed.valid() && (!fastest.valid() || p.ed.value > fastest.value))
        fastest = p.ed;
  if (fastest.valid() &&
      fastest.value > 1.5 * std::max(r.paper[0].ed.all.value, r.paper[1].ed.all.value))
    s.addText(fmt::format(
        "Caveat: some layers give front speeds up to {}, more than 1.5 times the paper "
        "scene's. A front speed is the slope of a straight line through the heights of the "
        "T~g peak above 0.5 T0; where that peak does not travel as one maximum (in the deep "
        "layers inspected it jumps between the plate region and the top of the layer within a "
        "few phases), the slope is not a front speed. Read the trend with N from the layers "
        "whose speeds have small errors.",
        format(fastest, 2, "m/s")));
}

// CPU seconds per answer against N: the particles' cost per cycle times the cycles one answer
// needs, beside the continuum from the settled layer to its periodic state (docs/performance.md).
void costPerAnswer(const WaveFrontsConfig& c, const WaveFrontsResults& r, ReportSection& s) {
  Figure fig;
  fig.title = "CPU time per answer against N";
  fig.caption = fmt::format(
      "Log scale. Particles: CPU per cycle of the sweep run x {:g} cycles; hydro: the whole run "
      "at the scene's grid, settled layer to periodic state.",
      c.answer_cycles);
  fig.xlabel = "N";
  fig.ylabel = "CPU time per answer (s)";
  fig.yscale = "log";
  const std::vector<double> x(c.counts.begin(), c.counts.end());
  std::string crossover;
  for (int law = 0; law < kLaws; ++law) {
    std::vector<double> ed, hy;
    int first_cheaper = 0;
    for (const SweepPoint& p : r.n_sweep[law]) {
      ed.push_back(p.ed_cpu_per_cycle * c.answer_cycles);
      hy.push_back(p.hydro_cpu);
      if (first_cheaper == 0 && hy.back() < ed.back()) first_cheaper = c.counts[ed.size() - 1];
    }
    fig.series.push_back(
        lineSeries(x, ed, std::string("particles ") + kLawNames[law], kLawColors[law]));
    Series hs = lineSeries(x, hy, std::string("hydro ") + kLawNames[law], kLawColors[law]);
    hs.marker = "s";
    hs.linestyle = "--";
    fig.series.push_back(hs);
    crossover += fmt::format(
        "{} layer: {}. ", kLawNames[law],
        first_cheaper ? fmt::format("hydro is cheaper per answer from N = {}", first_cheaper)
                      : std::string("hydro is not cheaper at any N run"));
  }
  s.add(std::move(fig));
  s.addText(crossover);
}

std::string trackedCell(const VelocityFronts& v) {
  if (v.speed.valid()) return format(v.speed);
  return v.why_none.empty() ? "–" : v.why_none;
}

// The Rankine-Hugoniot speed of the fronts, or why there is none.
std::string jumpCell(const VelocityFronts& v) {
  if (v.jump_speed.valid()) return format(v.jump_speed);
  return v.speed.valid() ? "undetermined: density jump below 2 %" : "none: no front";
}

// The velocity-jump tracker (docs/fields.md) over the sweep's seeds, beside the hydro solver's
// fronts found the same way and the Rankine-Hugoniot speeds from the states either side.
void trackedDepthTable(const WaveFrontsConfig& c, const WaveFrontsResults& r, ReportSection& s) {
  Table t;
  t.title = "Impact fronts by the velocity jump against N";
  t.columns = {"N",
               "ED dry (m/s)",
               "ED wet (m/s)",
               "ED dry RH (m/s)",
               "ED wet RH (m/s)",
               "hydro dry (m/s)",
               "hydro wet (m/s)",
               "hydro dry RH (m/s)",
               "hydro wet RH (m/s)"};
  for (std::size_t i = 0; i < c.counts.size(); ++i) {
    std::vector<std::string> row{std::to_string(c.counts[i])};
    for (int law = 0; law < kLaws; ++law) row.push_back(trackedCell(r.n_sweep[law][i].tracked));
    for (int law = 0; law < kLaws; ++law) row.push_back(jumpCell(r.n_sweep[law][i].tracked));
    for (int law = 0; law < kLaws; ++law)
      row.push_back(trackedCell(r.n_sweep[law][i].hydro_tracked));
    for (int law = 0; law < kLaws; ++law) row.push_back(jumpCell(r.n_sweep[law][i].hydro_tracked));
    t.rows.push_back(row);
  }
  s.add(std::move(t));
  int determined = 0, given = 0;  // RH speeds whose error is smaller than their value
  for (int law = 0; law < kLaws; ++law)
    for (const SweepPoint& p : r.n_sweep[law])
      for (const Measurement& m : {p.tracked.jump_speed, p.hydro_tracked.jump_speed})
        if (m.valid()) {
          ++given;
          determined += std::abs(m.value) > m.error;
        }
  if (given > 0 && 2 * determined < given)
    s.addText(fmt::format(
        "Only {} of the {} Rankine-Hugoniot speeds above exceed their error: across these "
        "fronts the density changes by a few per cent, so [rho v] / [rho] is ill-conditioned "
        "and checks nothing here. The tracker is checked against the jump conditions on the "
        "hydro solver's shock into a uniform gas (docs/fields.md), where the density jump is "
        "large.",
        determined, given));
  s.addText(fmt::format(
      "The front at a phase is where v_z falls through the midpoint between the fastest-rising "
      "and the fastest-falling row of the layer; its speed is a straight-line fit from when it "
      "leaves the plate until it reaches the top. Particles: seeds {} at {} phases per cycle, "
      "errors from a bootstrap over blocks of cycles and the fit, combined over seeds (seed "
      "scatter enlarges them); hydro: fit error. RH: the mass jump condition "
      "[rho v] / [rho] from the states two rows either side, undetermined where the density "
      "jump is below 2 %. Where no speed is given the cell says why.",
      fmt::join(c.sweep_seeds, ", "), c.sweep_phases));
}

}  // namespace

void depthSection(const WaveFrontsConfig& c, const WaveFrontsResults& r, Report& report) {
  ReportSection& s = report.section(
      "Layer depth N (Fig. 6a)",
      fmt::format("Mean speed of the impact fronts against the number of particles (seed {}, "
                  "{:g} s per run), particles and hydro (velocity-dependent closure). The paper "
                  "finds faster fronts for deeper layers and a weak effect of wetting, with the "
                  "wet layer hitting the plate about 0.02 T earlier.",
                  c.seeds.front(), c.sweep_duration));
  Figure fig;
  fig.title = "Front speed against N";
  fig.caption = "Error bars: one sigma (particles: fit and block spread; hydro: fit error).";
  fig.xlabel = "N";
  fig.ylabel = "front speed (m/s, lab)";
  Table t;
  t.title = "Front speed and collision time against N";
  t.columns = {"N",
               "ED dry (m/s)",
               "ED wet (m/s)",
               "hydro dry (m/s)",
               "hydro wet (m/s)",
               "ED dry CM lowest t/T",
               "ED wet CM lowest t/T"};
  std::map<int, std::vector<std::string>> rows;
  for (int n : c.counts) rows[n] = {std::to_string(n), "–", "–", "–", "–", "–", "–"};
  const std::vector<double> x(c.counts.begin(), c.counts.end());
  for (int law = 0; law < kLaws; ++law) {
    for (std::size_t i = 0; i < c.counts.size(); ++i) {
      const SweepPoint& p = r.n_sweep[law][i];
      std::vector<std::string>& row = rows[c.counts[i]];
      row[1 + law] = particleCell(p);
      row[5 + law] = formatNumber(p.collision_phase);
      row[3 + law] = hydroCell(p);
    }
    sweepSeries(x, r.n_sweep[law], law, fig);
  }
  for (auto& [n, row] : rows) t.rows.push_back(row);
  noteEmpty(fig);
  s.add(std::move(fig));
  s.add(std::move(t));
  deepLayerCaveat(r, s);
  trackedDepthTable(c, r, s);
  transitDepthTable(c, r, s);
  costPerAnswer(c, r, s);
}

void wetLawSection(const WaveFrontsResults& r, Report& report) {
  ReportSection& w = report.section(
      "Wet-law parameters St_c and e_inf (Fig. 6b)",
      "Mean impact-front speed of the wet layer (N as in the paper's scene) as one parameter of "
      "the wet restitution law varies and the other keeps its paper value. The paper finds the "
      "fronts and the centre-of-mass trajectories unchanged within its resolution.");
  Table tw;
  tw.title = "Front speed against the wet-law parameters";
  tw.columns = {"parameter", "value", "ED wet (m/s)", "hydro wet (m/s)", "ED CM period (T)"};
  for (const ParameterSweep& sw : r.wet_sweeps) {
    Figure fw;
    fw.title = "Front speed against " + sw.key;
    fw.caption = "Particles (seed 1) and hydro (velocity-dependent closure).";
    fw.xlabel = sw.key;
    fw.ylabel = "front speed (m/s, lab)";
    for (std::size_t i = 0; i < sw.values.size(); ++i) {
      const SweepPoint& p = sw.points[i];
      tw.rows.push_back({sw.key, formatCompact(sw.values[i]), particleCell(p), hydroCell(p),
                         p.layer_period >= 0 ? std::to_string(p.layer_period) : "–"});
    }
    std::vector<double> y, e, yh, eh;
    for (const SweepPoint& p : sw.points) {
      y.push_back(p.ed.value);
      e.push_back(p.ed.error);
      yh.push_back(p.hydro.value);
      eh.push_back(p.hydro.error);
    }
    fw.series.push_back(errorSeries(sw.values, y, e, "ED wet", kLawColors[1]));
    Series hs = errorSeries(sw.values, yh, eh, "hydro wet", kLawColors[1]);
    hs.marker = "s";
    hs.linestyle = "--";
    fw.series.push_back(hs);
    noteEmpty(fw);
    w.add(std::move(fw));
  }
  w.add(std::move(tw));
}

}  // namespace granwave
