// The analysis half of the wave-fronts study: reads the runs planned in WaveFrontsStudy.cpp
// and writes /results/wave_fronts and the report.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "coarse_grain/PeriodDetector.hpp"
#include "scene/SceneDerived.hpp"
#include "studies/run_files/HydroRunFile.hpp"
#include "studies/framework/FailureReason.hpp"
#include "studies/framework/FieldFigures.hpp"
#include "studies/framework/Measurement.hpp"
#include "studies/framework/StudyResults.hpp"
#include "studies/wave_fronts/WaveFrontsStudy.hpp"

namespace granwave {

namespace {

// The paper's numbers (Huang, Sec. IV: Fig. 5 fronts; Fig. 6a collision times).
const Measurement kPaperWeakWet{1.61, 0.25}, kPaperStrongWet{1.95, 0.25};
constexpr double kPaperCollisionDry = 0.92, kPaperCollisionWet = 0.90;
const char* kColor[2] = {"tab:orange", "tab:blue"};
const std::string kRoot = "/results/wave_fronts";

std::string g(double v) { return fmt::format("{:g}", v); }

std::optional<ParticleFields> particles(const RunSet& runs, const std::string& label) {
  const RunRecord& r = runs.get(label);
  if (!r.ok) return std::nullopt;
  return readParticleFields(r.fieldsPath());
}

std::optional<HydroFields> hydro(const RunSet& runs, const std::string& label) {
  const RunRecord& r = runs.get(label);
  if (!r.ok) return std::nullopt;
  return readHydroFields(r.hydroPath());
}

// Circular mean of phases given in [0, 1).
double meanPhase(const std::vector<double>& v) {
  double c = 0, s = 0;
  for (double x : v) {
    c += std::cos(2 * M_PI * x);
    s += std::sin(2 * M_PI * x);
  }
  if (v.empty()) return NAN;
  // In (0.5, 1.5]: collision times near the end of a cycle read as 0.98, 1.01, not 0.01.
  double m = std::atan2(s, c) / (2 * M_PI);
  return m <= 0.5 ? m + 1 : m;
}

Series frontSeries(const Profiles& p, double d, std::string label, std::string color,
                   std::string marker) {
  std::vector<double> y;
  for (int k = 0; k < p.phases; ++k) y.push_back((p.front[k] - p.plate[k]) / d);
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

}  // namespace

void WaveFrontsStudy::analyse(const RunSet& runs, h5::File& f, Report& report) const {
  f.createGroup(kRoot);
  paperSection(runs, f, report);
  sweepSections(runs, f, report);
  costSection(runs, f, report);
  failureSection(runs, f, report);
  modelSection(runs, f, report);
  if (c_.lammps) lammpsSection(runs, f, report);
  report.summary = summary_;
}

void WaveFrontsStudy::paperSection(const RunSet& runs, h5::File& f, Report& report) const {
  const double d = base_[0].particles.diameter;
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
          base_[0].particles.count, base_[0].drive.frequency, derive(base_[0]).gamma,
          c_.seeds.size(), c_.duration, c_.window, c_.blocks, e_eff_[0], e_eff_[1]));
  Table t;
  t.title = "Front speeds (lab frame), centre-of-mass period and collision time";
  t.caption =
      "Paper: Huang, Sec. IV (wet fronts, Fig. 5) and Fig. 6a (collision time = lowest point of "
      "the centre of mass). Errors are one sigma.";
  t.columns = {"source",
               "after weak impact (m/s)",
               "after strong impact (m/s)",
               "all impact fronts (m/s)",
               "CM period (T)",
               "CM lowest at t/T"};
  t.rows.push_back({"paper, wet", format(kPaperWeakWet), format(kPaperStrongWet), "–", "2",
                    formatNumber(kPaperCollisionWet)});
  t.rows.push_back({"paper, dry", "–", "–", "–", "2 (stated for both layers)",
                    formatNumber(kPaperCollisionDry)});

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

