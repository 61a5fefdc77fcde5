#include "studies/readings/ReadingsReport.hpp"

#include <fmt/format.h>

#include <cmath>

namespace granwave {

namespace {

std::string share(double v) { return std::isfinite(v) ? fmt::format("{:.0f} %", 100 * v) : "-"; }

Table readingsTable(const ReadingsConfig& c, const ReadingsResults& r) {
  Table t;
  t.title = "The readings and their physical cost";
  t.caption = fmt::format(
      "Each reading sets contact.kappa_units, wall_tangential, tc_tangential and tc_window "
      "(docs/scenes.md). e_dry(1 m/s) = 1 - kappa_SI and e_dry(v0) at the plate's peak speed "
      "v0 = {:.3f} m/s of the wave point: measured glass-on-glass restitution near 1 m/s is "
      "about 0.9-0.97, so a lower e_dry is lossier than real glass. TC share: the fraction of "
      "all collisions (pair and wall) the TC model made elastic at the wave point, summed over "
      "seeds. CPU s: all runs of the reading.",
      c.wave_v0);
  t.columns = {"reading",      "kappa units",  "walls",        "TC tangential",
               "TC window",    "kappa_SI",     "e_dry(1 m/s)", "e_dry(v0)",
               "TC share dry", "TC share wet", "CPU s",        "failed runs"};
  for (std::size_t i = 0; i < c.readings.size(); ++i) {
    const Reading& g = c.readings[i];
    const ReadingOutcome& o = r.readings[i];
    t.rows.push_back(
        {g.name, g.kappa_units, g.wall_tangential, g.tc_tangential, g.tc_window,
         fmt::format("{:.4f}", g.kappa_si), fmt::format("{:.3f}", o.e_dry_1ms),
         fmt::format("{:.3f}", o.e_dry_v0), share(o.tc_elastic_share[0]),
         share(o.tc_elastic_share[1]), fmt::format("{:.0f}", o.cpu_seconds),
         o.failed_runs ? fmt::format("{} ({})", o.failed_runs, o.first_failure) : "0"});
  }
  return t;
}

Table verdictTable(const ReadingsConfig& c, const ReadingsResults& r) {
  Table t;
  t.title = "Which statements of the paper each reading reproduces";
  t.caption = fmt::format(
      "{} seeds per reading, law and drive point, {} cycles per run. Fractions: seeds showing "
      "the statement; a majority statement holds if the 68 % Wilson interval of the fraction "
      "lies above 1/2, fails if below, else undecided. Numbers: mean +- standard error over "
      "seeds, compared with the paper within 2 sigma (sigma^2 = error^2 + the paper's "
      "uncertainty; for phases, its rounding to 0.01 and the phase bin), undecided when the "
      "number's own error exceeds the paper's uncertainty. Period and state "
      "from the live classifier of each run (docs/classification.md).",
      c.seeds.size(), formatCompact(c.cycles));
  t.columns = {"the paper says"};
  for (const Reading& g : c.readings) t.columns.push_back(g.name);
  for (int s = 0; s < kStatements; ++s) {
    std::vector<std::string> row{kStatementTexts[s].paper};
    for (const ReadingOutcome& o : r.readings)
      row.push_back(fmt::format("{}: {}", verdictName(o.verdict[s]), o.measured[s]));
    t.rows.push_back(std::move(row));
  }
  std::vector<std::string> total{"statements that hold"};
  for (const ReadingOutcome& o : r.readings)
    total.push_back(fmt::format("{} of {}", o.holds(), int{kStatements}));
  t.rows.push_back(std::move(total));
  return t;
}

Figure verdictMap(const ReadingsConfig& c, const ReadingsResults& r) {
  Image map;
  map.nx = static_cast<int>(c.readings.size());
  map.ny = kStatements;
  map.values.assign(static_cast<std::size_t>(map.nx * map.ny), NAN);
  for (int i = 0; i < map.nx; ++i)
    for (int s = 0; s < kStatements; ++s)
      map.values[static_cast<std::size_t>(s * map.nx + i)] =
          static_cast<double>(r.readings[i].verdict[s]);
  map.x0 = -0.5;
  map.x1 = map.nx - 0.5;
  map.y0 = -0.5;
  map.y1 = map.ny - 0.5;
  for (const Reading& g : c.readings) map.x_labels.push_back(g.name);
  for (const StatementText& s : kStatementTexts) map.y_labels.push_back(s.paper);
  map.label = "verdict";
  map.category_labels = {"holds", "fails", "undecided", "no data"};
  // Okabe and Ito's blue, vermillion and yellow: told apart with any colour vision.
  map.category_colors = {"#0072B2", "#D55E00", "#F0E442", "lightgrey"};
  Figure f;
  f.title = "Verdict map";
  f.caption = "The table above as colours: one column per reading, one row per statement.";
  f.xlabel = "reading";
  f.ylabel = "statement";
  f.image.push_back(std::move(map));
  f.legend = false;
  return f;
}

std::string summary(const ReadingsConfig& c, const ReadingsResults& r) {
  std::vector<std::string> all, best;
  int most = -1;
  for (std::size_t i = 0; i < r.readings.size(); ++i) {
    const int h = r.readings[i].holds();
    if (h == kStatements) all.push_back(c.readings[i].name);
    if (h > most) best.clear();
    if (h >= most) {
      most = h;
      best.push_back(c.readings[i].name);
    }
  }
  std::string s = fmt::format(
      "- {} readings of the paper's model text, each run with {} seeds per law and drive point; "
      "nothing tuned.\n",
      c.readings.size(), c.seeds.size());
  if (!all.empty())
    s += fmt::format("- Reproducing every one of the {} statements checked: {}.\n",
                     int{kStatements}, fmt::join(all, ", "));
  else
    s += fmt::format(
        "- No reading reproduces all {} statements checked; the most ({}) hold for: "
        "{}.\n",
        int{kStatements}, most, fmt::join(best, ", "));
  return s +
         "- What decides: a majority statement holds if the 68 % Wilson interval of the share of "
         "seeds showing it lies above 1/2; a measured number holds within 2 sigma of the paper's "
         "(its error and the paper's uncertainty combined).\n";
}

}  // namespace

void reportReadings(const ReadingsConfig& c, const ReadingsResults& r, Report& report) {
  report.title = "Readings of the paper's model text";
  report.summary = summary(c, r);
  ReportSection& s = report.section(
      "Readings and verdicts",
      "The paper fixes neither the velocity unit of kappa in e_dry = 1 - kappa v_n^(1/5) "
      "(\"with the material parameter kappa = 0.1\"), nor what its tangential COR \"set to 1\" "
      "at the walls and \"e_n = e_t = 1\" in TC collisions mean in its own convention, nor "
      "whether \"only the first collision of each particle within this time scale is "
      "inelastic\" restarts the window at every collision. Each reading below is one choice "
      "for each; docs/physics.md gives the sentences and the readings in full.");
  s.add(readingsTable(c, r));
  s.add(verdictTable(c, r));
  s.add(verdictMap(c, r));
}

}  // namespace granwave
