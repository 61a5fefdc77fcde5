#include "studies/stability/StabilityReport.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "studies/contract/FailureReason.hpp"
#include "studies/stability/StabilityOverSeedsReport.hpp"
#include "studies/statistics/Measurement.hpp"

namespace granwave {

namespace {

const char* kStateColor[3] = {"tab:blue", "tab:green", "tab:orange"};

// "liquid-like (3/3), period 2 (2/3), psi6 0.63, bonds kept 0.07 over 15 cycles, 0.56 over
// one, surface wave 2/3 (mode 2, 1.7 d)"; the failed seeds and their first reason.
std::string describe(const LayerVerdict& v) {
  std::string s;
  if (v.failed > 0)
    s = fmt::format("{} of {} seeds failed: {}", v.failed, v.runs, shortReason(v.failure));
  if (v.period.of == 0) return s;
  if (!s.empty()) s += "; ";
  if (!v.classified())
    return s + fmt::format("period {} ({}/{}), not classified", v.period.value, v.period.count,
                           v.period.of);
  s += fmt::format(
      "{} ({}/{}), period {} ({}/{}), psi6 {:.2f}, bonds kept {:.2f} over 15 cycles, {:.2f} "
      "over one",
      v.state.value, v.state.count, v.state.of, v.period.value, v.period.count, v.period.of, v.psi6,
      v.bonds_kept, v.bonds_kept_per_cycle);
  s += fmt::format(
      "; within one cycle {} ({}/{}), {:.1f} neighbours and psi6 {:.2f} when most compact, "
      "{:.1f} particles on the lid",
      v.within_cycle_state.value, v.within_cycle_state.count, v.within_cycle_state.of,
      v.within_cycle_coordination, v.within_cycle_psi6, v.lid_row);
  const int waves =
      v.surface_wave.value ? v.surface_wave.count : v.surface_wave.of - v.surface_wave.count;
  if (waves > 0)
    s += fmt::format(", surface wave {}/{} (mode {}, {:.1f} d)", waves, v.surface_wave.of,
                     v.surface_wave_mode, v.surface_wave_amplitude_d);
  const int kinks = v.kinks.value ? v.kinks.count : v.kinks.of - v.kinks.count;
  if (kinks > 0) s += fmt::format(", kinks {}/{}", kinks, v.kinks.of);
  return s;
}

std::string describe(const HydroPoint& h) {
  if (!h.run) return "not run";
  if (!h.ok) return "fails: " + shortReason(h.failure);
  const std::string regime = h.regime == "fluidised" ? "" : "; " + h.regime;
  return (h.periodic ? fmt::format("period {}", h.period) : "no period") + regime;
}

Series points(std::vector<double> x, std::vector<double> y, std::string label, std::string color,
              std::string marker) {
  Series s = lineSeries(std::move(x), std::move(y), std::move(label), std::move(color));
  s.style = "points";
  s.marker = std::move(marker);
  return s;
}

// Grid spacing, for the offset of the disagreement marker beside a point.
double spacing(const std::vector<double>& v) {
  return v.size() > 1
             ? (*std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end())) /
                   static_cast<double>(v.size() - 1)
             : 1.0;
}

Figure diagram(const StabilityConfig& c, const StabilityGrid& grid, int law,
               SolidCriterion criterion) {
  Figure fig;
  fig.title =
      fmt::format("Stability diagram, {} (state: {})", kLawNames[law], criterionName(criterion));
  fig.caption =
      "Particles, the most frequent verdict over the seeds. Unclassified or failed points are "
      "left blank; a grey star beside a point: its seeds disagree (either state, period, waves "
      "or kinks), or some of them failed; the table gives the votes.";
  fig.xlabel = "Gamma";
  fig.ylabel = "f (Hz)";
  fig.legend_outside = true;
  const std::size_t NF = c.frequencies.size(), NG = c.gammas.size();
  std::vector<double> sx[3], sy[3], wx, wy, kx, ky, px, py, ux, uy;
  const double dg = 0.3 * spacing(c.gammas), df = 0.3 * spacing(c.frequencies);
  for (std::size_t i = 0; i < NF; ++i)
    for (std::size_t j = 0; j < NG; ++j) {
      const LayerVerdict& v = grid.at(law, i, j);
      const double x = c.gammas[j], y = c.frequencies[i];
      const auto st =
          std::find(kLayerStates.begin(), kLayerStates.end(), v.stateBy(criterion).value);
      if (v.classified() && st != kLayerStates.end())
        sx[st - kLayerStates.begin()].push_back(x), sy[st - kLayerStates.begin()].push_back(y);
      if (v.classified() && v.surface_wave.value) wx.push_back(x), wy.push_back(y);
      if (v.classified() && v.kinks.value) kx.push_back(x), ky.push_back(y);
      if (v.period.of > 0 && v.period.value >= 2) px.push_back(x), py.push_back(y);
      if (v.classified() && !v.seedsAgree()) ux.push_back(x + dg), uy.push_back(y + df);
    }
  for (std::size_t si = 0; si < kLayerStates.size(); ++si)
    fig.series.push_back(points(sx[si], sy[si], kLayerStates[si], kStateColor[si], "s"));
  fig.series.push_back(points(wx, wy, "surface waves", "red", "^"));
  fig.series.push_back(points(kx, ky, "kinks", "black", "x"));
  fig.series.push_back(points(px, py, "period >= 2", "black", "."));
  fig.series.push_back(points(ux, uy, "seeds disagree", "grey", "*"));
  return fig;
}

// Differences dry - wet in the paper's symbols.
Figure differences(const StabilityConfig& c, const StabilityGrid& grid) {
  Figure diff;
  diff.title = "Where dry and wet differ";
  diff.caption =
      "Points where the dry and the wet layer differ in a symbol of the paper's diagram (state, "
      "surface waves, kinks; most frequent over the seeds), and, separately, in the "
      "centre-of-mass period, which the paper's diagram does not show.";
  diff.xlabel = "Gamma";
  diff.ylabel = "f (Hz)";
  diff.legend_outside = true;
  std::vector<double> dx, dy, qx, qy, wx, wy;
  const double dg = 0.15 * spacing(c.gammas);
  for (std::size_t i = 0; i < c.frequencies.size(); ++i)
    for (std::size_t j = 0; j < c.gammas.size(); ++j) {
      if (grid.symbolsDiffer(i, j)) dx.push_back(c.gammas[j]), dy.push_back(c.frequencies[i]);
      if (grid.symbolsDiffer(i, j, SolidCriterion::within_cycle))
        wx.push_back(c.gammas[j] + dg), wy.push_back(c.frequencies[i]);
      if (grid.periodsDiffer(i, j)) qx.push_back(c.gammas[j]), qy.push_back(c.frequencies[i]);
    }
  diff.series.push_back(points(dx, dy, "state (bonds), waves or kinks differ", "purple", "D"));
  diff.series.push_back(
      points(wx, wy, "state (within one cycle), waves or kinks differ", "tab:cyan", "o"));
  diff.series.push_back(points(qx, qy, "period differs", "black", "+"));
  return diff;
}

Table everyPoint(const StabilityConfig& c, const StabilityResults& r) {
  Table t;
  t.title = "Every point of the grid";
  t.caption =
      "Particles: the most frequent state and period over the seeds with their votes, the mean "
      "<|psi6|> and bonds kept (over the 15 cycles, which decides, and from one cycle to the "
      "next, reported) over the classified seeds; the state within one cycle with the mean "
      "neighbour count and <|psi6|> at each cycle's most compact phase, and the particles "
      "pressed against the lid (within 0.1 d) at the fullest phase of a cycle; how many seeds "
      "show surface waves or kinks (the detector the diagrams draw). Beside it the surface "
      "waves from the space-time spectrum of the surface (windows of 10 cycles pooled over "
      "the seeds; docs/classification.md). Hydro: one run per point (the continuum has no "
      "seed).";
  t.columns = {
      "f (Hz)",           "Gamma",     "dry (particles)", "wet (particles)", "dry f/2 spectrum",
      "wet f/2 spectrum", "hydro dry", "hydro wet",       "hydro rough dry", "hydro rough wet"};
  const std::size_t NG = c.gammas.size();
  for (std::size_t i = 0; i < c.frequencies.size(); ++i)
    for (std::size_t j = 0; j < NG; ++j) {
      const std::size_t k = i * NG + j;
      t.rows.push_back({formatCompact(c.frequencies[i]), formatCompact(c.gammas[j]),
                        describe(r.grid.at(0, i, j)), describe(r.grid.at(1, i, j)),
                        describe(r.spectrum[0][k]), describe(r.spectrum[1][k]),
                        describe(r.hydro[0][k]), describe(r.hydro[1][k]),
                        describe(r.hydro_rough[0][k]), describe(r.hydro_rough[1][k])});
    }
  return t;
}

// One line per law against Gamma at frequency index i0: `value` of the classified verdicts.
template <class Value>
void lawLines(Figure& fig, const StabilityGrid& grid, std::size_t i0, const std::string& what,
              const std::string& linestyle, const Value& value) {
  const char* color[2] = {"tab:red", "tab:blue"};
  for (int law = 0; law < kLaws; ++law) {
    std::vector<double> x, y;
    for (std::size_t j = 0; j < grid.gammas.size(); ++j) {
      const LayerVerdict& v = grid.at(law, i0, j);
      if (!v.classified()) continue;
      x.push_back(grid.gammas[j]);
      y.push_back(value(v));
    }
    Series sr = lineSeries(x, y, std::string(kLawNames[law]) + what, color[law]);
    sr.marker = linestyle == "-" ? "o" : "s";
    sr.linestyle = linestyle;
    fig.series.push_back(sr);
  }
}

// The within-cycle criterion's two numbers at each cycle's most compact phase.
Figure compactPhaseFigure(const StabilityGrid& grid, std::size_t i0) {
  Figure fig;
  fig.title = fmt::format("Within one cycle against Gamma at f = {:g} Hz", grid.frequencies[i0]);
  fig.caption =
      "At each cycle's most compact sampled phase, mean over cycles and classified seeds: "
      "neighbours within 1.2 d per particle (solid lines; at least 4, the isostatic count of "
      "disks, for a caged layer) and <|psi6|> (dashed; above 0.7 a crystal).";
  fig.xlabel = "Gamma";
  fig.ylabel = "neighbours; <|psi6|>";
  lawLines(fig, grid, i0, ", neighbours", "-",
           [](const LayerVerdict& v) { return v.within_cycle_coordination; });
  lawLines(fig, grid, i0, ", <|psi6|>", "--",
           [](const LayerVerdict& v) { return v.within_cycle_psi6; });
  fig.series.push_back(horizontalLine(4.0, "caged from here (neighbours)", 0, "black"));
  fig.series.push_back(horizontalLine(0.7, "crystal from here (psi6)", 0, "grey"));
  fig.legend_outside = true;
  return fig;
}

Figure lidFigure(const StabilityGrid& grid, std::size_t i0) {
  Figure fig;
  fig.title = fmt::format("Particles pressed against the lid at f = {:g} Hz", grid.frequencies[i0]);
  fig.caption =
      "Particles whose top is within 0.1 d of the lid at the fullest sampled phase of a cycle "
      "(10 phases per cycle), mean over the last 16 cycles and the classified seeds. In the "
      "paper's "
      "box, 30 d wide, about 30 particles make a full row.";
  fig.xlabel = "Gamma";
  fig.ylabel = "particles on the lid";
  lawLines(fig, grid, i0, "", "-", [](const LayerVerdict& v) { return v.lid_row; });
  return fig;
}

void featuresSection(const StabilityResults& r, ReportSection& section) {
  const StabilityGrid& grid = r.grid;
  section.add(featuresTable(r));
  section.add(differencesTable(r));

  // Caging against Gamma at the lowest f: does the layer solidify again, over the 15 cycles
  // that decide or over one cycle (closer to the paper's look at one free flight)?
  const std::size_t i0 = lowestFrequency(grid);
  Figure fig;
  fig.title = fmt::format("Caging against Gamma at f = {:g} Hz", grid.frequencies[i0]);
  fig.caption =
      "Fraction of neighbour bonds kept, mean over the classified seeds: over the 15 cycles the "
      "classifier uses (solid lines; caged, i.e. crystal or amorphous, at 0.5 or more) and from "
      "one cycle to the next (dashed). The paper's layers are solid again at Gamma >= 6.";
  fig.xlabel = "Gamma";
  fig.ylabel = "bonds kept";
  const char* color[2] = {"tab:red", "tab:blue"};
  for (int law = 0; law < kLaws; ++law) {
    std::vector<double> x, b15, b1;
    for (std::size_t j = 0; j < grid.gammas.size(); ++j) {
      const LayerVerdict& v = grid.at(law, i0, j);
      if (!v.classified()) continue;
      x.push_back(grid.gammas[j]);
      b15.push_back(v.bonds_kept);
      b1.push_back(v.bonds_kept_per_cycle);
    }
    Series a = lineSeries(x, b15, std::string(kLawNames[law]) + ", 15 cycles", color[law]);
    a.marker = "o";
    Series b = lineSeries(x, b1, std::string(kLawNames[law]) + ", one cycle", color[law]);
    b.marker = "s";
    b.linestyle = "--";
    fig.series.push_back(a);
    fig.series.push_back(b);
  }
  fig.series.push_back(horizontalLine(0.5, "caged from here (15 cycles)", 0, "black"));
  section.add(std::move(fig));

  section.add(compactPhaseFigure(grid, i0));
  section.add(lidFigure(grid, i0));

  // Wet surface waves where the dry layer has none, at the lowest f: the reverse of the paper.
  bool reversed = false;
  for (std::size_t j = 0; j < grid.gammas.size(); ++j) {
    const LayerVerdict &a = grid.at(0, i0, j), &b = grid.at(1, i0, j);
    reversed |= b.classified() && b.surface_wave.value && !(a.classified() && a.surface_wave.value);
  }
  if (reversed)
    section.addText(
        "Why the surface waves differ (measured, docs/fields.md and docs/physics.md): with the "
        "paper's laws, the dry layer's restitution is about 0.9 at its impact speeds, and at "
        "f = 10 Hz, Gamma = 4 it moves with period 1 without the f/2 standing wave; the wet "
        "layer, whose slow collisions are completely inelastic, doubles its period and carries "
        "a standing f/2 wave. A constant-restitution scan puts the switch between e = 0.9 "
        "(period 1) and e = 0.8 (period 2), as soft-sphere DEM does. The paper reports the "
        "reverse pattern; the particle model here follows its stated laws, nothing was tuned.");
}

// The last recorded frame of a few runs per state, to check the classification by eye.
void gallerySection(const StabilityConfig& c, const StabilityResults& r, Report& report) {
  ReportSection& gal = report.section(
      "Snapshot gallery", "The last recorded frame (one per cycle, at phase 0) of up to " +
                              std::to_string(c.gallery_per_state) +
                              " runs per state, so the classification can be checked by eye.");
  for (const GallerySnapshot& s : r.gallery) {
    const LayerPatterns& p = s.patterns;
    Figure fg;
    fg.title = fmt::format("{}: {} f = {:g} Hz, Gamma = {:g}, seed {}", kLayerStates[s.state],
                           kLawNames[s.law], s.frequency, s.gamma, s.seed);
    fg.caption = fmt::format(
        "psi6 {:.2f}, bonds kept {:.2f} over 15 cycles, {:.2f} over one, period {}{}", p.psi6,
        p.bonds_kept, p.bonds_kept_per_cycle, p.period, p.surface_wave ? ", surface wave" : "");
    fg.xlabel = "x / d";
    fg.ylabel = "z / d";
    fg.series.push_back(points(s.x, s.z, "particles", kStateColor[s.state], "o"));
    fg.series.push_back(lineSeries({0, s.width}, {s.plate, s.plate}, "plate", "black"));
    fg.legend = false;
    gal.add(std::move(fg));
  }
}

std::string method(const StabilityConfig& c) {
  std::string seeds;
  for (int sd : c.seeds) seeds += (seeds.empty() ? "" : ", ") + std::to_string(sd);
  return fmt::format(
      "Each (f, Gamma) point is {} particle run(s) of {:g} cycles (seeds {}), each classified "
      "live over its last 16 cycles at the free-flight phase (docs/classification.md): "
      "crystal / amorphous / liquid-like from the hexatic order and the bonds kept over 15 "
      "cycles, standing surface waves, kinks, and the centre-of-mass period; and a second "
      "state, each of the 16 cycles judged on its own at its most compact sampled phase "
      "(liquid-like below 4 neighbours within 1.2 d per particle, else crystal above <|psi6|> "
      "0.7, else amorphous; the most frequent over the cycles), closer to the paper's "
      "inspection of one flight. Both criteria give the known state of equilibrium hard disks "
      "away from freezing (docs/classification.md). A point's label "
      "is the most frequent over its seeds (ties: the first seed listed). Markers: squares "
      "coloured by state; red triangles: surface waves; black crosses: kinks; a black dot: "
      "period 2 or more. A layer is caged (crystal or amorphous) when it keeps at least half "
      "of its neighbour bonds over the 15 cycles. This rule replaced a per-cycle mobility "
      "threshold after that threshold called the f = 10 Hz, Gamma = 2 layer liquid-like "
      "although it keeps 81 % of its bonds with <|psi6|> = 0.90 (the paper: solid there); "
      "the reasons, and what the old rule gave, are in docs/classification.md.",
      c.seeds.size(), c.cycles, seeds);
}

// How often a continuum closure has the particles' period (their most frequent over the seeds),
// and whether it has their dry/wet split where the particles' dry and wet periods differ.
std::string continuumAgreement(const StabilityConfig& c, const StabilityResults& r,
                               const std::vector<HydroPoint> (&hydro)[2], const char* name) {
  const std::size_t NG = c.gammas.size();
  int compared = 0, same = 0, splits = 0, split_same = 0;
  for (std::size_t k = 0; k < c.frequencies.size() * NG; ++k) {
    int ed[2], hy[2];
    bool both = true;
    for (int law = 0; law < kLaws; ++law) {
      const LayerVerdict& v = r.grid.at(law, k / NG, k % NG);
      const HydroPoint& h = hydro[law][k];
      ed[law] = v.period.of > 0 ? v.period.value : -1;
      hy[law] = h.ok && h.periodic ? h.period : -2;
      both = both && ed[law] > 0 && h.run && h.ok;
      if (ed[law] > 0 && h.run && h.ok) {
        ++compared;
        same += hy[law] == ed[law];
      }
    }
    if (!both || ed[0] == ed[1]) continue;
    ++splits;
    split_same += hy[0] == ed[0] && hy[1] == ed[1];
  }
  return fmt::format(
      "{}: the particles' period at {} of {} comparable point-layers; of the {} points where the "
      "particles' dry and wet periods differ, it reproduces both at {}.",
      name, same, compared, splits, split_same);
}

// The headline, one answer per line: the grid, then the dry-wet differences per frequency,
// with the state by each solid criterion, then in the period.
std::string summary(const StabilityConfig& c, const StabilityResults& r) {
  std::string per_f, period_per_f, within_per_f;
  for (std::size_t i = 0; i < c.frequencies.size(); ++i) {
    within_per_f += fmt::format("{}{:g} Hz: {:g}", i ? ", " : "", c.frequencies[i],
                                r.symbol_differences_within_cycle[i]);
    per_f +=
        fmt::format("{}{:g} Hz: {:g}", i ? ", " : "", c.frequencies[i], r.symbol_differences[i]);
    period_per_f +=
        fmt::format("{}{:g} Hz: {:g}", i ? ", " : "", c.frequencies[i], r.period_differences[i]);
  }
  return fmt::format(
      "- Grid: {} points per law (f = {:g} to {:g} Hz, Gamma = {:g} to {:g}, so {} Gamma values "
      "per frequency), {} seed(s) each.\n"
      "- Points where dry and wet differ in state, surface waves or kinks (the state solid by {}), "
      "per frequency: {}.\n"
      "- The same with the state judged {}: {}.\n"
      "- Points where dry and wet differ in the period, per frequency: {}.\n",
      c.frequencies.size() * c.gammas.size(), c.frequencies.front(), c.frequencies.back(),
      c.gammas.front(), c.gammas.back(), c.gammas.size(), c.seeds.size(),
      criterionName(SolidCriterion::bonds), per_f, criterionName(SolidCriterion::within_cycle),
      within_per_f, period_per_f);
}

}  // namespace