  for (int law = 0; law < 2; ++law) {
    const std::string name = kLawNames[law];
    std::vector<ImpactFronts> per_seed;
    std::vector<double> minima;
    std::string periods;
    std::optional<ParticleFields> first;
    for (int seed : c_.seeds) {
      auto p = particles(runs, edLabel(law, fmt::format("seed {}", seed)));
      if (!p) continue;
      per_seed.push_back(impactFronts(p->fronts));
      for (double m : centerOfMassMinimumPhases(*p, p->cycles_per_window)) minima.push_back(m);
      periods += (periods.empty() ? "" : ", ") + std::to_string(p->layer_period);
      if (!first) first = std::move(p);
    }
    const ImpactFronts ed = combineImpactFronts(per_seed);
    ed_paper_[law] = ed;
    const std::string g_ed = fmt::format("{}/ed_{}", kRoot, name);
    putMeasurement(f, g_ed, "weak", ed.weak);
    putMeasurement(f, g_ed, "strong", ed.strong);
    putMeasurement(f, g_ed, "all", ed.all);
    putValue(f, g_ed, "collision_phase", meanPhase(minima));
    t.rows.push_back({fmt::format("ED {} ({} seeds × {:g} s)", name, per_seed.size(), c_.duration),
                      format(ed.weak), format(ed.strong), format(ed.all),
                      periods.empty() ? "–" : periods, formatNumber(meanPhase(minima))});
    if (first) {
      fronts.series.push_back(frontSeries(*first, d, "ED " + name, kColor[law], "^"));
      com.series.push_back(centerOfMassSeries(*first, d, "ED " + name, kColor[law]));
    }
    for (const char* variant : {"velocity", "constant"}) {
      auto h = hydro(runs, hydroLabel(law, variant));
      const std::string row =
          std::string("hydro ") + name +
          (std::string(variant) == "velocity" ? ", velocity-dependent closure"
                                              : fmt::format(", constant e = {:.3f}", e_eff_[law]));
      if (!h) {
        t.rows.push_back({row, "failed: " + shortReason(runs.get(hydroLabel(law, variant)).message),
                          "–", "–", "–", "–"});
        continue;
      }
      const ImpactFronts hf = impactFronts(h->fronts);
      const int cycles = h->periodic ? h->period : 2;
      const std::string gh = fmt::format("{}/hydro_{}_{}", kRoot, name, variant);
      putMeasurement(f, gh, "weak", hf.weak);
      putMeasurement(f, gh, "strong", hf.strong);
      putMeasurement(f, gh, "all", hf.all);
      putValue(f, gh, "period", h->period);
      const double cmin = meanPhase(centerOfMassMinimumPhases(*h, cycles));
      putValue(f, gh, "collision_phase", cmin);
      t.rows.push_back({row, format(hf.weak), format(hf.strong), format(hf.all),
                        h->periodic ? std::to_string(h->period) : "none in the cycles run",
                        formatNumber(cmin)});
      if (std::string(variant) == "velocity") {
        Series fs = frontSeries(*h, d, "hydro " + name, kColor[law], "o");
        fronts.series.push_back(fs);
        Series cs = centerOfMassSeries(*h, d, "hydro " + name, kColor[law]);
        cs.linestyle = "--";
        com.series.push_back(cs);
      }
    }
    if (law == 0 && first) {
      std::vector<double> plate;
      for (int k = 0; k < first->phases; ++k) plate.push_back(first->plate[k] / d);
      com.series.push_back(lineSeries(first->phase, plate, "plate", "black"));
    }
  }
  s.add(std::move(t));
  s.add(std::move(fronts));
  s.add(std::move(com));

  // Temperature profiles at the paper's phases, and the space-time plots.
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
  for (int law : {1, 0}) {
    const std::string name = kLawNames[law];
    const double T0 = derive(base_[law]).T0;
    const double Lz = base_[law].container.height;
    auto p = particles(runs, edLabel(law, fmt::format("seed {}", c_.seeds.front())));
    if (p) {
      const ImpactFronts imp = impactFronts(p->fronts);
      const double onset = imp.strong_start >= 0 ? imp.strong_start : c_.profile_phases.front();
      prof.add(profilesAtPhases(
          *p, p->temperature, 1.0 / T0, d, phasesFromImpact(c_.profile_phases, onset),
          "Particles, " + name + ": T~g(z) / T0", "T~g / T0",
          fmt::format("From the onset of the strong impact's front (t/T = {:.2f} of the "
                      "{}-cycle window), at the paper's spacing.",
                      onset, c_.window)));
      st.add(spaceTimeFigure(*p, d, Lz, "Particles, " + name,
                             fmt::format("Layer period {} T.", p->layer_period)));
    }
    auto h = hydro(runs, hydroLabel(law, "velocity"));
    if (h) {
      const ImpactFronts imp = impactFronts(h->fronts);
      const double onset = imp.strong_start >= 0 ? imp.strong_start : c_.profile_phases.front();
      prof.add(profilesAtPhases(
          *h, h->temperature, 1.0 / T0, d, phasesFromImpact(c_.profile_phases, onset),
          "Hydro, " + name + ": T(z) / T0", "T / T0",
          fmt::format("Velocity-dependent closure; from the onset of the impact front (t/T = "
                      "{:.2f}), at the paper's spacing.",
                      onset)));
      st.add(spaceTimeFigure(*h, d, Lz, "Hydro, " + name,
                             h->periodic ? fmt::format("Periodic state of period {} T.", h->period)
                                         : std::string("No periodic state was reached.")));
    }
  }
}

