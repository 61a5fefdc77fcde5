#include "studies/sound_speed/SoundSpeedReport.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace granwave {

namespace {

template <class T, class F>
std::string listOf(const std::vector<T>& values, F format) {
  std::string x;
  for (const T& v : values) x += (x.empty() ? "" : ", ") + format(v);
  return "[" + x + "]";
}

std::string method(const SoundSpeedConfig& c) {
  return fmt::format(
      "Every impact front of the particle runs (dry and wet, N = {}, Gamma = {}; {:g} s, "
      "seed {}). The gas ahead is the {} rows (diameters) starting {} row(s) above the "
      "front, the gas behind the same below it, area-fraction weighted and averaged over "
      "the front's phases. The front speed w is taken relative to the gas ahead; the "
      "piston speed U_p is the velocity of the gas behind relative to the gas ahead. "
      "Theories (hydro/SoundSpeed.hpp, hydro/ShockRelations.hpp), each evaluated with the "
      "Maxwell-averaged closure of the layer's own law at the temperature ahead: the "
      "adiabatic and isothermal sound speeds; the Rankine-Hugoniot shock driven by U_p; "
      "the strong shock into cold gas; the compaction front (close packing behind); and "
      "mass conservation across the measured states. A theory holds for a front when it "
      "lies within 2 combined sigma of w (errors: the front's fit and block errors, and "
      "the spread of each prediction over the blocks).",
      listOf(c.counts, [](int n) { return std::to_string(n); }),
      listOf(c.gammas, [](double v) { return formatCompact(v); }), c.duration, c.seed, c.rows,
      c.gap);
}

Table statesTable(const SoundSpeedResults& r) {
  Table t;
  t.title = "States ahead of and behind each front";
  t.columns = {"run",       "front at t/T",     "nu ahead",  "T ahead / T0", "u_z ahead (m/s)",
               "nu behind", "u_z behind (m/s)", "U_p (m/s)", "w (m/s)"};
  for (const FrontComparison& f : r.fronts) {
    const FrontStates& st = f.states;
    switch (f.outcome) {
      case FrontComparison::Outcome::RunFailed:
        t.rows.push_back({f.run, "failed: " + f.failure, "–", "–", "–", "–", "–", "–", "–"});
        break;
      case FrontComparison::Outcome::NoState:
        t.rows.push_back({f.run, formatNumber(f.start), "–", "–", "–", "–", "–", "–",
                          "no state: the front reaches the edge of the layer (failed to "
                          "sample)"});
        break;
      case FrontComparison::Outcome::Compared:
        t.rows.push_back({f.run, formatNumber(f.start), formatNumber(st.ahead.nu, 3),
                          formatNumber(st.ahead.T / f.T0, 3), formatNumber(st.ahead.uz),
                          formatNumber(st.behind.nu, 3), formatNumber(st.behind.uz),
                          formatNumber(st.behind.uz - st.ahead.uz), format(f.w)});
        break;
    }
  }
  return t;
}

Table comparisonTable(const SoundSpeedResults& r) {
  Table t;
  t.title = "Front speed against each theory (relative to the gas ahead, m/s)";
  t.caption =
      "Each cell: prediction ± spread over blocks, then (w - prediction) / prediction "
      "and whether it holds (2 sigma).";
  t.columns = {"run", "w (m/s)", "Mach w/c_s"};
  for (const char* name : kTheoryNames) t.columns.push_back(name);
  for (const FrontComparison& f : r.fronts) {
    if (f.outcome != FrontComparison::Outcome::Compared) continue;
    std::vector<std::string> row{fmt::format("{} (t/T {:.2f})", f.run, f.start), format(f.w),
                                 formatNumber(f.w.value / f.theory[0].value, 2)};
    for (int k = 0; k < kTheories; ++k) {
      const Measurement& m = f.theory[k];
      row.push_back(m.valid() ? fmt::format("{}: {:+.0f} %, {}", format(m),
                                            100 * (f.w.value - m.value) / m.value,
                                            f.holds[k] ? "holds" : "misses")
                              : "n/a (no compression)");
    }
    t.rows.push_back(row);
  }
  return t;
}

Figure measuredAgainstPredicted(const SoundSpeedResults& r) {
  static const char* kColors[kTheories] = {"tab:blue",   "tab:cyan",  "tab:red",
                                           "tab:orange", "tab:green", "tab:purple"};
  Figure fig;
  fig.title = "Measured front speed against each theory";
  fig.caption = "Each point is one front; on the dashed line theory and particles agree.";
  fig.xlabel = "predicted speed relative to the gas ahead (m/s)";
  fig.ylabel = "measured w (m/s)";
  double top = 0;
  for (int k = 0; k < kTheories; ++k) {
    const TheorySeries& t = r.theories[k];
    if (t.predicted.empty()) continue;
    Series sk = errorSeries(t.predicted, t.measured, t.measured_error, kTheoryNames[k], kColors[k]);
    sk.xerr = t.predicted_error;
    sk.linestyle = "none";
    fig.series.push_back(sk);
    for (double v : t.predicted) top = std::max(top, v);
    for (double v : t.measured) top = std::max(top, v);
  }
  Series diag = lineSeries({0.0, top * 1.1}, {0.0, top * 1.1}, "agreement", "black");
  diag.linestyle = "--";
  fig.series.push_back(diag);
  return fig;
}

}  // namespace

void reportSoundSpeed(const SoundSpeedConfig& c, const SoundSpeedResults& r, Report& report) {
  ReportSection& s = report.section("Fronts against sound-speed and shock theory", method(c));
  Table verdict;
  verdict.title = "How often each theory holds";
  verdict.columns = {"theory", "fronts tested", "holds within 2 sigma"};
  std::string summary;
  for (int k = 0; k < kTheories; ++k) {
    const TheorySeries& t = r.theories[k];
    verdict.rows.push_back({kTheoryNames[k], std::to_string(t.tested), std::to_string(t.holds)});
    summary +=
        fmt::format("- {}: holds for {} of {} fronts.\n", kTheoryNames[k], t.holds, t.tested);
  }
  s.add(std::move(verdict));
  s.add(measuredAgainstPredicted(r));
  s.add(comparisonTable(r));
  s.add(statesTable(r));
  report.summary = summary +
                   "- What decides: a theory holds for a front when its prediction lies within 2 "
                   "combined sigma of the measured front speed w.\n";
}

}  // namespace granwave
