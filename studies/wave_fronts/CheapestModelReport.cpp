// The wave-fronts study's report on cost per answer at equal accuracy (docs/studies.md): every
// model's CPU seconds per answer against its distance from the particles' answer, scene by
// scene, and the cheapest model that reproduces the particles.
#include <fmt/format.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "studies/wave_fronts/WaveFrontsReport.hpp"

namespace granwave {

namespace {

bool isWet(const SceneCost& s) { return s.scene.find("wet") != std::string::npos; }

std::string ratioText(double cpu, double reference_cpu) {
  if (!std::isfinite(cpu) || !(reference_cpu > 0)) return "–";
  return fmt::format("{:.3g}", cpu / reference_cpu);
}

std::string gapText(const ModelCost& m) {
  if (!std::isfinite(m.gap.value)) return "–";
  if (m.reference) return fmt::format("0 (own error {:.0f} %)", 100 * m.gap.error);
  if (!std::isfinite(m.gap.error))
    return fmt::format("{:+.0f} %, error unknown ({})", 100 * m.gap.value, m.gap_on);
  return fmt::format("{:+.0f} +- {:.0f} % ({})", 100 * m.gap.value, 100 * m.gap.error, m.gap_on);
}

std::string transitsText(const ModelCost& m) {
  if (!m.has_transits) return "–";
  return fmt::format("{} / {}", transitCell(m.transit[0]), transitCell(m.transit[1]));
}

// "1, 1, 2, 1" -> "1 (3 seeds), 2 (1 seed)"; a single period as it is.
std::string periodsText(const std::string& periods) {
  if (periods.empty()) return "–";
  std::map<std::string, int> count;
  std::vector<std::string> order;
  for (std::size_t from = 0;;) {
    const std::size_t to = periods.find(", ", from);
    const std::string p = periods.substr(from, to - from);
    if (count[p]++ == 0) order.push_back(p);
    if (to == std::string::npos) break;
    from = to + 2;
  }
  if (order.size() == 1 && count[order[0]] == 1) return order[0];
  std::string out;
  for (const std::string& p : order)
    out += fmt::format("{}{} ({} seed{})", out.empty() ? "" : ", ", p, count[p],
                       count[p] == 1 ? "" : "s");
  return out;
}

// One law's models of one kind (continuum or simpler particles) over every scene: cost
// relative to the particles' against the front's difference in per cent.
Series costAccuracySeries(const std::vector<SceneCost>& scenes, int law, bool continuum) {
  std::vector<double> x, y, e;
  for (const SceneCost& s : scenes) {
    if (isWet(s) != (law == 1)) continue;
    const double ref_cpu = s.models.front().cpu;
    for (const ModelCost& m : s.models) {
      if (m.reference || m.continuum != continuum || !std::isfinite(m.gap.value) ||
          !std::isfinite(m.cpu) || !(ref_cpu > 0))
        continue;
      x.push_back(m.cpu / ref_cpu);
      y.push_back(100 * m.gap.value);
      e.push_back(std::isfinite(m.gap.error) ? 100 * m.gap.error : 0.0);  // unknown: no bar
    }
  }
  Series sr = errorSeries(
      x, y, e, fmt::format("{}, {}", continuum ? "continuum" : "simpler particles", kLawNames[law]),
      kLawColors[law]);
  sr.marker.assign(1, continuum ? 's' : 'o');  // (a literal warns falsely in GCC 12)
  return sr;
}

// Cost relative to the particles on the same scene against the relative front difference:
// every scene on one pair of axes, the particles at (1, 0).
Figure costAccuracyFigure(const WaveFrontsConfig& c, const std::vector<SceneCost>& scenes) {
  Figure fig;
  fig.title = "Cost per answer against agreement with the particles";
  fig.xlabel = "CPU time per answer / the full particle model's on the same scene";
  fig.ylabel = "front - the particles' (% of the particles')";
  fig.xscale = "log";
  fig.legend_outside = true;
  fig.series.push_back(
      horizontalLine(0, fmt::format("within the tolerance (+-{:.0f} %)", 100 * c.front_tolerance),
                     100 * c.front_tolerance, "0.6"));
  Series cost_line = lineSeries({1.0}, {0.0}, "the particles' cost", "0.3");
  cost_line.style = "vline";
  fig.series.push_back(cost_line);
  for (int law = 0; law < kLaws; ++law)
    for (bool continuum : {true, false}) {
      Series sr = costAccuracySeries(scenes, law, continuum);
      if (!sr.x.empty()) fig.series.push_back(std::move(sr));
    }
  fig.caption = fmt::format(
      "One point per model and scene (the paper's scene and each N of the sweep): its CPU "
      "seconds per answer divided by the full particle model's on the same scene, and how far "
      "its velocity-jump front lies from the particles' (error bars: one sigma of both): on "
      "the paper's scenes the straight-line fit's speed, on the N sweep the transit through "
      "the layer's mass farthest from the particles' among those both resolve (the fit where "
      "they resolve none; no bar where the particles' transit has no error). Left of the "
      "vertical line and inside the band a model is cheaper and right; the table gives each "
      "verdict with the period. An answer: {:g} cycles of particles, or the "
      "whole continuum run (the start to its periodic state).",
      c.answer_cycles);
  if (fig.series.size() == 2)
    fig.caption +=
        " No model has a front to compare with the particles' here (the table says "
        "why): the plot is empty.";
  else
    limitYAxis(fig, -100, 100, "+-100 %", "%");
  return fig;
}

Table everyModelTable(const std::vector<SceneCost>& scenes) {
  Table t;
  t.title = "Every model's answer, cost and agreement, scene by scene";
  t.columns = {"scene",
               "model",
               "CPU-s per answer",
               "/ particles' cost",
               "front, fit (m/s)",
               "transits, mass 0.1-0.5 / 0.5-0.9 (m/s)",
               "difference from the particles",
               "period (T)",
               "reproduces",
               "judged on"};
  for (const SceneCost& s : scenes)
    for (const ModelCost& m : s.models)
      t.rows.push_back({s.scene, m.model, formatNumber(m.cpu, 3),
                        ratioText(m.cpu, s.models.front().cpu), formatOr(m.speed, "–"),
                        transitsText(m), gapText(m), periodsText(m.periods),
                        m.failed ? "no (fails)" : matchText(m.match), m.why});
  return t;
}

std::string openText(const SceneCost& s) {
  std::string out;
  for (int i : s.cheaper_open)
    out += (out.empty() ? "" : "; ") + s.models[static_cast<std::size_t>(i)].model;
  return out.empty() ? "–" : out;
}

}  // namespace

std::string cheapestModelSection(const WaveFrontsConfig& c, const WaveFrontsResults& r,
                                 Report& report) {
  ReportSection& s = report.section(
      "Cost per answer at equal accuracy: the cheapest model per scene",
      fmt::format(
          "Which model should a user run? For each scene, every model the study ran: what one "
          "answer (front speed and period) cost it in CPU seconds, and how far that answer lies "
          "from the full particle model's. A model reproduces the particles when its front "
          "lies within {:.0f} % of theirs at 95 % and its period agrees. On the paper's scenes "
          "that is the simplest-model section's test (the fitted front speed, the time in the "
          "period-2 state); on the N sweep the front is judged by its transits through the "
          "layer's mass (the transits' table), each one the particles' fronts reach, the worst "
          "verdict counting (a transit within fewer phases than a speed needs is a bound: "
          "only a speed beyond it by more than the tolerance differs), and by the fit only "
          "where the particles' fronts reach neither. The cheapest one that does is named. The "
          "full particle model always answers, so it is named where nothing cheaper reproduces "
          "it. CPU times are this machine's, measured in this study.",
          100 * c.front_tolerance));
  s.add(costAccuracyFigure(c, r.cheapest));
  Table t;
  t.title = "The cheapest model that reproduces the particles";
  t.columns = {"scene", "cheapest model that reproduces", "CPU-s per answer", "/ particles' cost",
               "cheaper, not yet decided"};
  std::vector<std::string> cheaper_and_right;
  for (const SceneCost& sc : r.cheapest) {
    const ModelCost& m = sc.models[static_cast<std::size_t>(sc.cheapest)];
    t.rows.push_back({sc.scene, m.model, formatNumber(m.cpu, 3),
                      ratioText(m.cpu, sc.models.front().cpu), openText(sc)});
    if (m.continuum) cheaper_and_right.push_back(sc.scene);
  }
  s.add(std::move(t));
  s.add(everyModelTable(r.cheapest));
  const std::string where = cheaper_and_right.empty()
                                ? std::string("on none of the scenes run")
                                : fmt::format("on {}", fmt::join(cheaper_and_right, "; "));
  s.addText(fmt::format("The continuum is both cheaper and right {} ({} of {} scenes).", where,
                        cheaper_and_right.size(), r.cheapest.size()));
  // The headline (results.h5's root summary) names the models but quotes no CPU time: those
  // are this machine's measurements and live under /cost with the section's tables.
  std::string line = "Cheapest model that reproduces the particles (by CPU time per answer): ";
  for (std::size_t k = 0; k < r.cheapest.size() && k < 2; ++k) {
    const SceneCost& sc = r.cheapest[k];
    line += fmt::format("{}{}: {}", k ? "; " : "", sc.scene,
                        sc.models[static_cast<std::size_t>(sc.cheapest)].model);
  }
  return line + fmt::format("; the continuum is cheaper and right {}.", where);
}

}  // namespace granwave