void WaveFrontsStudy::sweepSections(const RunSet& runs, h5::File& f, Report& report) const {
  // Layer depth (Fig. 6a).
  ReportSection& s = report.section(
      "Layer depth N (Fig. 6a)",
      fmt::format("Mean speed of the impact fronts against the number of particles (seed {}, "
                  "{:g} s per run), particles and hydro (velocity-dependent closure). The paper "
                  "finds faster fronts for deeper layers and a weak effect of wetting, with the "
                  "wet layer hitting the plate about 0.02 T earlier.",
                  c_.seeds.front(), c_.sweep_duration));
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
  for (int n : c_.counts) rows[n] = {std::to_string(n), "–", "–", "–", "–", "–", "–"};
  for (int law = 0; law < 2; ++law) {
    std::vector<double> x, y, e, xh, yh, eh, cmin;
    for (int n : c_.counts) {
      auto p = particles(runs, edLabel(law, fmt::format("N={}", n)));
      Measurement m;
      double phase = NAN;
      if (p) {
        m = impactFronts(p->fronts).all;
        phase = meanPhase(centerOfMassMinimumPhases(*p, p->cycles_per_window));
      }
      x.push_back(n);
      y.push_back(m.value);
      e.push_back(m.error);
      cmin.push_back(phase);
      rows[n][1 + law] = format(m);
      rows[n][5 + law] = formatNumber(phase);
      const std::string hl = hydroLabel(law, fmt::format("N={}", n));
      auto h = hydro(runs, hl);
      Measurement mh;
      if (h) mh = impactFronts(h->fronts).all;
      xh.push_back(n);
      yh.push_back(mh.value);
      eh.push_back(mh.error);
      rows[n][3 + law] = h ? format(mh) : "failed: " + shortReason(runs.get(hl).message);
    }
    const std::string grp = fmt::format("{}/n_sweep/{}", kRoot, kLawNames[law]);
    f.createGroup(grp);
    putSeries(f, grp + "/count", x, "1");
    putSeries(f, grp + "/ed_speed", y, "m s-1");
    putSeries(f, grp + "/ed_speed_error", e, "m s-1");
    putSeries(f, grp + "/ed_collision_phase", cmin, "1");
    putSeries(f, grp + "/hydro_speed", yh, "m s-1");
    fig.series.push_back(errorSeries(x, y, e, std::string("ED ") + kLawNames[law], kColor[law]));
    Series hs = errorSeries(xh, yh, eh, std::string("hydro ") + kLawNames[law], kColor[law]);
    hs.marker = "s";
    hs.linestyle = "--";
    fig.series.push_back(hs);
  }
  for (auto& [n, row] : rows) t.rows.push_back(row);
  s.add(std::move(fig));
  s.add(std::move(t));
  // A measured caveat, stated only when the runs show it: in deep layers the T~g peak above
  // the threshold jumps between the plate and the top of the layer, and a line through such an
  // episode is not a front speed.
  Measurement fastest;
  for (int law = 0; law < 2; ++law)
    for (int n : c_.counts)
      if (auto p = particles(runs, edLabel(law, fmt::format("N={}", n)))) {
        const Measurement m = impactFronts(p->fronts).all;
        if (m.valid() && (!fastest.valid() || m.value > fastest.value)) fastest = m;
      }
  if (fastest.valid() &&
      fastest.value > 1.5 * std::max(ed_paper_[0].all.value, ed_paper_[1].all.value))
    s.addText(fmt::format(
        "Caveat: some layers give front speeds up to {} m/s, more than 1.5 times the paper "
        "scene's. A front speed is the slope of a straight line through the heights of the "
        "T~g peak above 0.5 T0; where that peak does not travel as one maximum (in the deep "
        "layers inspected it jumps between the plate region and the top of the layer within a "
        "few phases), the slope is not a front speed. Read the trend with N from the layers "
        "whose speeds have small errors.",
        format(fastest)));

  // Wet-law parameters (Fig. 6b).
  ReportSection& w = report.section(
      "Wet-law parameters St_c and e_inf (Fig. 6b)",
      "Mean impact-front speed of the wet layer (N as in the paper's scene) as one parameter of "
      "the wet restitution law varies and the other keeps its paper value. The paper finds the "
      "fronts and the centre-of-mass trajectories unchanged within its resolution.");
  Table tw;
  tw.title = "Front speed against the wet-law parameters";
  tw.columns = {"parameter", "value", "ED wet (m/s)", "hydro wet (m/s)", "ED CM period (T)"};
  for (const auto& [key, values, label] :
       {std::tuple{"St_c", c_.stokes, "St_c"}, std::tuple{"e_inf", c_.e_inf, "e_inf"}}) {
    Figure fw;
    fw.title = std::string("Front speed against ") + label;
    fw.caption = "Particles (seed 1) and hydro (velocity-dependent closure).";
    fw.xlabel = label;
    fw.ylabel = "front speed (m/s, lab)";
    std::vector<double> y, e, yh, eh;
    for (double v : values) {
      auto p = particles(runs, edLabel(1, fmt::format("{}={}", key, g(v))));
      auto h = hydro(runs, hydroLabel(1, fmt::format("{}={}", key, g(v))));
      Measurement m = p ? impactFronts(p->fronts).all : Measurement{};
      Measurement mh = h ? impactFronts(h->fronts).all : Measurement{};
      y.push_back(m.value);
      e.push_back(m.error);
      yh.push_back(mh.value);
      eh.push_back(mh.error);
      const std::string hl = hydroLabel(1, fmt::format("{}={}", key, g(v)));
      tw.rows.push_back({label, g(v), format(m),
                         h ? format(mh) : "failed: " + shortReason(runs.get(hl).message),
                         p ? std::to_string(p->layer_period) : "–"});
    }
    const std::string grp = fmt::format("{}/{}_sweep", kRoot, key);
    f.createGroup(grp);
    putSeries(f, grp + "/value", values, "1");
    putSeries(f, grp + "/ed_speed", y, "m s-1");
    putSeries(f, grp + "/ed_speed_error", e, "m s-1");
    putSeries(f, grp + "/hydro_speed", yh, "m s-1");
    fw.series.push_back(errorSeries(values, y, e, "ED wet", kColor[1]));
    Series hs = errorSeries(values, yh, eh, "hydro wet", kColor[1]);
    hs.marker = "s";
    hs.linestyle = "--";
    fw.series.push_back(hs);
    w.add(std::move(fw));
  }
  w.add(std::move(tw));
}

