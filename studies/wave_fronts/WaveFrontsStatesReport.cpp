// The wave-fronts study's report on the layer's state: share of seeds and of time in the
// period-2 state, and the fronts and r_x of each state's episodes (docs/studies.md,
// "State-resolved statistics").
#include <fmt/format.h>

#include "studies/wave_fronts/WaveFrontsReport.hpp"

namespace granwave {

namespace {
std::string share(double p, double lo, double hi) {
  if (!std::isfinite(p)) return "–";
  return fmt::format("{:.2f} ({:.2f}–{:.2f})", p, lo, hi);
}

// A state's value combined over the seeds that gave one, or why there is none: only seeds
// with at least as many windows in the state as blocks have its fields.
std::string withSeeds(const Measurement& m, int seeds) {
  if (!m.valid())
    return seeds == 0 ? "none: no seed with as many windows in this state as blocks gave one"
                      : "none: not resolved in this state's fields";
  return fmt::format("{} ({} seed{})", format(m), seeds, seeds == 1 ? "" : "s");
}
// The weak and the strong impact of the period-2 state, its windows aligned on their strong
// impact, beside the whole run's (whose 2-cycle average mixes both parities) and the paper's.
void weakAndStrongByParity(const WaveFrontsResults& r, ReportSection& s) {
  Table t;
  t.title = "Weak and strong impact fronts labelled by the state's parity";
  t.caption =
      "Velocity-jump fronts after the weak and after the strong impact (ranked by their peak "
      "T~g/T0 within a 2-cycle window), combined over seeds. Whole run: the phase average of "
      "every 2-cycle window, in which period-2 episodes of both parities (strong impact on "
      "even or on odd cycles) are added together. Period-2 state: only the period-2 windows, "
      "each turned to the parity of the first, so the strong impacts of all episodes fall on "
      "the same cycle (seeds: those with at least as many period-2 windows as blocks). Paper: "
      "Huang, Sec. IV (wet layer).";
  t.columns = {"layer", "fields", "seeds", "after the weak impact (m/s)",
               "after the strong impact (m/s)"};
  for (int law = 0; law < kLaws; ++law) {
    const VelocityFronts& whole = r.paper[law].tracked;
    const StateShares& st = r.states[law];
    const std::string none = "none: no resolved front matched to this impact";
    t.rows.push_back({kLawNames[law], "whole run", std::to_string(r.paper[law].seeds_used),
                      formatOr(whole.weak, none), formatOr(whole.strong, none)});
    t.rows.push_back({kLawNames[law], "period-2 state, aligned by parity",
                      std::to_string(st.front_seeds[1]),
                      formatOr(st.period2_weak, "none: no period-2 fields resolved it"),
                      formatOr(st.period2_strong, "none: no period-2 fields resolved it")});
  }
  t.rows.push_back({"wet", "paper", "–", format(kPaperWeakWet), format(kPaperStrongWet)});
  s.add(std::move(t));
}
}  // namespace

void stateSection(const WaveFrontsResults& r, Report& report) {
  ReportSection& s = report.section(
      "The layer's state: period 1 and period 2",
      "A run's centre of mass cut into windows of 12 cycles after the transient; a window is in "
      "the period-2 state when its f/2 strength exceeds the larger of 0.1 and three times the "
      "strength the same comb shifted off the f/2 lines holds (the window's own noise). Share "
      "of seeds: runs whose whole-run period is 2 (95 % Wilson interval, n = seeds). Share of "
      "time: windows in the period-2 state over all seeds (95 % Wilson interval with the summed "
      "effective numbers of windows). Fronts (by the velocity jump) and r_x of a state: the "
      "phase averages of that state's windows alone (period-2 windows aligned on their strong "
      "impact), combined over "
      "the seeds that had at least as many windows in the state as blocks; r_x against the "
      "whole dry run of the same seed.");
  Table t;
  t.title = "State shares and state-conditioned fronts (paper's scene)";
  t.columns = {"layer",
               "seeds",
               "period-2 share of seeds",
               "windows",
               "period-2 share of time",
               "velocity-jump front, period 1 (m/s)",
               "velocity-jump front, period 2 (m/s)",
               "r_x, period 1",
               "r_x, period 2"};
  for (int law = 0; law < kLaws; ++law) {
    const StateShares& st = r.states[law];
    t.rows.push_back(
        {kLawNames[law], std::to_string(st.seeds), share(st.seed_share, st.seed_low, st.seed_high),
         fmt::format("{} ({} period 2)", st.windows, st.windows_period2),
         share(st.time_share, st.time_low, st.time_high), withSeeds(st.front[0], st.front_seeds[0]),
         withSeeds(st.front[1], st.front_seeds[1]),
         law == 1 ? withSeeds(st.r_x[0], st.r_x_seeds[0]) : "wet layer only",
         law == 1 ? withSeeds(st.r_x[1], st.r_x_seeds[1]) : "wet layer only"});
  }
  s.add(std::move(t));
  weakAndStrongByParity(r, s);
}

}  // namespace granwave
