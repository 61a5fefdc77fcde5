#include "studies/wave_fronts/WaveFrontsReport.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include "scene/SceneDerived.hpp"
#include "studies/framework/FailureReason.hpp"
#include "studies/framework/FieldFigures.hpp"

namespace granwave {

namespace {

Series frontSeries(const PhaseProfiles& p, double d, std::string label, std::string color,
                   std::string marker) {
  std::vector<double> y;
  for (int k = 0; k < p.phases(); ++k) y.push_back((p.front_height[k] - p.plate_height[k]) / d);
  Series s = lineSeries(p.phase, y, std::move(label), std::move(color));
  s.style = "points";
  s.marker = std::move(marker);
  return s;
}

// The paper's profile phases (t/T = 0.88, 0.90, ...; its impact starts at 0.88) moved onto
// this run's strong impact: the first one at the onset of its front, the others at the same
// spacing, so that the profiles show the same stage of the front whatever the impact phase.
std::vector<double> phasesFromImpact(const std::vector<double>& paper, double onset) {
  std::vector<double> out;
  for (double ph : paper) out.push_back(onset + (ph - paper.front()));
  return out;
}

std::string periodList(const std::vector<int>& periods) {
  std::string s;
  for (int p : periods) s += (s.empty() ? "" : ", ") + std::to_string(p);
  return s.empty() ? "–" : s;
}

Table paperTable() {
  Table t;
  t.title = "Front speeds (lab frame), centre-of-mass period and collision time";
  t.caption =
      "Paper: Huang, Sec. IV (wet fronts, Fig. 5) and Fig. 6a (collision time = lowest point of "
      "the centre of mass). Errors are one sigma.";
  t.columns = {"source",
               "after weak impact (m/s)",
               "after strong impact (m/s)",
               "all impact fronts (m/s)",
               "velocity-jump front (m/s)",
               "CM period (T)",
               "CM lowest at t/T"};
  t.rows.push_back({"paper, wet", format(kPaperWeakWet), format(kPaperStrongWet), "–", "–", "2",
                    formatNumber(kPaperCollisionWet)});
  t.rows.push_back({"paper, dry", "–", "–", "–", "–", "2 (stated for both layers)",
                    formatNumber(kPaperCollisionDry)});
  return t;
}

// What the T~g-peak columns measure on this scene, counted over the runs (docs/studies.md,
// "Front speeds on the paper's scene").
std::string peakJumpText(const WaveFrontsResults& r) {
  int fronts = 0, jumps = 0;
  for (const PaperLaw& p : r.paper) {
    fronts += p.peak_fronts;
    jumps += p.peak_jumps;
  }
  if (fronts == 0) return "";
  const std::string counted = fmt::format(
      "In {} of the {} T~g-peak impact fronts of these runs the peak rises between two phases "
      "faster than {:g} m/s. ",
      jumps, fronts, PaperLaw::kPeakJumpSpeed);
  const std::string meaning =
      jumps == 0 ? ""
                 : "There the maximum of T~g leaves the plate region for the top of the layer "
                   "at once, and the line fitted through the episode (the columns 'after weak', "
                   "'after strong' and 'all') depends on where that jump falls. ";
  return counted + meaning +
         "The velocity-jump front (the boundary between the material moving with the plate "
         "and the material still falling) travels through the layer and is what the model "
         "hierarchy below compares.";
}

// One law's rows of the paper table and its series in the front and centre-of-mass figures.
void paperLaw(const WaveFrontsConfig& c, int law, const PaperLaw& p, Table& t, Figure& fronts,
              Figure& com) {
  const double d = c.scenes.base[0].particles.diameter;
  const std::string name = kLawNames[law];
  t.rows.push_back({fmt::format("ED {} ({} seeds × {:g} s)", name, p.seeds_used, c.duration),
                    format(p.ed.weak), format(p.ed.strong), format(p.ed.all),
                    format(p.tracked.speed), periodList(p.periods),
                    formatNumber(p.collision_phase)});
  if (p.first) {
    const PhaseProfiles& first = p.first->profiles;
    fronts.series.push_back(frontSeries(first, d, "ED " + name, kLawColors[law], "^"));
    com.series.push_back(centerOfMassSeries(first, d, "ED " + name, kLawColors[law]));
  }
  for (int v = 0; v < 2; ++v) {
    const HydroOutcome& h = p.hydro[v];
    const std::string row = "hydro " + name +
                            (v == 0 ? ", velocity-dependent closure"
                                    : fmt::format(", constant e = {:.3f}", c.e_eff[law]));
    if (!h.fields) {
      t.rows.push_back({row, "failed: " + shortReason(h.failure), "–", "–", "–", "–", "–"});
      continue;
    }
    t.rows.push_back(
        {row, format(h.fronts.weak), format(h.fronts.strong), format(h.fronts.all),
         format(h.tracked),
         h.fields->periodic ? std::to_string(h.fields->period) : "none in the cycles run",
         formatNumber(h.collision_phase)});
    if (v != 0) continue;
    fronts.series.push_back(frontSeries(h.fields->lab, d, "hydro " + name, kLawColors[law], "o"));
    Series cs = centerOfMassSeries(h.fields->lab, d, "hydro " + name, kLawColors[law]);
    cs.linestyle = "--";
    com.series.push_back(cs);
  }
  if (law == 0 && p.first) {
    std::vector<double> plate;
    const PhaseProfiles& first = p.first->profiles;
    for (int k = 0; k < first.phases(); ++k) plate.push_back(first.plate_height[k] / d);
    com.series.push_back(lineSeries(first.phase, plate, "plate", "black"));
  }
}

void paperSection(const WaveFrontsConfig& c, const WaveFrontsResults& r, Report& report) {
  const Scene& dry = c.scenes.base[0];
  ReportSection& s = report.section(
      "The paper's scene: front speeds, period and collision time",
      fmt::format(
          "N = {}, f = {:g} Hz, Gamma = {:g}; particles: {} seed(s) of {:g} s each, fields "
          "averaged over windows of {} cycles in {} blocks (front speed errors combine the fit "
          "and the block spread; across seeds the inverse-variance mean, its error scaled up "
          "when the seeds scatter more than their errors). Hydro: the 1D solver with the "
          "Maxwell-averaged velocity-dependent closures, and with one constant restitution "
          "e_eff = sqrt(1 - <1 - e^2>) evaluated at the drive's temperature scale T0 = m v0^2/2 "
          "(dry {:.3f}, wet {:.3f}). The weak and the strong impact are told apart by the "
          "peak T~g/T0 of their fronts; a period-1 layer has two equivalent impacts.",
          dry.particles.count, dry.drive.frequency, derive(dry).gamma, c.seeds.size(), c.duration,
          c.window, c.blocks, c.e_eff[0], c.e_eff[1]));
  Table t = paperTable();
  Figure fronts;
  fronts.title = "Front trajectories (seed 1 and hydro)";
  fronts.caption =
      "Height of the T~g peak above the plate at each phase where a front is detected "
      "(T~g/T0 > 0.5 within the layer); the slope is the front speed in the plate frame.";
  fronts.xlabel = "t / T";
  fronts.ylabel = "front height above the plate / d";
  Figure com;
  com.title = "Centre of mass over the window";
  com.caption = "Phase-averaged centre-of-mass height (particles, seed 1) and the hydro solver's.";
  com.xlabel = "t / T";
  com.ylabel = "z_CM / d (lab frame)";
  for (int law = 0; law < kLaws; ++law) paperLaw(c, law, r.paper[law], t, fronts, com);
  s.add(std::move(t));
  s.addText(peakJumpText(r));
  s.add(std::move(fronts));
  s.add(std::move(com));
}

// Temperature profiles at the paper's phases, and the space-time plots.
void profileSections(const WaveFrontsConfig& c, const WaveFrontsResults& r, Report& report) {
  ReportSection& prof = report.section(
      "Temperature profiles at the paper's phases (Fig. 4, right)",
      "Row-averaged granular temperature T~g/T0 against height at the paper's phases "
      "t/T = 0.88, 0.90, ... counted from the onset of the impact front (the paper's impact "
      "starts at 0.88; ours may start at another phase): particles (seed 1, the strong impact) "
      "and the hydro solver's periodic state. The paper's wet layer shows a peak that forms at "
      "the plate, broadens and travels up within a tenth of a period.");
  ReportSection& st = report.section(
      "Density space-time plots (Fig. 5)",
      "Area fraction (grey) against t/T and height, with the T~g-peak fronts (triangles), the "
      "centre of mass (yellow) and the plate and lid (blue). Particles: seed 1, averaged over "
      "the steady cycles; hydro: the periodic state.");
  const double d = c.scenes.base[0].particles.diameter;
  for (int law : {1, 0}) {
    const std::string name = kLawNames[law];
    const double T0 = derive(c.scenes.base[law]).T0;
    const double Lz = c.scenes.base[law].container.height;
    if (const auto& seed1 = r.paper[law].seed1) {
      const PhaseProfiles& p = seed1->profiles;
      const ImpactFronts imp = impactFronts(p);
      const double onset = imp.strong_start >= 0 ? imp.strong_start : c.profile_phases.front();
      prof.add(profilesAtPhases(
          p, p.pooled.profile_temperature, 1.0 / T0, d, phasesFromImpact(c.profile_phases, onset),
          "Particles, " + name + ": T~g(z) / T0", "T~g / T0",
          fmt::format("From the onset of the strong impact's front (t/T = {:.2f} of the "
                      "{}-cycle window), at the paper's spacing.",
                      onset, c.window)));
      st.add(spaceTimeFigure(p, d, Lz, "Particles, " + name,
                             fmt::format("Layer period {} T.", seed1->context.layer_period)));
    }
    if (const auto& h = r.paper[law].hydro[0].fields) {
      const ImpactFronts& imp = r.paper[law].hydro[0].fronts;
      const double onset = imp.strong_start >= 0 ? imp.strong_start : c.profile_phases.front();
      prof.add(profilesAtPhases(
          h->lab, h->lab.pooled.profile_temperature, 1.0 / T0, d,
          phasesFromImpact(c.profile_phases, onset), "Hydro, " + name + ": T(z) / T0", "T / T0",
          fmt::format("Velocity-dependent closure; from the onset of the impact front (t/T = "
                      "{:.2f}), at the paper's spacing.",
                      onset)));
      st.add(spaceTimeFigure(h->lab, d, Lz, "Hydro, " + name,
                             h->periodic ? fmt::format("Periodic state of period {} T.", h->period)
                                         : std::string("No periodic state was reached.")));
    }
  }
}

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
  return s.hydro_ok ? format(s.hydro) : "failed: " + shortReason(s.hydro_failure);
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
        "Caveat: some layers give front speeds up to {} m/s, more than 1.5 times the paper "
        "scene's. A front speed is the slope of a straight line through the heights of the "
        "T~g peak above 0.5 T0; where that peak does not travel as one maximum (in the deep "
        "layers inspected it jumps between the plate region and the top of the layer within a "
        "few phases), the slope is not a front speed. Read the trend with N from the layers "
        "whose speeds have small errors.",
        format(fastest)));
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
    for (int law = 0; law < kLaws; ++law)
      row.push_back(format(r.n_sweep[law][i].tracked.jump_speed));
    for (int law = 0; law < kLaws; ++law)
      row.push_back(trackedCell(r.n_sweep[law][i].hydro_tracked));
    for (int law = 0; law < kLaws; ++law)
      row.push_back(format(r.n_sweep[law][i].hydro_tracked.jump_speed));
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
      row[1 + law] = format(p.ed);
      row[5 + law] = formatNumber(p.collision_phase);
      row[3 + law] = hydroCell(p);
    }
    sweepSeries(x, r.n_sweep[law], law, fig);
  }
  for (auto& [n, row] : rows) t.rows.push_back(row);
  s.add(std::move(fig));
  s.add(std::move(t));
  deepLayerCaveat(r, s);
  trackedDepthTable(c, r, s);
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
      tw.rows.push_back({sw.key, formatCompact(sw.values[i]), format(p.ed), hydroCell(p),
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
    w.add(std::move(fw));
  }
  w.add(std::move(tw));
}

}  // namespace

void reportWaveFronts(const WaveFrontsConfig& c, const WaveFrontsResults& r, Report& report) {
  paperSection(c, r, report);
  profileSections(c, r, report);
  depthSection(c, r, report);
  wetLawSection(r, report);
  costSection(c, r.cost, report);
  failureSection(c, r.failures, report);
  stateSection(r, report);
  modelSection(c, r, report);
  if (r.lammps) lammpsSection(c, *r.lammps, r.paper[0], report);
}

}  // namespace granwave