void WaveFrontsStudy::costSection(const RunSet& runs, h5::File& f, Report& report) const {
  ReportSection& s = report.section(
      "Cost against accuracy",
      "Error of the wet layer's mean impact-front speed against the CPU time of the run, on the "
      "same axes. Particles: the statistical error (fit and block spread) against the number of "
      "cycles averaged; it need not fall, since the wet layer switches between periods 1 and 2 "
      "and the front speed depends on that. Hydro: the discretisation error, |v - v_ref| against "
      "the finest "
      "grid and tightest tolerance run (v_ref), which is not plotted. The dashed line is the "
      "model gap: the hydro reference minus the particles' combined value, an error no grid "
      "or tolerance removes.");
  Figure fig;
  fig.title = "Front-speed error against CPU time (wet layer)";
  fig.caption = "Log-log. Each point is one run; CPU time of the run's process.";
  fig.xlabel = "CPU time (s)";
  fig.ylabel = "front-speed error (m/s)";
  fig.xscale = "log";
  fig.yscale = "log";
  Table t;
  t.title = "Runs of the cost-accuracy chart";
  t.columns = {"method", "setting", "CPU s", "front speed (m/s)", "error (m/s)"};
  std::vector<double> ex, ey;
  for (double dur : c_.cost_durations) {
    const std::string label = edLabel(1, fmt::format("{} s", g(dur)));
    const RunRecord& r = runs.get(label);
    auto p = particles(runs, label);
    if (!p) continue;
    const Measurement m = impactFronts(p->fronts).all;
    ex.push_back(r.cpu);
    ey.push_back(m.error);
    t.rows.push_back({"particles", fmt::format("{:g} s ({} cycles pooled)", dur, p->pooled_cycles),
                      formatNumber(r.cpu), format(m), formatNumber(m.error, 3)});
  }
  // Hydro: the reference is the finest grid with the tightest tolerance.
  const int ref_cells = *std::max_element(c_.cost_cells.begin(), c_.cost_cells.end());
  const double ref_rtol = *std::min_element(c_.cost_rtol.begin(), c_.cost_rtol.end());
  auto ref = hydro(runs, hydroLabel(1, fmt::format("{} cells rtol {}", ref_cells, g(ref_rtol))));
  const Measurement v_ref = ref ? impactFronts(ref->fronts).all : Measurement{};
  std::map<double, std::pair<std::vector<double>, std::vector<double>>> by_rtol;
  for (int cells : c_.cost_cells)
    for (double rtol : c_.cost_rtol) {
      const std::string label = hydroLabel(1, fmt::format("{} cells rtol {}", cells, g(rtol)));
      const RunRecord& r = runs.get(label);
      auto h = hydro(runs, label);
      const std::string setting = fmt::format("{} cells, rtol {:g}", cells, rtol);
      if (!h) {
        t.rows.push_back(
            {"hydro", setting, formatNumber(r.cpu), "failed: " + shortReason(r.message), "–"});
        continue;
      }
      const Measurement m = impactFronts(h->fronts).all;
      const bool is_ref = cells == ref_cells && rtol == ref_rtol;
      const double err = is_ref ? NAN : std::abs(m.value - v_ref.value);
      if (!is_ref && std::isfinite(err)) {
        by_rtol[rtol].first.push_back(r.cpu);
        by_rtol[rtol].second.push_back(err);
      }
      t.rows.push_back({"hydro", setting + (is_ref ? " (reference)" : ""), formatNumber(r.cpu),
                        format(m), is_ref ? "reference" : formatNumber(err, 3)});
    }
  Series eds = lineSeries(ex, ey, "particles (cycles averaged)", kColor[1]);
  eds.marker = "o";
  fig.series.push_back(eds);
  const std::string grp = kRoot + "/cost";
  f.createGroup(grp);
  putSeries(f, grp + "/ed_cpu_seconds", ex, "s");
  putSeries(f, grp + "/ed_error", ey, "m s-1");
  for (auto& [rtol, xy] : by_rtol) {
    std::vector<double> shown = xy.second;  // a zero error cannot sit on a log axis
    for (double& e : shown) e = std::max(e, 1e-4);
    Series hs = lineSeries(xy.first, shown, fmt::format("hydro, rtol {:g} (cells vary)", rtol));
    hs.marker = "s";
    fig.series.push_back(hs);
    putSeries(f, fmt::format("{}/hydro_rtol_{:g}_cpu_seconds", grp, rtol), xy.first, "s");
    putSeries(f, fmt::format("{}/hydro_rtol_{:g}_error", grp, rtol), xy.second, "m s-1");
  }
  const double gap = std::abs(v_ref.value - ed_paper_[1].all.value);
  putValue(f, grp, "model_gap", gap);
  if (std::isfinite(gap) && gap > 0)
    fig.series.push_back(horizontalLine(gap, "model gap |hydro - particles|", 0, "black"));
  s.add(std::move(fig));
  s.add(std::move(t));
}

