#include "studies/continuum_sensitivity/ContinuumSensitivityReport.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "studies/statistics/Measurement.hpp"

namespace granwave {

namespace {

std::string percent(double change) {
  if (std::isinf(change)) return "changed";
  if (std::isnan(change)) return "undetermined";
  return fmt::format("{:.1f} %", 100 * change);
}

// The fit's change, and in units of the fits' combined error where both fronts have one.
std::string fitChangeText(const SensitivityChange& c) {
  if (!std::isfinite(c.fit) || std::isnan(c.fit_sigma)) return percent(c.fit);
  return fmt::format("{} ({:.1f} sigma)", percent(c.fit), c.fit_sigma);
}

std::string transitsText(const SensitivityFront& f) {
  std::vector<std::string> t;
  for (const SensitivityTransit& x : f.transits)
    t.push_back(!x.reached   ? "-"
                : x.resolved ? formatNumber(x.speed, 2)
                             : "> " + formatNumber(x.speed, 0));
  return t.empty() ? std::string() : fmt::format(" [{}]", fmt::join(t, ", "));
}

std::string periodText(const SensitivityAnswer& a) {
  if (!a.ok) return "failed";
  const std::string p = a.period > 0 ? fmt::format("{}T", a.period) : "not periodic";
  if (a.solver_period == a.period) return p;
  return p +
         (a.solver_period > 0 ? fmt::format(" (solver {}T)", a.solver_period) : " (solver: none)");
}

std::string frontsText(const SensitivityAnswer& a) {
  if (!a.ok) return "-";
  if (a.fronts.empty()) return "none";
  std::string s;
  for (const SensitivityFront& f : a.fronts) {
    if (!s.empty()) s += ", ";
    if (f.bulk) s += fmt::format("bulk > {} then ", formatNumber(f.bulk_speed, 0));
    s += f.resolved ? formatNumber(f.speed, 2) + " +- " + formatNumber(f.fit_error, 2)
                    : "> " + formatNumber(f.speed, 0);
    s += transitsText(f);
  }
  return s;
}

std::string variantName(const SensitivityVariant& v) {
  if (v.parameter.empty()) return "base";
  return fmt::format("{} x{} ({})", v.parameter, formatCompact(v.factor), formatCompact(v.value));
}

Table caseTable(const ContinuumSensitivityConfig& config, std::size_t k,
                const SensitivityCaseResult& c) {
  const double d = config.scenes.base[config.cases[k].law].particles.diameter;
  Table t;
  t.title = fmt::format("{} ({})", config.cases[k].name, kLawNames[config.cases[k].law]);
  t.caption = fmt::format(
      "Each run against the base: period (at the tolerance; the solver's stricter one in brackets "
      "where it differs), the centre of mass's mean lowest and highest point "
      "per cycle above the plate (in diameters), the largest relative change of either (of the "
      "base's excursion), the velocity-jump fronts of the window (m/s: the straight line through "
      "the track, +- its standard error, and in brackets the transit speeds between the layer's "
      "mass fractions {}; '> x': faster than the sampling resolves, with its bound; '-': not "
      "reached; 'bulk > x then': the impact crossed the packed bottom within one phase, faster "
      "than x), the largest relative change of a matched front's transits (a front reaching "
      "none: of its fit) and of its fit, with the fit's change in units of the two fits' "
      "combined error. Within tolerance: the same period and the centre-of-mass and transit "
      "changes below {:.0f} %.",
      fmt::join(config.front_fractions, ", "), 100 * config.tolerance);
  t.columns = {"run",        "period",       "centre of mass (d)",
               "change",     "fronts (m/s)", "transit change",
               "fit change", "within",       "CPU s"};
  for (std::size_t v = 0; v < c.answers.size(); ++v) {
    const SensitivityAnswer& a = c.answers[v];
    const SensitivityChange& ch = c.changes[v];
    const bool base = v == 0;
    t.rows.push_back(
        {variantName(config.variants[k][v]), periodText(a),
         a.ok ? fmt::format("{:.2f}-{:.2f}", a.com_low / d, a.com_high / d) : a.failure,
         base ? "(base)" : percent(ch.com), frontsText(a), base ? "(base)" : percent(ch.front),
         base ? "(base)" : fitChangeText(ch), base ? "(base)" : (ch.within ? "yes" : "no"),
         formatNumber(a.cpu_seconds, 1)});
  }
  return t;
}

// The larger of a variant's two changes against its factor, one series per parameter, with
// the tolerance: what moved, and by how much, at a glance. A front that appeared or vanished
// (an infinite change) is drawn at the top of the axis and said in the caption.
Figure caseFigure(const ContinuumSensitivityConfig& config, std::size_t k,
                  const SensitivityCaseResult& c) {
  Figure f;
  f.title = fmt::format("{}: largest change per variant", config.cases[k].name);
  f.xlabel = "factor on the parameter";
  f.ylabel = "largest change of the centre-of-mass range or a front (%)";
  f.xscale = "log";
  f.legend_outside = true;
  int changed = 0;
  for (const std::string& parameter : config.parameters) {
    Series s;
    s.style = "points";
    s.label = parameter;
    for (std::size_t v = 1; v < c.changes.size(); ++v) {
      if (config.variants[k][v].parameter != parameter) continue;
      const double worst = std::max(c.changes[v].com, c.changes[v].front);
      changed += std::isfinite(worst) ? 0 : 1;
      s.x.push_back(config.variants[k][v].factor);
      s.y.push_back(std::isfinite(worst) ? 100 * worst : 100.0);
    }
    f.series.push_back(std::move(s));
  }
  f.series.push_back(horizontalLine(100 * config.tolerance, "tolerance"));
  f.caption = fmt::format(
      "Each point is one run with one parameter scaled by the factor: the larger of its "
      "centre-of-mass and front changes against the base run. {}",
      changed == 0
          ? std::string("No front appeared or vanished.")
          : fmt::format("{} run(s) gained or lost a front or failed: drawn at 100 %.", changed));
  return f;
}

// One case's answer: how many variants stay within the tolerance, and for each that does not,
// what moved it out (the tests of sensitivityChange: failed run, period, centre of mass, front).
std::string caseAnswer(const ContinuumSensitivityConfig& config, std::size_t k,
                       const SensitivityCaseResult& c) {
  std::string outside;
  for (std::size_t v = 1; v < c.changes.size(); ++v) {
    const SensitivityChange& ch = c.changes[v];
    if (ch.within) continue;
    std::vector<std::string> why;
    if (!c.answers[0].ok || !c.answers[v].ok) {
      why.push_back("a run failed");
    } else {
      if (!ch.same_period) why.push_back("period changed");
      if (!(ch.com < config.tolerance)) why.push_back("centre of mass moved " + percent(ch.com));
      if (std::isnan(ch.front))
        why.push_back("a transit resolved in one run only (the sampling cannot tell)");
      else if (!(ch.front < config.tolerance))
        why.push_back(std::isinf(ch.front) ? "a front or transit appeared or vanished"
                                           : "front's transit moved " + percent(ch.front));
    }
    outside += fmt::format("{}{} ({})", outside.empty() ? "" : "; ",
                           variantName(config.variants[k][v]), fmt::join(why, ", "));
  }
  return fmt::format("- {} ({}): {} of {} within; {}.\n", config.cases[k].name,
                     kLawNames[config.cases[k].law], c.within, c.compared,
                     outside.empty() ? "none outside" : "outside: " + outside);
}

}  // namespace

void reportContinuumSensitivity(const ContinuumSensitivityConfig& config,
                                const ContinuumSensitivityResults& r, Report& report) {
  int within = 0, compared = 0;
  for (const SensitivityCaseResult& c : r.cases) {
    within += c.within;
    compared += c.compared;
  }
  report.summary = fmt::format(
      "- {} of {} runs with one numerical parameter halved or doubled give the base run's "
      "period, centre-of-mass range and impact fronts within {:.0f} %.\n",
      within, compared, 100 * config.tolerance);
  for (std::size_t k = 0; k < r.cases.size(); ++k)
    report.summary += caseAnswer(config, k, r.cases[k]);
  ReportSection& s = report.section(
      "Sensitivity to the numerical parameters",
      "A continuum answer counts only if it does not move when a numerical or regularisation "
      "parameter is halved or doubled (docs/hydro.md, \"Sensitivity to the numerical "
      "parameters\"). One table per case; every run starts as the particles do.");
  for (std::size_t k = 0; k < r.cases.size(); ++k) {
    s.add(caseFigure(config, k, r.cases[k]));
    s.add(caseTable(config, k, r.cases[k]));
  }
}

}  // namespace granwave
