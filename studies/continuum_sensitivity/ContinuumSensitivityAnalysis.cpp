#include "studies/continuum_sensitivity/ContinuumSensitivityAnalysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "coarse_grain/FrontTransit.hpp"
#include "coarse_grain/ImpactFrontTracker.hpp"
#include "studies/contract/StudyResults.hpp"
#include "studies/run_files/HydroRunFile.hpp"

namespace granwave {

namespace {

const std::string kRoot = "/results/continuum_sensitivity";
constexpr double kInf = std::numeric_limits<double>::infinity();

// Mean over the settled cycles (the run's second half, at least its window) of each cycle's
// lowest and highest centre of mass above the plate.
void comRange(const HydroRunContent& c, SensitivityAnswer& a) {
  const std::vector<double>& h = c.com_history;
  const std::size_t M = static_cast<std::size_t>(std::max<std::int64_t>(c.phases_per_cycle, 0));
  const std::size_t cycles = M > 0 ? h.size() / M : 0;
  const std::size_t window = static_cast<std::size_t>(c.windowCycles());
  const std::size_t used = std::max(window, cycles / 2);
  if (cycles < used || used == 0) {  // a file without the history: the window alone
    std::vector<double> w = c.lab.pooled.center_of_mass_height;
    for (std::size_t k = 0; k < w.size() && k < c.lab.plate_height.size(); ++k)
      w[k] -= c.lab.plate_height[k];
    const auto [lo, hi] = std::minmax_element(w.begin(), w.end());
    a.com_low = w.empty() ? 0 : *lo;
    a.com_high = w.empty() ? 0 : *hi;
    return;
  }
  double low = 0, high = 0;
  for (std::size_t k = cycles - used; k < cycles; ++k) {
    const auto first = h.begin() + static_cast<long>(k * M);
    const auto [lo, hi] = std::minmax_element(first, first + static_cast<long>(M));
    low += *lo / used;
    high += *hi / used;
  }
  a.com_low = low;
  a.com_high = high;
}

// The smallest P (cycles, at most 4) with |com(t) - com(t - P T)| below `tolerance` of the
// centre of mass's excursion over the last 2P cycles: the period at the resolution the study
// compares at. The solver's own test (hydro::HydroSimulation, 2 % of the excursion at every
// phase) tells a P2 whose two cycles differ by 3 % from a P1; at a 5 % tolerance both are one
// answer, and a period-doubling that small is not one this comparison resolves.
int periodAtTolerance(const std::vector<double>& h, std::size_t M, double tolerance) {
  if (M == 0) return 0;
  const std::size_t cycles = h.size() / M;
  for (std::size_t P = 1; P <= 4 && 2 * P <= cycles; ++P) {
    const auto first = h.begin() + static_cast<long>((cycles - 2 * P) * M);
    const auto last = h.begin() + static_cast<long>(cycles * M);
    const auto [lo, hi] = std::minmax_element(first, last);
    const double excursion = *hi - *lo;
    double worst = 0;
    for (std::size_t k = (cycles - P) * M; k < cycles * M; ++k)
      worst = std::max(worst, std::abs(h[k] - h[k - P * M]));
    if (worst <= tolerance * excursion) return static_cast<int>(P);
  }
  return 0;
}

double cyclicDistance(double a, double b, double span) {
  const double d = std::fmod(std::abs(a - b), span);
  return std::min(d, span - d);
}

// The run's front that starts nearest to `b` (within 0.03 of a cycle), or null.
const SensitivityFront* matchingFront(const SensitivityFront& b, const SensitivityAnswer& run,
                                      double span) {
  const SensitivityFront* match = nullptr;
  for (const SensitivityFront& r : run.fronts)
    if (cyclicDistance(r.start, b.start, span) <= 0.03 &&
        (!match ||
         cyclicDistance(r.start, b.start, span) < cyclicDistance(match->start, b.start, span)))
      match = &r;
  return match;
}

// The largest relative change of a matched front's transits (kInf: one appeared or vanished,
// or became faster than the sampling by more than the tolerance; NaN: resolved in one run and
// faster than the sampling in the other, with a bound that does not tell them apart). A front
// with no transit resolved in either run is compared by its fit.
double transitChange(const SensitivityFront& b, const SensitivityFront& r, double tolerance) {
  if (b.transits.size() != r.transits.size()) return kInf;
  double worst = 0;
  bool resolved = false, undetermined = false;
  for (std::size_t i = 0; i < b.transits.size(); ++i) {
    const SensitivityTransit &tb = b.transits[i], &tr = r.transits[i];
    if (tb.reached != tr.reached) return kInf;
    if (!tb.reached || (!tb.resolved && !tr.resolved)) continue;
    resolved = true;
    if (tb.resolved && tr.resolved) {
      worst = std::max(worst, std::abs(tr.speed - tb.speed) / tb.speed);
      continue;
    }
    // One speed against the other's lower bound.
    const double speed = tb.resolved ? tb.speed : tr.speed;
    const double bound = tb.resolved ? tr.speed : tb.speed;
    if (bound > (1 + tolerance) * speed) return kInf;
    undetermined = true;
  }
  if (undetermined) return std::numeric_limits<double>::quiet_NaN();
  if (resolved || !b.resolved) return worst;
  return std::abs(r.speed - b.speed) / b.speed;
}

// Into c: the largest change of a matched front's transits (c.front) and of its fitted speed
// (c.fit, with c.fit_sigma that change over its fits' combined error).
void frontChanges(const SensitivityAnswer& base, const SensitivityAnswer& run, double span,
                  double tolerance, SensitivityChange& c) {
  c.fit_sigma = std::numeric_limits<double>::quiet_NaN();
  c.front = c.fit = 0;
  if (base.fronts.empty() != run.fronts.empty()) {
    c.front = c.fit = kInf;
    return;
  }
  for (const SensitivityFront& b : base.fronts) {
    const SensitivityFront* match = matchingFront(b, run, span);
    if (!match || match->resolved != b.resolved || match->bulk != b.bulk) {
      c.front = c.fit = kInf;
      c.fit_sigma = std::numeric_limits<double>::quiet_NaN();
      return;
    }
    const double transit = transitChange(b, *match, tolerance);
    // A change beyond doubt (inf) outranks an undetermined one (NaN), which outranks a number.
    if (std::isinf(transit) || std::isinf(c.front))
      c.front = kInf;
    else if (std::isnan(transit) || std::isnan(c.front))
      c.front = std::numeric_limits<double>::quiet_NaN();
    else
      c.front = std::max(c.front, transit);
    if (!b.resolved) continue;
    const double change = std::abs(match->speed - b.speed) / b.speed;
    if (change < c.fit) continue;
    c.fit = change;
    const double e = std::hypot(b.fit_error, match->fit_error);
    c.fit_sigma =
        e > 0 ? std::abs(match->speed - b.speed) / e : std::numeric_limits<double>::quiet_NaN();
  }
}

}  // namespace

SensitivityAnswer readSensitivityAnswer(const RunRecord& run, double tolerance,
                                        const std::vector<double>& front_fractions) {
  SensitivityAnswer a;
  a.cpu_seconds = run.cpu;
  if (!run.ok) {
    a.failure = run.message;
    return a;
  }
  const HydroRunContent c = readHydroRunFile(run.hydroPath());
  a.ok = true;
  a.solver_period = c.periodic ? static_cast<int>(c.period) : 0;
  a.period = c.com_history.empty()
                 ? a.solver_period
                 : periodAtTolerance(c.com_history, static_cast<std::size_t>(c.phases_per_cycle),
                                     tolerance);
  a.regime = c.regime;
  comRange(c, a);
  const double dt = c.lab.time.size() > 1 ? c.lab.time[1] - c.lab.time[0] : 0;
  const FrontProfiles profiles = frontProfiles(c.lab.pooled, c.lab.z);
  for (const TrackedFront& f : trackFronts(profiles, dt)) {
    SensitivityFront s{c.lab.phase[static_cast<std::size_t>(f.first_phase)],
                       f.resolved,
                       f.resolved ? f.speed : f.speed_lower_bound,
                       f.resolved ? f.fit_error : 0.0,
                       f.bulk_crossing > 0,
                       f.bulk_speed_lower_bound,
                       {}};
    for (std::size_t k = 0; k + 1 < front_fractions.size(); ++k) {
      const FrontTransit t =
          frontTransit(profiles, f, dt, front_fractions[k], front_fractions[k + 1]);
      s.transits.push_back({t.reached, t.resolved, t.resolved ? t.speed : t.speed_lower_bound});
    }
    a.fronts.push_back(std::move(s));
  }
  return a;
}

SensitivityChange sensitivityChange(const SensitivityAnswer& base, const SensitivityAnswer& run,
                                    double tolerance) {
  SensitivityChange c;
  if (!base.ok || !run.ok) {
    c.com = c.front = c.fit = kInf;
    return c;
  }
  c.same_period = base.period == run.period;
  const double excursion = std::max(base.com_high - base.com_low, 1e-12);
  c.com = std::max(std::abs(run.com_low - base.com_low), std::abs(run.com_high - base.com_high)) /
          excursion;
  frontChanges(base, run, std::max(1, base.period), tolerance, c);
  c.within = c.same_period && c.com < tolerance && c.front < tolerance;
  return c;
}

ContinuumSensitivityResults analyseContinuumSensitivity(const ContinuumSensitivityConfig& config,
                                                        const RunSet& runs) {
  ContinuumSensitivityResults r;
  for (const std::vector<SensitivityVariant>& variants : config.variants) {
    SensitivityCaseResult k;
    for (const SensitivityVariant& v : variants)
      k.answers.push_back(
          readSensitivityAnswer(runs.get(v.label), config.tolerance, config.front_fractions));
    for (const SensitivityAnswer& a : k.answers) {
      k.changes.push_back(sensitivityChange(k.answers.front(), a, config.tolerance));
      if (&a == &k.answers.front()) continue;
      ++k.compared;
      k.within += k.changes.back().within ? 1 : 0;
    }
    r.cases.push_back(std::move(k));
  }
  return r;
}

void writeContinuumSensitivityResults(h5::File& f, const ContinuumSensitivityConfig& config,
                                      const ContinuumSensitivityResults& r) {
  f.createGroup(kRoot);
  putValue(f, kRoot, "tolerance", config.tolerance);
  putSeries(f, kRoot + "/front_fractions", config.front_fractions, "1");
  for (std::size_t k = 0; k < r.cases.size(); ++k) {
    const SensitivityCaseResult& c = r.cases[k];
    const std::string g = kRoot + "/case_" + std::to_string(k);
    f.createGroup(g);
    f.writeStringAttribute(g, "name", config.cases[k].name);
    f.writeStringAttribute(g, "law", kLawNames[config.cases[k].law]);
    std::vector<std::string> parameter;
    std::vector<double> factor, period, solver_period, low, high, com, front, fit, sigma, within,
        cpu, fastest, fastest_error;
    const std::size_t transits = config.front_fractions.size() - 1;
    std::vector<std::vector<double>> transit(transits);
    for (std::size_t v = 0; v < c.answers.size(); ++v) {
      const SensitivityAnswer& a = c.answers[v];
      const SensitivityChange& d = c.changes[v];
      parameter.push_back(
          config.variants[k][v].parameter.empty() ? "base" : config.variants[k][v].parameter);
      factor.push_back(config.variants[k][v].factor);
      period.push_back(a.ok ? a.period : std::nan(""));
      solver_period.push_back(a.ok ? a.solver_period : std::nan(""));
      low.push_back(a.ok ? a.com_low : std::nan(""));
      high.push_back(a.ok ? a.com_high : std::nan(""));
      com.push_back(d.com);
      front.push_back(d.front);
      fit.push_back(d.fit);
      sigma.push_back(d.fit_sigma);
      within.push_back(d.within ? 1 : 0);
      cpu.push_back(a.cpu_seconds);
      const SensitivityFront* fast = nullptr;
      for (const SensitivityFront& fr : a.fronts)
        if (fr.resolved && (!fast || fr.speed > fast->speed)) fast = &fr;
      fastest.push_back(fast ? fast->speed : std::nan(""));
      fastest_error.push_back(fast ? fast->fit_error : std::nan(""));
      for (std::size_t i = 0; i < transits; ++i) {
        const bool known = fast && i < fast->transits.size() && fast->transits[i].resolved;
        transit[i].push_back(known ? fast->transits[i].speed : std::nan(""));
      }
    }
    f.writeStringArrayAttribute(g, "parameters", parameter);
    putSeries(f, g + "/factor", factor, "1");
    putSeries(f, g + "/period", period, "cycles");
    putSeries(f, g + "/solver_period", solver_period, "cycles");
    putSeries(f, g + "/com_low", low, "m");
    putSeries(f, g + "/com_high", high, "m");
    putSeries(f, g + "/com_change", com, "1");
    putSeries(f, g + "/front_change", front, "1");
    putSeries(f, g + "/fit_change", fit, "1");
    putSeries(f, g + "/fit_change_sigma", sigma, "1");
    putSeries(f, g + "/fastest_front", fastest, "m s-1");
    putSeries(f, g + "/fastest_front_error", fastest_error, "m s-1");
    for (std::size_t i = 0; i < transits; ++i)
      putSeries(f, g + "/fastest_front_transit_" + std::to_string(i), transit[i], "m s-1");
    putSeries(f, g + "/within_tolerance", within, "1");
    putSeries(f, g + "/cpu_seconds", cpu, "s");
    putValue(f, g, "variants_within", c.within);
    putValue(f, g, "variants_compared", c.compared);
  }
}

}  // namespace granwave