void WaveFrontsStudy::failureSection(const RunSet& runs, h5::File& f, Report& report) const {
  ReportSection& s = report.section(
      "Where each method fails",
      "Each case below was run. Particles without the TC model (contact.tc = \"off\"): inelastic "
      "collapse, an infinite number of collisions in finite time, stops the event-driven engine "
      "(it is detected and reported with the time and the particles). Hydro: the CVODE outcome "
      "over Gamma, grid and tolerance. CV_CONSTR_FAIL means the step could not keep density and "
      "temperature positive (the inequality constraints): at a loose tolerance the error test "
      "lets a step overshoot into the vacuum above the layer or into the dense layer at impact; "
      "CV_TOO_MUCH_WORK / CV_CONV_FAILURE mean the stiff impact could not be resolved in the "
      "step budget.");
  Table tp;
  tp.title = "Particles without the TC model";
  tp.columns = {"Gamma", "dry", "wet"};
  std::vector<double> collapse_time[2];
  for (double gamma : c_.fail_gammas) {
    std::vector<std::string> row{g(gamma)};
    for (int law = 0; law < 2; ++law) {
      const RunRecord& r = runs.get(edLabel(law, fmt::format("no TC Gamma={}", g(gamma))));
      if (r.ok) {
        auto p = readParticleFields(r.fieldsPath());
        row.push_back(fmt::format("ran {:g} s, period {}", c_.fail_duration, p.layer_period));
        collapse_time[law].push_back(NAN);
      } else {
        row.push_back(shortReason(r.message));
        collapse_time[law].push_back(collapseTime(r.message));
      }
    }
    tp.rows.push_back(row);
  }
  for (int law = 0; law < 2; ++law)
    putSeries(f, fmt::format("{}/failure/ed_no_tc_collapse_time_{}", kRoot, kLawNames[law]),
              collapse_time[law], "s");
  putSeries(f, kRoot + "/failure/gamma", c_.fail_gammas, "1");

  Table th;
  th.title = "Hydro solver over Gamma, grid and tolerance";
  th.columns = {"Gamma"};
  for (int law = 0; law < 2; ++law)
    for (int cells : c_.fail_cells)
      for (double rtol : c_.fail_rtol)
        th.columns.push_back(fmt::format("{} {} cells rtol {:g}", kLawNames[law], cells, rtol));
  Image map;
  map.nx = static_cast<int>(c_.fail_gammas.size());
  map.ny = static_cast<int>(th.columns.size()) - 1;
  map.values.assign(static_cast<std::size_t>(map.nx * map.ny), NAN);
  int failures = 0;
  for (std::size_t i = 0; i < c_.fail_gammas.size(); ++i) {
    const double gamma = c_.fail_gammas[i];
    std::vector<std::string> row{g(gamma)};
    int col = 0;
    for (int law = 0; law < 2; ++law)
      for (int cells : c_.fail_cells)
        for (double rtol : c_.fail_rtol) {
          const RunRecord& r = runs.get(
              hydroLabel(law, fmt::format("Gamma={} {} cells rtol {}", g(gamma), cells, g(rtol))));
          double v = 0;
          if (r.ok) {
            const HydroFields h = readHydroFields(r.hydroPath());
            row.push_back(h.periodic ? fmt::format("ok, period {}", h.period)
                                     : fmt::format("ok, no period in {} cycles", h.cycles));
            v = 1;
          } else {
            row.push_back("fails: " + shortReason(r.message));
            ++failures;
          }
          map.values[static_cast<std::size_t>(col) * map.nx + i] = v;
          ++col;
        }
    th.rows.push_back(row);
  }
  putValue(f, kRoot + "/failure", "hydro_failures", failures);
  s.add(std::move(tp));
  s.add(std::move(th));
  Figure fm;
  fm.title = "Hydro stability map";
  fm.caption =
      "Green: the solver reached the end (1); red: CVODE failed (0). Rows, bottom to top: the "
      "columns of the table above, left to right.";
  fm.xlabel = "case index along Gamma (see table)";
  fm.ylabel = "grid / tolerance / law (table column)";
  map.x0 = -0.5;
  map.x1 = map.nx - 0.5;
  map.y0 = 0.5;
  map.y1 = map.ny + 0.5;
  map.label = "solver succeeded";
  map.cmap = "RdYlGn";
  fm.image.push_back(std::move(map));
  fm.legend = false;
  s.add(std::move(fm));
}

