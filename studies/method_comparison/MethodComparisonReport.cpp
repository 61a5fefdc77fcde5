#include "studies/method_comparison/MethodComparisonReport.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "studies/contract/FailureReason.hpp"
#include "studies/wave_analysis/FieldFigures.hpp"

namespace granwave {

namespace {

const char* const kNoPeakFront = "none: no T~g peak above 0.5 T0 rose from an impact";

Table costTable(const CostAccuracy& cost) {
  Table t;
  t.title = "Runs of the cost-accuracy chart";
  t.columns = {"method", "setting", "CPU s", "front speed (m/s)", "error (m/s)"};
  for (const CostRow& r : cost.rows) {
    if (r.particles) {
      t.rows.push_back(
          {"particles", fmt::format("{:g} s ({} cycles pooled)", r.duration, r.pooled_cycles),
           formatNumber(r.cpu), formatOr(r.speed, kNoPeakFront), formatNumber(r.error, 3)});
      continue;
    }
    const std::string setting = fmt::format("{} cells, rtol {:g}", r.cells, r.rtol);
    if (!r.ok)
      t.rows.push_back(
          {"hydro", setting, formatNumber(r.cpu), "failed: " + shortReason(r.failure), "–"});
    else
      t.rows.push_back({"hydro", setting + (r.reference ? " (reference)" : ""), formatNumber(r.cpu),
                        formatOr(r.speed, kNoPeakFront),
                        r.reference ? "reference" : formatNumber(r.error, 3)});
  }
  return t;
}

Table particleFailureTable(const MethodComparisonConfig& c, const FailureMap& m) {
  Table t;
  t.title = "Particles without the TC model";
  t.columns = {"Gamma", "dry", "wet"};
  for (std::size_t i = 0; i < c.fail_gammas.size(); ++i) {
    std::vector<std::string> row{formatCompact(c.fail_gammas[i])};
    for (const FailureCase& f : m.particles[i])
      row.push_back(f.ok ? fmt::format("ran {:g} s, period {}", c.fail_duration, f.period)
                         : shortReason(f.failure));
    t.rows.push_back(row);
  }
  return t;
}

// One row per case (law, grid, tolerance), one column per Gamma: the table stays as narrow as
// the Gamma values are few.
Table hydroFailureTable(const MethodComparisonConfig& c, const FailureMap& m) {
  Table t;
  t.title = "Hydro solver over Gamma, grid and tolerance";
  t.columns = {"law, grid, tolerance"};
  for (double gamma : c.fail_gammas) t.columns.push_back("Gamma = " + formatCompact(gamma));
  for (std::size_t k = 0; k < m.hydro_cases.size(); ++k) {
    std::vector<std::string> row{m.hydro_cases[k]};
    for (std::size_t i = 0; i < c.fail_gammas.size(); ++i) {
      const FailureCase& f = m.hydro[i][k];
      const std::string regime = f.regime == "fluidised" ? "" : " (" + f.regime + ")";
      row.push_back(!f.ok        ? "fails: " + shortReason(f.failure)
                    : f.periodic ? fmt::format("ok, period {}{}", f.period, regime)
                                 : fmt::format("ok, no period in {} cycles{}", f.cycles, regime));
    }
    t.rows.push_back(row);
  }
  return t;
}

// Two colours for a yes/no outcome, the cases and Gamma values named on the axes: vermillion
// and blue of Okabe and Ito's palette, told apart with any colour vision (not red and green).
Figure hydroFailureMap(const MethodComparisonConfig& c, const FailureMap& m) {
  Image map;
  map.nx = static_cast<int>(c.fail_gammas.size());
  map.ny = static_cast<int>(m.hydro_cases.size());
  map.values.assign(static_cast<std::size_t>(map.nx * map.ny), NAN);
  for (std::size_t i = 0; i < c.fail_gammas.size(); ++i)
    for (std::size_t k = 0; k < m.hydro_cases.size(); ++k)
      map.values[k * map.nx + i] = m.hydro[i][k].ok ? 1 : 0;
  map.x0 = -0.5;
  map.x1 = map.nx - 0.5;
  map.y0 = -0.5;
  map.y1 = map.ny - 0.5;
  for (double gamma : c.fail_gammas) map.x_labels.push_back(formatCompact(gamma));
  map.y_labels = m.hydro_cases;
  map.label = "CVODE outcome";
  map.category_labels = {"failed", "reached the end"};
  map.category_colors = {"#D55E00", "#0072B2"};
  Figure fm;
  fm.title = "Hydro stability map";
  fm.caption =
      "Each cell one hydro run of the table above: blue, the solver reached the end; "
      "vermillion, CVODE failed (the table gives the flag).";
  fm.xlabel = "Gamma";
  fm.ylabel = "law, grid, tolerance";
  fm.image.push_back(std::move(map));
  fm.legend = false;
  return fm;
}

// "0.58 (0.49–0.66)"; an exact share (deterministic model) alone; "–" if unknown.
std::string shareText(const StateShare& s) {
  if (!s.known()) return "–";
  if (s.effective_windows == 0) return fmt::format("{:.0f} (exact)", s.share);
  return fmt::format("{:.2f} ({:.2f}–{:.2f})", s.share, s.low, s.high);
}

std::string gapText(const ShareDifference& d) {
  if (std::isnan(d.difference)) return "–";
  return fmt::format("{:+.2f} ({:+.2f} to {:+.2f})", d.difference, d.low, d.high);
}

// The period a hydro candidate gave ("2", "none") or why it has none.
std::string hydroPeriod(const ModelHierarchy& m, const std::string& key) {
  for (const ModelCandidate& c : m.candidates)
    if (c.key == key) return c.failed ? "no period (failed)" : c.periods;
  return "not run";
}

// Every verdict the bootstrap resamples gave, with its share: "'none' 58 %, 'X' 42 %".
std::string resampleShares(const VerdictStability& v) {
  std::string out;
  for (const auto& [verdict, share] : v.shares)
    out += fmt::format("{}'{}' {}", out.empty() ? "" : ", ", verdict,
                       share < 0.01 ? std::string("< 1 %") : fmt::format("{:.0f} %", 100 * share));
  return out;
}

std::string seedCount(int n) { return n == 1 ? "1 seed" : fmt::format("{} seeds", n); }

// How often resamples of the seeds repeat the verdict, in plain words.
std::string agreementText(const VerdictStability& v) {
  if (v.seeds < 2)
    return "With one seed the bootstrap cannot test it (every resample is that seed)";
  std::string s = fmt::format(
      "The same verdict in {:.0f} % of {} bootstrap resamples of the "
      "seeds",
      100 * v.agreement, v.resamples);
  if (v.agreement < 1) s += fmt::format(" (all they give: {})", resampleShares(v));
  return s;
}

// A verdict in plain words (docs/studies.md, "Verdict stability"): what it is, what decided
// it or why nothing could, and how often resamples of the seeds repeat it. `names`: list the
// open candidates by name (the section) or count them (the headline).
std::string verdictText(const VerdictStability& v, bool names) {
  if (!v.decided)
    return fmt::format(
        "undecided at {}: a simpler candidate is not yet settled (an interval of its "
        "differences from the full model still crosses a tolerance's edge); bootstrap "
        "resamples of the seeds give {}",
        seedCount(v.seeds), resampleShares(v));
  const bool none = v.verdict == "none";
  if (v.open.empty())
    return fmt::format(
        "{}. Decided: with all {} every simpler candidate is settled (the 95 % intervals "
        "of its differences from the full model, front speed and time in period 2, lie wholly "
        "within the tolerances, or one lies wholly outside). {}",
        none ? "none of the simpler models reproduces the particles"
             : v.verdict + " is the simplest model that reproduces the particles",
        seedCount(v.seeds), agreementText(v) + ".");
  std::string open;
  for (const std::string& o : v.open) open += (open.empty() ? "" : "; ") + o;
  const std::size_t k = v.open.size();
  return fmt::format(
      "{}. Not decided by the data: at the cap of {} {} still not settled (an interval "
      "crosses a tolerance's edge: not shown to reproduce, not shown to differ) and passed "
      "over{}. {}",
      none ? "none of the simpler models is shown to reproduce the particles"
           : v.verdict + " is the simplest model shown to reproduce the particles",
      seedCount(v.seeds),
      k == 1 ? std::string("1 candidate is") : fmt::format("{} candidates are", k),
      names ? ": " + open : std::string(""), agreementText(v) + ".");
}

std::string doublingVerdict(const ModelHierarchy (&models)[2]) {
  std::string text = "Period doubling in the continuum: ";
  std::string split[2][2];  // [model smooth, rough][law]
  bool rough_matches = true;
  for (int law = 0; law < kLaws; ++law) {
    const ModelHierarchy& m = models[law];
    split[0][law] = hydroPeriod(m, MethodComparisonConfig::hydroRun(law, "velocity"));
    split[1][law] = hydroPeriod(m, MethodComparisonConfig::hydroRun(law, "rough"));
    rough_matches = rough_matches && m.reference_period > 0 &&
                    split[1][law] == std::to_string(m.reference_period);
    text += fmt::format(
        "{} layer, particles period {} (seeds {}), smooth-disk hydro {}, rough-particle hydro {}; ",
        kLawNames[law], m.reference_period, m.reference_periods, split[0][law], split[1][law]);
  }
  return text + (rough_matches
                     ? "the rough closure reproduces the particles' dry/wet periods."
                     : "the rough closure does not reproduce the particles' dry/wet periods "
                       "(or the particles' period is undecided).");
}

}  // namespace

void costSection(const MethodComparisonConfig&, const CostAccuracy& cost, Report& report) {
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
  Series eds = lineSeries(cost.ed_cpu, cost.ed_error, "particles (cycles averaged)", kLawColors[1]);
  eds.marker = "o";
  fig.series.push_back(eds);
  for (const auto& [rtol, xy] : cost.hydro_by_rtol) {
    std::vector<double> shown = xy.second;  // a zero error cannot sit on a log axis
    for (double& e : shown) e = std::max(e, 1e-4);
    Series hs = lineSeries(xy.first, shown, fmt::format("hydro, rtol {:g} (cells vary)", rtol));
    // A moved std::string, not a literal: GCC 12 warns falsely (-Wrestrict, GCC bug 105329)
    // on assigning a literal here once this loop is inlined.
    hs.marker = std::string("s");
    fig.series.push_back(hs);
  }
  if (std::isfinite(cost.model_gap) && cost.model_gap > 0)
    fig.series.push_back(
        horizontalLine(cost.model_gap, "model gap |hydro - particles|", 0, "black"));
  s.add(std::move(fig));
  s.add(costTable(cost));
}

void failureSection(const MethodComparisonConfig& c, const FailureMap& m, Report& report) {
  ReportSection& s = report.section(
      "Where each method fails",
      "Each case below was run. Particles without the TC model (contact.tc = \"off\"): inelastic "
      "collapse, an infinite number of collisions in finite time, stops the event-driven engine "
      "(it is detected and reported with the time and the particles). Hydro: the solver's "
      "outcome over Gamma, grid and tolerance. Its state is admissible by construction "
      "(temperature positive, packing below close packing; docs/hydro.md), so a failure means "
      "CVODE gave up or the step budget of a drive cycle ran out (stagnation), reported with the "
      "time and cycle. A layer that never leaves the plate or moves as a block is a result, "
      "not a failure: it is marked 'at rest' or 'solid'.");
  s.add(particleFailureTable(c, m));
  s.add(hydroFailureTable(c, m));
  s.add(hydroFailureMap(c, m));
}

std::vector<std::string> modelSection(const MethodComparisonConfig& config,
                                      const ModelHierarchy (&models)[2], Report& report) {
  ReportSection& s = report.section(
      "The simplest model that reproduces the particles",
      fmt::format(
          "Reference: the full particle model (rotation with Coulomb friction, velocity-dependent "
          "restitution), combined over seeds. Candidates from the simplest up, each judged on its "
          "impact-front speed by the velocity jump (the tracker of the N sweep below; the peak of "
          "T~g, the paper's marker, is not a travelling front on this scene: it sits near the "
          "plate at 0.45-0.7 m/s, then jumps to the top of the layer, and the line fitted across "
          "the jump depends on where the jump falls, docs/studies.md) and on its share of time "
          "in the period-2 state (Newcombe's "
          "hybrid score interval of the difference, over the effective numbers of 12-cycle "
          "windows; a hydro run is deterministic: its share is 0 for period 1, 1 for period 2, "
          "unknown otherwise). The share, not the period of each run, is compared, because a "
          "bistable layer's period is a draw from its states that round-off alone changes. A "
          "candidate reproduces the reference if the 95 % intervals of both differences lie "
          "within the study's tolerances ({}), and does not if either lies wholly outside; "
          "otherwise it is open, and seeds are added (the full and the simpler "
          "particle models) up to [particles] max_seeds. The verdict is the first candidate that "
          "reproduces; it is undecided while a simpler one is open, and at the cap a candidate "
          "still open is passed over as not shown to reproduce (and named). A hydro candidate "
          "whose own "
          "front error alone keeps its interval across the tolerance's edge cannot be told by any "
          "number of seeds and is passed over (the table marks it: the verdict is then the "
          "simplest among the candidates that could be told). Beside each verdict: the share of "
          "bootstrap resamples of the seeds that "
          "give it (docs/studies.md, \"Verdict stability\").",
          fmt::format("front speed within {:.0f} % of the reference's, time share within {:.2f}",
                      100 * config.front_tolerance, config.share_tolerance)));
  Table t;
  t.title = "Model hierarchy against the full particle model";
  t.caption =
      "Δ/σ: the front-speed difference from the reference in combined sigmas ('–' where "
      "either front speed is missing).";
  t.columns = {"layer",
               "model",
               "front speed, velocity jump (m/s)",
               "Δ/σ",
               "period (T)",
               "time in period 2 (95 %)",
               "share − reference's (95 %)",
               "reproduces"};
  std::vector<std::string> headline;
  std::string verdicts;
  for (int law = 0; law < kLaws; ++law) {
    const std::string name = kLawNames[law];
    const ModelHierarchy& m = models[law];
    t.rows.push_back({name, "particles, full model (reference)",
                      formatOr(m.reference, "none: no seed gave a velocity-jump front"), "0",
                      m.reference_periods + " (mode " + std::to_string(m.reference_period) + ")",
                      shareText(m.reference_share), "–", "–"});
    for (const ModelCandidate& c : m.candidates) {
      if (c.failed) {
        t.rows.push_back({name, c.description, c.failure, "–", "–", "–", "–", "no (fails)"});
        continue;
      }
      t.rows.push_back({name, c.description,
                        formatOr(c.speed, "none: no velocity-jump front resolved"),
                        formatNumber(c.sigma, 1), c.periods.empty() ? "–" : c.periods,
                        shareText(c.share), gapText(c.share_gap), matchText(c.match)});
    }
    const std::string law_name = name == "dry" ? "Dry layer" : "Wet layer";
    verdicts += fmt::format("- {}: {}\n", law_name, verdictText(m.stability, true));
    headline.push_back(fmt::format("{}: {}", law_name, verdictText(m.stability, false)));
  }
  s.add(std::move(t));
  s.addText(verdicts);
  s.addText(doublingVerdict(models));
  return headline;
}

void lammpsSection(const MethodComparisonConfig& c, const LammpsComparison& l,
                   const std::optional<FieldsRecord>& dry_seed1, const HydroOutcome& dry_hydro,
                   Report& report) {
  ReportSection& s = report.section(
      "The alternative a user would run: soft-sphere DEM (LAMMPS)",
      "The paper's scene with LAMMPS' granular package (studies/lammps/paper-scene.lmp: Hertz "
      "contacts of softened glass, E = 63 MPa, Tsuji damping for a binary restitution of 0.9, "
      "Mindlin friction 0.5, the same container and drive), beside the event-driven dry layer "
      "(seed 1; its restitution is close to 0.9 at the layer's impact speeds) and the hydro "
      "solver. Speeds are CPU seconds (one core each) per simulated second, measured in this "
      "study's run (CPU, not wall, time: the study runs several runs at once). The "
      "deck writes the centre of mass only, so no front speed is compared.");
  Table t;
  t.title = "Soft-sphere DEM against event-driven and continuum, dry layer";
  t.columns = {"method",       "CPU s per simulated s", "CM period (T)",
               "f/2 strength", "CM mean height / d",    "front speed (m/s)"};
  if (l.ed.ran)
    t.rows.push_back({"event-driven (granwave)", formatNumber(l.ed.cpu_rate, 4),
                      std::to_string(l.ed.period), "–", formatNumber(l.ed.mean_height, 2),
                      format(l.ed.front)});
  if (l.hydro.ran)
    t.rows.push_back({"hydro (granwave, velocity-dependent closure)",
                      formatNumber(l.hydro.cpu_rate, 3), std::to_string(l.hydro.period), "–",
                      formatNumber(l.hydro.mean_height, 2), format(l.hydro.front)});
  if (!l.ok) {
    t.rows.push_back({"LAMMPS", "failed: " + l.failure, "–", "–", "–", "–"});
    s.add(std::move(t));
    return;
  }
  const std::string f2 = l.period.strength.size() > 2 ? formatNumber(l.period.strength[2], 3) : "–";
  t.rows.push_back({"LAMMPS (soft-sphere DEM, one core)", formatNumber(l.lammps_rate, 3),
                    std::to_string(l.period.period), f2, formatNumber(l.mean_height, 2),
                    "not available (centre of mass only)"});
  s.add(std::move(t));

  // Centre of mass folded onto two cycles over the steady part, beside the particles'.
  const double d = c.scenes.base[0].particles.diameter;
  Figure fig;
  fig.title = "Centre of mass over two cycles: DEM, event-driven, hydro (dry)";
  fig.caption = "LAMMPS: averaged over its last 80 % of cycles, folded onto two cycles.";
  fig.xlabel = "t / T";
  fig.ylabel = "z_CM / d (lab frame)";
  fig.series.push_back(lineSeries(l.folded_phase, l.folded_height, "LAMMPS (DEM)", "tab:green"));
  if (dry_seed1)
    fig.series.push_back(centerOfMassSeries(dry_seed1->profiles, d, "event-driven", "tab:orange"));
  if (const auto& h = dry_hydro.fields) {
    Series hs = centerOfMassSeries(h->lab, d, "hydro", "tab:orange");
    hs.linestyle = "--";
    fig.series.push_back(hs);
  }
  s.add(std::move(fig));
  s.addText(fmt::format(
      "Measured in this run: LAMMPS takes {} CPU seconds per simulated second against {} for "
      "the event-driven engine on the same scene, a factor {}. Its centre of mass moves with "
      "period {} (f/2 strength {}), the event-driven dry layer with period {}.",
      formatNumber(l.lammps_rate, 2), formatNumber(l.ed_rate, 3), formatNumber(l.ratio, 0),
      l.period.period, f2, l.ed.ran ? std::to_string(l.ed.period) : "–"));
}

}  // namespace granwave