void reportStability(const StabilityConfig& c, const StabilityResults& r, Report& report) {
  ReportSection& s = report.section("Stability diagrams", method(c));
  for (SolidCriterion criterion : kSolidCriteria)
    for (int law = 0; law < kLaws; ++law) s.add(diagram(c, r.grid, law, criterion));
  s.add(differences(c, r.grid));
  ReportSection& q = report.section(
      "The paper's features, point by point",
      "Huang, Sec. III: at f = 10 Hz both layers fluidize as Gamma rises from 2 and solidify "
      "again at Gamma >= 6 (lid contact); for Gamma in [3, 5] the dry layer shows surface waves "
      "and the wet one does not; at Gamma ~ 5 both crystallize again as f rises; the dry-wet "
      "differences shrink as f rises. The first three are checked at the grid's lowest "
      "frequency. A difference is one in the paper's symbols (state, surface waves, kinks); "
      "the periods are compared separately. Every check involving the state is made with each "
      "solid criterion.");
  featuresSection(r, q);
  s.add(everyPoint(c, r));
  if (c.hydro)
    s.addText("Continuum against particles. " +
              continuumAgreement(c, r, r.hydro, "Smooth-disk hydro") +
              (c.hydro_rough ? " " + continuumAgreement(c, r, r.hydro_rough, "Rough-particle hydro")
                             : std::string()));
  gallerySection(c, r, report);
  report.summary = summary(c, r);
}

}  // namespace granwave