void WaveFrontsStudy::modelSection(const RunSet& runs, h5::File& f, Report& report) const {
  ReportSection& s = report.section(
      "The simplest model that reproduces the particles",
      "Reference: the full particle model (rotation with Coulomb friction, velocity-dependent "
      "restitution), combined over seeds. Candidates from the simplest up; a candidate "
      "reproduces the reference if its mean impact-front speed lies within 2 combined sigma and "
      "its centre-of-mass period is the reference's most frequent period over the seeds. "
      "Particle candidates run with the same seeds and are combined the same way.");
  Table t;
  t.title = "Model hierarchy against the full particle model";
  t.columns = {"layer", "model", "front speed (m/s)", "Δ / σ", "period (T)", "reproduces"};
  std::string verdicts;
  for (int law = 0; law < 2; ++law) {
    const std::string name = kLawNames[law];
    // Combined front speed, the periods of the seeds and their most frequent value.
    auto overSeeds = [&](const std::string& tag, Measurement& speed, std::string& periods) {
      std::vector<ImpactFronts> fronts;
      std::map<int, int> count;
      periods.clear();
      for (int sd : c_.seeds) {
        auto p = particles(runs, edLabel(law, fmt::format("{}seed {}", tag, sd)));
        if (!p) continue;
        fronts.push_back(impactFronts(p->fronts));
        ++count[p->layer_period];
        periods += (periods.empty() ? "" : ", ") + std::to_string(p->layer_period);
      }
      speed = combineImpactFronts(fronts).all;
      int mode = 0, best = 0;
      for (auto [period, n] : count)
        if (n > best) {
          best = n;
          mode = period;
        }
      return mode;
    };
    Measurement ref;
    std::string ref_periods;
    const int ref_period = overSeeds("", ref, ref_periods);
    t.rows.push_back({name, "particles, full model (reference)", format(ref), "0",
                      ref_periods + " (mode " + std::to_string(ref_period) + ")", "–"});
    struct Candidate {
      std::string description, label;
      bool is_hydro;
    };
    const std::vector<Candidate> candidates{
        {fmt::format("hydro, constant e = {:.3f}, Jenkins-Richman", e_eff_[law]),
         hydroLabel(law, "constant"), true},
        {"hydro, velocity-dependent closure, Jenkins-Richman", hydroLabel(law, "velocity"), true},
        {"hydro, velocity-dependent closure, Garzo-Dufty", hydroLabel(law, "Garzo-Dufty"), true},
        {fmt::format("particles, constant e = {:.3f}", e_eff_[law]), "constant e ", false},
        {"particles, no rotation (mu = 0)", "no rotation ", false},
    };
    std::string simplest;
    for (const Candidate& c : candidates) {
      Measurement m;
      int period = 0;
      std::string periods;
      if (c.is_hydro) {
        const RunRecord& run = runs.get(c.label);
        if (!run.ok) {
          t.rows.push_back(
              {name, c.description, "failed: " + shortReason(run.message), "–", "–", "no (fails)"});
          continue;
        }
        if (auto h = hydro(runs, c.label)) {
          m = impactFronts(h->fronts).all;
          period = h->periodic ? h->period : 0;
          periods = period ? std::to_string(period) : "none";
        }
      } else {
        period = overSeeds(c.label, m, periods);
        if (periods.empty()) {
          t.rows.push_back({name, c.description, "failed: every seed", "–", "–", "no (fails)"});
          continue;
        }
      }
      const double z = sigmaDistance(m, ref);
      // A candidate much less precise than the reference passes a 2-sigma test by its own
      // error bar: that says nothing, and is shown as such.
      const bool powerless = std::isfinite(m.error) && std::isfinite(ref.error) &&
                             m.error > 2 * std::max(ref.error, 1e-12);
      const bool ok = !powerless && std::isfinite(z) && std::abs(z) <= 2.0 && ref_period > 0 &&
                      period == ref_period;
      if (ok && simplest.empty()) simplest = c.description;
      t.rows.push_back({name, c.description, format(m), formatNumber(z, 1),
                        periods.empty() ? "–" : periods,
                        ok          ? "yes"
                        : powerless ? "cannot tell (error > 2x the reference's)"
                                    : "no"});
      std::string key = c.is_hydro ? c.label : "ED " + c.label;
      while (!key.empty() && key.back() == ' ') key.pop_back();
      putMeasurement(f, fmt::format("{}/models/{}", kRoot, name), key, m);
    }
    verdicts += fmt::format("{} layer: {}. ", name,
                            simplest.empty() ? "no simpler model reproduces the particles"
                                             : "simplest model that reproduces it: " + simplest);
  }
  s.add(std::move(t));
  s.addText(verdicts);

  const ImpactFronts& wet = ed_paper_[1];
  const ImpactFronts& dry = ed_paper_[0];
  summary_ = fmt::format(
      "Particles, wet layer: fronts at {} m/s after the weak and {} m/s after the strong impact "
      "(paper: 1.61 ± 0.25 and 1.95 ± 0.25; {} and {} sigma away). Dry layer: {} and {} "
      "m/s. {}",
      format(wet.weak), format(wet.strong), formatNumber(sigmaDistance(wet.weak, kPaperWeakWet), 1),
      formatNumber(sigmaDistance(wet.strong, kPaperStrongWet), 1), format(dry.weak),
      format(dry.strong), verdicts);
}

