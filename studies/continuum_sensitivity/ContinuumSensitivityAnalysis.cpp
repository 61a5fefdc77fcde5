#include "studies/continuum_sensitivity/ContinuumSensitivityAnalysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

// The largest relative change of a matched front (kInf: a front appeared or vanished), and into
// `sigma` that front's change over its fits' combined error (NaN: no such front or no errors).
double frontChange(const SensitivityAnswer& base, const SensitivityAnswer& run, double span,
                   double& sigma) {
  sigma = std::numeric_limits<double>::quiet_NaN();
  if (base.fronts.empty() != run.fronts.empty()) return kInf;
  double worst = 0, worst_sigma = sigma;
  for (const SensitivityFront& b : base.fronts) {
    const SensitivityFront* match = nullptr;
    for (const SensitivityFront& r : run.fronts)
      if (cyclicDistance(r.start, b.start, span) <= 0.03 &&
          (!match ||
           cyclicDistance(r.start, b.start, span) < cyclicDistance(match->start, b.start, span)))
        match = &r;
    if (!match || match->resolved != b.resolved || match->bulk != b.bulk) return kInf;
    if (!b.resolved) continue;
    const double change = std::abs(match->speed - b.speed) / b.speed;
    if (change < worst) continue;
    worst = change;
    const double e = std::hypot(b.fit_error, match->fit_error);
    worst_sigma =
        e > 0 ? std::abs(match->speed - b.speed) / e : std::numeric_limits<double>::quiet_NaN();
  }
  sigma = worst_sigma;
  return worst;
}

}  // namespace

SensitivityAnswer readSensitivityAnswer(const RunRecord& run, double tolerance) {
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
  for (const TrackedFront& f : trackFronts(frontProfiles(c.lab.pooled, c.lab.z), dt))
    a.fronts.push_back({c.lab.phase[static_cast<std::size_t>(f.first_phase)], f.resolved,
                        f.resolved ? f.speed : f.speed_lower_bound, f.resolved ? f.fit_error : 0.0,
                        f.bulk_crossing > 0, f.bulk_speed_lower_bound});
  return a;
}

SensitivityChange sensitivityChange(const SensitivityAnswer& base, const SensitivityAnswer& run,
                                    double tolerance) {
  SensitivityChange c;
  if (!base.ok || !run.ok) {
    c.com = c.front = kInf;
    return c;
  }
  c.same_period = base.period == run.period;
  const double excursion = std::max(base.com_high - base.com_low, 1e-12);
  c.com = std::max(std::abs(run.com_low - base.com_low), std::abs(run.com_high - base.com_high)) /
          excursion;
  c.front = frontChange(base, run, std::max(1, base.period), c.front_sigma);
  c.within = c.same_period && c.com < tolerance && c.front < tolerance;
  return c;
}

ContinuumSensitivityResults analyseContinuumSensitivity(const ContinuumSensitivityConfig& config,
                                                        const RunSet& runs) {
  ContinuumSensitivityResults r;
  for (const std::vector<SensitivityVariant>& variants : config.variants) {
    SensitivityCaseResult k;
    for (const SensitivityVariant& v : variants)
      k.answers.push_back(readSensitivityAnswer(runs.get(v.label), config.tolerance));
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
  for (std::size_t k = 0; k < r.cases.size(); ++k) {
    const SensitivityCaseResult& c = r.cases[k];
    const std::string g = kRoot + "/case_" + std::to_string(k);
    f.createGroup(g);
    f.writeStringAttribute(g, "name", config.cases[k].name);
    f.writeStringAttribute(g, "law", kLawNames[config.cases[k].law]);
    std::vector<std::string> parameter;
    std::vector<double> factor, period, solver_period, low, high, com, front, sigma, within, cpu,
        fastest, fastest_error;
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
      sigma.push_back(d.front_sigma);
      within.push_back(d.within ? 1 : 0);
      cpu.push_back(a.cpu_seconds);
      double fast = std::nan(""), fast_error = std::nan("");
      for (const SensitivityFront& fr : a.fronts)
        if (fr.resolved && (std::isnan(fast) || fr.speed > fast)) {
          fast = fr.speed;
          fast_error = fr.fit_error;
        }
      fastest.push_back(fast);
      fastest_error.push_back(fast_error);
    }
    f.writeStringArrayAttribute(g, "parameters", parameter);
    putSeries(f, g + "/factor", factor, "1");
    putSeries(f, g + "/period", period, "cycles");
    putSeries(f, g + "/solver_period", solver_period, "cycles");
    putSeries(f, g + "/com_low", low, "m");
    putSeries(f, g + "/com_high", high, "m");
    putSeries(f, g + "/com_change", com, "1");
    putSeries(f, g + "/front_change", front, "1");
    putSeries(f, g + "/front_change_sigma", sigma, "1");
    putSeries(f, g + "/fastest_front", fastest, "m s-1");
    putSeries(f, g + "/fastest_front_error", fastest_error, "m s-1");
    putSeries(f, g + "/within_tolerance", within, "1");
    putSeries(f, g + "/cpu_seconds", cpu, "s");
    putValue(f, g, "variants_within", c.within);
    putValue(f, g, "variants_compared", c.compared);
  }
}

}  // namespace granwave
