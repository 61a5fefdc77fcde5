#include "studies/wave_fronts/WaveFrontsReport.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include "scene/SceneDerived.hpp"
#include "studies/contract/FailureReason.hpp"
#include "studies/wave_analysis/FieldFigures.hpp"

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
      "the centre of mass). Errors are one sigma; '–': the paper gives no such number.";
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

// A T~g-peak front speed, or why there is none.
std::string peakCell(const Measurement& m) {
  return formatOr(m, "none: no T~g peak above 0.5 T0 rose from an impact");
}

// One law's rows of the paper table and its series in the front and centre-of-mass figures.
void paperLaw(const WaveFrontsConfig& c, int law, const PaperLaw& p, Table& t, Figure& fronts,
              Figure& com) {
  const double d = c.scenes.base[0].particles.diameter;
  const std::string name = kLawNames[law];
  t.rows.push_back(
      {fmt::format("ED {} ({} seed{} × {:g} s)", name, p.seeds_used, p.seeds_used == 1 ? "" : "s",
                   c.duration),
       peakCell(p.ed.weak), peakCell(p.ed.strong), peakCell(p.ed.all),
       formatOr(p.tracked.speed, p.tracked.why_none.empty() ? "none" : p.tracked.why_none),
       periodList(p.periods), formatNumber(p.collision_phase)});
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
        {row, peakCell(h.fronts.weak), peakCell(h.fronts.strong), peakCell(h.fronts.all),
         formatOr(h.tracked, "none: no velocity-jump front resolved"),
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
  // The box moves with the plate: in its frame the layer lives between 0 and the lid.
  double box = 0;
  for (const Scene& sc : c.scenes.base)
    box = std::max(box, sc.container.height / sc.particles.diameter);
  fronts.series.push_back(horizontalLine(box, "lid", 0, "grey"));
  limitYAxis(fronts, 0.0, box, "the box (plate to lid)", "d");
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

// One impact's velocity-jump front as the headline states it, beside the paper's if given.
std::string frontAnswer(const Measurement& m, const std::string& impact, const Measurement* paper) {
  if (!m.valid()) return fmt::format("none measured after the {} impact", impact);
  std::string s = fmt::format("{} after the {} impact", format(m, 2, "m/s"), impact);
  if (paper)
    s += fmt::format(" (paper {}: {} sigma away)", format(*paper, 2, "m/s"),
                     formatNumber(std::abs(sigmaDistance(m, *paper)), 1));
  return s;
}

// A layer's velocity-jump fronts after its weak and strong impacts, or why there are none.
std::string frontsAnswer(const VelocityFronts& v, bool paper) {
  if (!v.weak.valid() && !v.strong.valid())
    return "none measured after either impact (" +
           (v.why_none.empty() ? std::string("no velocity-jump front matched to them")
                               : v.why_none) +
           ")";
  return frontAnswer(v.weak, "weak", paper ? &kPaperWeakWet : nullptr) + "; " +
         frontAnswer(v.strong, "strong", paper ? &kPaperStrongWet : nullptr);
}

// The report's headline, one answer per line: the wet and dry fronts against the paper's, the
// models' verdicts, the wet layer's time in the period-2 state.
void summarise(const WaveFrontsResults& r, const std::vector<std::string>& verdicts,
               Report& report) {
  const VelocityFronts& wet = r.paper[1].tracked;
  const VelocityFronts& dry = r.paper[0].tracked;
  std::string lines = fmt::format(
      "- Wet layer, particles, velocity-jump fronts: {}.\n"
      "- Dry layer, particles, velocity-jump fronts (the paper gives none): {}.\n",
      frontsAnswer(wet, true), frontsAnswer(dry, false));
  for (const std::string& v : verdicts) lines += "- " + v + "\n";
  const StateShares& st = r.states[1];
  if (st.windows > 0)
    lines += fmt::format(
        "- Wet layer's state: period 2 for {:.0f} % of the time (95 % interval {:.0f}–{:.0f} %, "
        "from {} windows of its runs); {} of {} seeds have period 2 over the whole run.\n",
        100 * st.time_share, 100 * st.time_low, 100 * st.time_high, st.windows, st.seeds_period2,
        st.seeds);
  report.summary = lines;
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
  energyBudgetSection(r, report);
  std::vector<std::string> verdicts = modelSection(c, r.models, report);
  verdicts.push_back(cheapestModelSection(c, r, report));
  summarise(r, verdicts, report);
  if (r.lammps) lammpsSection(c, *r.lammps, r.paper[0].seed1, r.paper[0].hydro[0], report);
}

}  // namespace granwave