void WaveFrontsStudy::lammpsSection(const RunSet& runs, h5::File& f, Report& report) const {
  ReportSection& s = report.section(
      "The alternative a user would run: soft-sphere DEM (LAMMPS)",
      "The paper's scene with LAMMPS' granular package (studies/lammps/paper-scene.lmp: Hertz "
      "contacts of softened glass, E = 63 MPa, Tsuji damping for a binary restitution of 0.9, "
      "Mindlin friction 0.5, the same container and drive), beside the event-driven dry layer "
      "(seed 1; its restitution is close to 0.9 at the layer's impact speeds) and the hydro "
      "solver. Speeds are CPU seconds (one core each) per simulated second, measured in this "
      "study's run (CPU, not wall, time: the study runs several runs at once). The "
      "deck writes the centre of mass only, so no front speed is compared.");
  const std::string label = fmt::format("LAMMPS dry seed {}", c_.lammps_seed);
  const RunRecord& r = runs.get(label);
  Table t;
  t.title = "Soft-sphere DEM against event-driven and continuum, dry layer";
  t.columns = {"method",       "CPU s per simulated s", "CM period (T)",
               "f/2 strength", "CM mean height / d",    "front speed (m/s)"};
  const double d = base_[0].particles.diameter;
  const RunRecord& ed_run = runs.get(edLabel(0, fmt::format("seed {}", c_.seeds.front())));
  const double ed_rate = ed_run.ok ? ed_run.cpu / c_.duration : NAN;
  auto ed = particles(runs, edLabel(0, fmt::format("seed {}", c_.seeds.front())));
  if (ed) {
    double mean = 0;
    for (double z : ed->com) mean += z / d / ed->phases;
    t.rows.push_back({"event-driven (granwave)", formatNumber(ed_rate, 4),
                      std::to_string(ed->layer_period), "–", formatNumber(mean, 2),
                      format(impactFronts(ed->fronts).all)});
  }
  auto h = hydro(runs, hydroLabel(0, "velocity"));
  const RunRecord& hr = runs.get(hydroLabel(0, "velocity"));
  if (h) {
    double mean = 0;
    for (double z : h->com) mean += z / d / h->phases;
    t.rows.push_back({"hydro (granwave, velocity-dependent closure)",
                      formatNumber(hr.cpu / (h->cycles / base_[0].drive.frequency), 3),
                      std::to_string(h->period), "–", formatNumber(mean, 2),
                      format(impactFronts(h->fronts).all)});
  }
  if (!r.ok) {
    t.rows.push_back({"LAMMPS", "failed: " + r.message, "–", "–", "–", "–"});
    s.add(std::move(t));
    return;
  }
  const LammpsTrajectory l = readLammpsTrajectory(r.lammpsPath());
  const int M = 100;  // the deck's samples per cycle (its default, used by the study)
  PeriodOptions po;
  po.samples_per_cycle = M;
  const int cycles = static_cast<int>(l.com.size()) / M;
  const PeriodResult period = detectPeriod(l.com, std::max(3, cycles / 5), po);
  const double lammps_rate = r.cpu / c_.lammps_duration;
  double mean = 0;
  for (double z : l.com) mean += z / d / static_cast<double>(l.com.size());
  t.rows.push_back({"LAMMPS (soft-sphere DEM, one core)", formatNumber(lammps_rate, 3),
                    std::to_string(period.period),
                    period.strength.size() > 2 ? formatNumber(period.strength[2], 3) : "–",
                    formatNumber(mean, 2), "not available (centre of mass only)"});
  const double ratio = lammps_rate / ed_rate;
  putValue(f, kRoot + "/lammps", "cpu_per_simulated_second", lammps_rate);
  putValue(f, kRoot + "/lammps", "event_driven_cpu_per_simulated_second", ed_rate);
  putValue(f, kRoot + "/lammps", "speed_ratio", ratio);
  putValue(f, kRoot + "/lammps", "period", period.period);
  s.add(std::move(t));

  // Centre of mass folded onto two cycles over the steady part, beside the particles'.
  Figure fig;
  fig.title = "Centre of mass over two cycles: DEM, event-driven, hydro (dry)";
  fig.caption = "LAMMPS: averaged over its last 80 % of cycles, folded onto two cycles.";
  fig.xlabel = "t / T";
  fig.ylabel = "z_CM / d (lab frame)";
  std::vector<double> x(2 * M), y(2 * M, 0.0);
  std::vector<int> n(2 * M, 0);
  const int first = std::max(3, cycles / 5) * M;
  for (std::size_t i = static_cast<std::size_t>(first); i < l.com.size(); ++i) {
    const double phase = l.time[i] * base_[0].drive.frequency;
    const int k = static_cast<int>(std::lround(phase * M)) % (2 * M);
    y[k] += l.com[i] / d;
    ++n[k];
  }
  for (int k = 0; k < 2 * M; ++k) {
    x[k] = static_cast<double>(k) / M;
    y[k] = n[k] ? y[k] / n[k] : NAN;
  }
  fig.series.push_back(lineSeries(x, y, "LAMMPS (DEM)", "tab:green"));
  if (ed) fig.series.push_back(centerOfMassSeries(*ed, d, "event-driven", "tab:orange"));
  if (h) {
    Series hs = centerOfMassSeries(*h, d, "hydro", "tab:orange");
    hs.linestyle = "--";
    fig.series.push_back(hs);
  }
  s.add(std::move(fig));
  s.addText(fmt::format(
      "Measured in this run: LAMMPS takes {} CPU seconds per simulated second against {} for "
      "the event-driven engine on the same scene, a factor {}. Its centre of mass moves with "
      "period {} (f/2 strength {}), the event-driven dry layer with period {}.",
      formatNumber(lammps_rate, 2), formatNumber(ed_rate, 3), formatNumber(ratio, 0), period.period,
      period.strength.size() > 2 ? formatNumber(period.strength[2], 3) : "–",
      ed ? std::to_string(ed->layer_period) : "–"));
}

}  // namespace granwave
