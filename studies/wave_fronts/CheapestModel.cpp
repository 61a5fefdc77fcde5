// The cheapest model that reproduces the particles, scene by scene (docs/studies.md, "Cost per
// answer at equal accuracy").
#include "studies/wave_fronts/CheapestModel.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "coarse_grain/FrontTransit.hpp"          // kReportedFractions
#include "coarse_grain/PeriodDoublingSeries.hpp"  // kZ95
#include "studies/contract/FailureReason.hpp"
#include "studies/contract/StudyResults.hpp"
#include "studies/wave_fronts/WaveFrontsAnalysis.hpp"

namespace granwave {

namespace {

// (v - ref) / ref with both errors: the accuracy axis.
Measurement relativeGap(const Measurement& v, const Measurement& ref) {
  if (!v.valid() || !ref.valid() || ref.value == 0) return {};
  const double ev = std::isfinite(v.error) ? v.error : 0.0;
  const double er = std::isfinite(ref.error) ? ref.error : 0.0;
  return {(v.value - ref.value) / ref.value, std::hypot(ev, er) / std::abs(ref.value)};
}

// The same for a transit, where the particles' error may be unknown (then so is the gap's);
// the continuum's transit is deterministic (no error of its own).
Measurement transitGap(const Measurement& continuum, const Measurement& particles) {
  if (!continuum.valid() || !particles.valid() || particles.value == 0) return {};
  const double own = std::isfinite(continuum.error) ? continuum.error : 0.0;
  return {(continuum.value - particles.value) / particles.value,
          std::hypot(own, particles.error) / std::abs(particles.value)};
}

ModelCost reference(const std::string& periods, const Measurement& speed, double cpu) {
  ModelCost m;
  m.model = "particles, full model";
  m.reference = true;
  m.cpu = cpu;
  m.speed = speed;
  if (speed.valid()) m.gap = {0.0, std::abs(speed.error / speed.value)};
  m.periods = periods;
  m.match = Match::yes;
  m.why = "the reference";
  return m;
}

// The paper's scene of one law: the full particle model and the hierarchy's candidates.
SceneCost paperScene(const WaveFrontsConfig& c, const ModelHierarchy& h, int law) {
  SceneCost s;
  s.scene = fmt::format("paper's scene, {}", kLawNames[law]);
  s.models.push_back(
      reference(h.reference_periods, h.reference, h.reference_cpu_per_cycle * c.answer_cycles));
  for (const ModelCandidate& cand : h.candidates) {
    ModelCost m;
    m.model = cand.description;
    m.continuum = cand.key.rfind("hydro", 0) == 0;
    m.failed = cand.failed;
    // The run's CPU time as recorded (the particles' too); a failed run gave no answer.
    m.cpu = cand.failed ? NAN : m.continuum ? cand.run_cpu : cand.cpu_per_cycle * c.answer_cycles;
    m.speed = cand.speed;
    m.gap = relativeGap(cand.speed, h.reference);
    m.periods = cand.periods;
    m.match = cand.failed ? Match::no : cand.match;
    m.why = cand.failed           ? cand.failure
            : !cand.speed.valid() ? "no resolved front"
                                  : "front speed and time in the period-2 state";
    s.models.push_back(m);
  }
  return s;
}

std::string joined(const std::vector<int>& v) {
  std::string out;
  for (int x : v) out += (out.empty() ? "" : ", ") + (x > 0 ? std::to_string(x) : "none");
  return out;
}

// "mass 0.1-0.5", "mass 0.5-0.9": transit i between consecutive kReportedFractions.
std::string transitName(int i) {
  return fmt::format("mass {:g}-{:g}", kReportedFractions[i], kReportedFractions[i + 1]);
}

// The period part of a sweep verdict: no when every seed agrees on a period the continuum
// does not have; not yet when the seeds differ and its period is none of theirs (two seeds do
// not rule it out). Otherwise nothing, and `note` says what the period check found.
std::optional<Match> periodVerdict(int period, const std::vector<int>& periods, std::string& why,
                                   std::string& note) {
  bool agree = !periods.empty() && periods.front() > 0;
  for (int q : periods) agree = agree && q == periods.front();
  if (agree && period != periods.front()) {
    why = fmt::format("period {} against the particles' {}",
                      period > 0 ? std::to_string(period) : std::string("none"), periods.front());
    return Match::no;
  }
  const bool among = std::find(periods.begin(), periods.end(), period) != periods.end();
  if (!agree && !among) {
    why = "the seeds' periods differ and the continuum's is none of them";
    return Match::not_yet;
  }
  note = agree ? "period" : "a period one of the seeds has";
  return std::nullopt;
}

// One transit of the continuum against the particles': nothing where the particles' fronts
// reach neither fraction (no speed, no bound). A transit within fewer phases than a speed needs
// is a lower bound: a speed below (1 - tolerance) of the other side's bound, or a bound above
// (1 + tolerance) of its speed, is a difference; any other comparison with a bound stays open.
std::optional<Match> transitMatch(const TransitSpeeds& c, const TransitSpeeds& p, double tolerance,
                                  std::string& why) {
  const bool p_bound = std::isfinite(p.lower_bound), c_bound = std::isfinite(c.lower_bound);
  if (!p.speed.valid() && !p_bound) {
    why = "the particles' fronts do not reach it";
    return std::nullopt;
  }
  if (!c.speed.valid() && !c_bound) {
    why = c.fronts == 0 ? "the continuum has no front" : "the continuum's front stops below it";
    return Match::no;
  }
  if (c.speed.valid() && p.speed.valid()) {
    const Measurement g = transitGap(c.speed, p.speed);
    // Without an error (fewer than half of the bootstrap's resamples resolve the particles'
    // transit) no difference is known at 95 %: more seeds give one.
    if (!std::isfinite(g.error)) {
      why = fmt::format("{:+.0f} %, the particles' without an error", 100 * g.value);
      return Match::not_yet;
    }
    why = fmt::format("{:+.0f} +- {:.0f} %", 100 * g.value, 100 * g.error);
    return frontMatch(c.speed, p.speed, tolerance, true);
  }
  if (c.speed.valid()) {  // the particles' bound only
    const double own = std::isfinite(c.speed.error) ? c.speed.error : 0.0;
    const bool slower = c.speed.value + kZ95 * own < (1 - tolerance) * p.lower_bound;
    why = fmt::format("{:.3g} m/s against the particles' bound > {:.3g}", c.speed.value,
                      p.lower_bound);
    return slower ? Match::no : Match::not_yet;
  }
  if (p.speed.valid()) {  // the continuum's bound only
    const double own = std::isfinite(p.speed.error) ? p.speed.error : 0.0;
    const bool faster = c.lower_bound > (1 + tolerance) * (p.speed.value + kZ95 * own);
    why = fmt::format("bound > {:.3g} m/s against the particles' {:.3g}", c.lower_bound,
                      p.speed.value);
    return faster ? Match::no : Match::not_yet;
  }
  why = "both cross it within fewer phases than a speed needs";
  return Match::not_yet;
}

int severity(Match m) {
  switch (m) {
    case Match::no:
      return 3;
    case Match::not_yet:
      return 2;
    case Match::cannot_tell:
      return 1;
    case Match::yes:
      return 0;
  }
  return 3;
}

// One count of the N sweep: the particles over the sweep's seeds against the continuum with the
// velocity-dependent closure, judged by the transits through the layer's mass.
SceneCost sweepScene(const WaveFrontsConfig& c, const SweepPoint& p, int law, int count) {
  SceneCost s;
  s.scene = fmt::format("N = {}, {}", count, kLawNames[law]);
  ModelCost ref =
      reference(joined(p.seed_periods), p.tracked.speed, p.ed_cpu_per_cycle * c.answer_cycles);
  VelocityFronts particles = p.tracked;
  for (int i = 0; i < 2; ++i) particles.transit[i] = particleTransit(p, i);
  ref.has_transits = true;
  for (int i = 0; i < 2; ++i) ref.transit[i] = particles.transit[i];
  if (!p.tracked.speed.valid())
    ref.why = std::isfinite(p.tracked.lower_bound)
                  ? fmt::format(
                        "the reference; its front crosses the layer faster than the "
                        "phases resolve (> {:.3g} m/s)",
                        p.tracked.lower_bound)
                  : "the reference; no front speed: " + p.tracked.why_none;
  s.models.push_back(ref);
  ModelCost m;
  m.model = "hydro, velocity-dependent closure, Jenkins-Richman";
  m.continuum = true;
  m.failed = !p.hydro_ok;
  m.cpu = p.hydro_ok ? p.hydro_cpu : NAN;
  m.speed = p.hydro_tracked.speed;
  m.has_transits = p.hydro_ok;
  for (int i = 0; i < 2; ++i) m.transit[i] = p.hydro_tracked.transit[i];
  m.gap = relativeGap(m.speed, p.tracked.speed);
  for (int i = 0; i < 2 && m.has_transits; ++i) {
    const Measurement g = transitGap(m.transit[i].speed, particles.transit[i].speed);
    if (std::isfinite(g.value) &&
        (m.gap_on == "fit" || std::abs(g.value) > std::abs(m.gap.value))) {
      m.gap = g;
      m.gap_on = transitName(i);
    }
  }
  m.periods = p.hydro_ok ? joined({p.hydro_period}) : "";
  if (m.failed) {
    m.match = Match::no;
    m.why = "failed: " + shortReason(p.hydro_failure);
  } else {
    m.match = sweepTransitMatch(p.hydro_tracked, p.hydro_period, particles, p.seed_periods,
                                c.front_tolerance, m.why);
  }
  s.models.push_back(m);
  return s;
}

}  // namespace

Match sweepMatch(const Measurement& v, int period, const Measurement& ref, double bound,
                 const std::vector<int>& periods, double tolerance, std::string& why) {
  if (!v.valid()) {
    why = "no resolved front";
    return Match::no;
  }
  std::string note;
  if (const auto verdict = periodVerdict(period, periods, why, note)) return *verdict;
  const std::string period_note =
      note == "period" ? "front speed and period" : "front speed, and " + note;
  if (ref.valid()) {
    why = period_note;
    return frontMatch(v, ref, tolerance, true);
  }
  const double own = std::isfinite(v.error) ? v.error : 0.0;
  if (std::isfinite(bound) && v.value + kZ95 * own < (1 - tolerance) * bound) {
    why = fmt::format("slower than the particles' lower bound {:.3g} m/s", bound);
    return Match::no;
  }
  why = std::isfinite(bound)
            ? fmt::format("the particles give only a lower bound, {:.3g} m/s", bound)
            : std::string("the particles' front is not resolved");
  return Match::not_yet;
}

Match sweepTransitMatch(const VelocityFronts& c, int period, const VelocityFronts& p,
                        const std::vector<int>& periods, double tolerance, std::string& why) {
  std::string note;
  if (const auto verdict = periodVerdict(period, periods, why, note)) return *verdict;
  std::optional<Match> worst;
  std::string parts;
  for (int i = 0; i < 2; ++i) {
    std::string part;
    const auto m = transitMatch(c.transit[i], p.transit[i], tolerance, part);
    parts += fmt::format("{}{}: {}", i ? "; " : "", transitName(i), part);
    if (m && (!worst || severity(*m) > severity(*worst))) worst = m;
  }
  if (worst) {
    why = fmt::format("transits ({}) and {}", parts, note);
    return *worst;
  }
  // Nothing to compare the transits with: the fit, as before the transits existed.
  const Match fit = sweepMatch(c.speed, period, p.speed, p.lower_bound, periods, tolerance, why);
  why = fmt::format("the fit ({}): {}; {}", why, parts, note);
  return fit;
}

void pickCheapest(SceneCost& s) {
  s.cheapest = 0;
  s.cheaper_open.clear();
  // Without the particles' own cost nothing can be shown to be cheaper than them.
  if (s.models.empty() || !std::isfinite(s.models.front().cpu)) return;
  for (std::size_t i = 1; i < s.models.size(); ++i) {
    const ModelCost& m = s.models[i];
    if (m.match != Match::yes || !std::isfinite(m.cpu)) continue;
    if (m.cpu < s.models[static_cast<std::size_t>(s.cheapest)].cpu)
      s.cheapest = static_cast<int>(i);
  }
  const double limit = s.models.empty() ? NAN : s.models[static_cast<std::size_t>(s.cheapest)].cpu;
  for (std::size_t i = 1; i < s.models.size(); ++i) {
    const ModelCost& m = s.models[i];
    const bool open = m.match == Match::not_yet || m.match == Match::cannot_tell;
    if (open && std::isfinite(m.cpu) && !(m.cpu >= limit))
      s.cheaper_open.push_back(static_cast<int>(i));
  }
}

std::vector<SceneCost> cheapestModels(const WaveFrontsConfig& c, const WaveFrontsResults& r) {
  std::vector<SceneCost> out;
  for (int law = 0; law < kLaws; ++law) out.push_back(paperScene(c, r.models[law], law));
  for (int law = 0; law < kLaws; ++law)
    for (std::size_t i = 0; i < c.counts.size() && i < r.n_sweep[law].size(); ++i)
      out.push_back(sweepScene(c, r.n_sweep[law][i], law, c.counts[i]));
  for (SceneCost& s : out) pickCheapest(s);
  return out;
}

void writeCheapestModels(h5::File& f, const std::string& root,
                         const std::vector<SceneCost>& scenes) {
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    const SceneCost& s = scenes[k];
    const std::string g = fmt::format("{}/cost/cheapest/scene_{}", root, k);
    std::vector<double> cpu, speed, speed_error, gap, gap_error, transit[2], transit_error[2],
        transit_bound[2];
    std::string models, reproduces, open, gap_on;
    for (const ModelCost& m : s.models) {
      cpu.push_back(m.cpu);
      speed.push_back(m.speed.value);
      speed_error.push_back(m.speed.error);
      gap.push_back(m.gap.value);
      gap_error.push_back(m.gap.error);
      for (int i = 0; i < 2; ++i) {
        transit[i].push_back(m.has_transits ? m.transit[i].speed.value : NAN);
        transit_error[i].push_back(m.has_transits ? m.transit[i].speed.error : NAN);
        transit_bound[i].push_back(m.has_transits ? m.transit[i].lower_bound : NAN);
      }
      models += (models.empty() ? "" : "; ") + m.model;
      gap_on += (gap_on.empty() ? "" : "; ") + m.gap_on;
      reproduces +=
          (reproduces.empty() ? "" : "; ") + (m.failed ? "no (fails)" : matchText(m.match));
    }
    for (int i : s.cheaper_open)
      open += (open.empty() ? "" : "; ") + s.models[static_cast<std::size_t>(i)].model;
    f.createGroup(g);
    putSeries(f, g + "/cpu_seconds_per_answer", cpu, "s");
    putSeries(f, g + "/front_speed", speed, "m s-1");
    putSeries(f, g + "/front_speed_error", speed_error, "m s-1");
    putSeries(f, g + "/front_difference", gap, "1");
    putSeries(f, g + "/front_difference_error", gap_error, "1");
    const char* part[2] = {"dense", "upper"};  // mass 0.1-0.5, 0.5-0.9 (NaN: none)
    for (int i = 0; i < 2; ++i) {
      putSeries(f, fmt::format("{}/transit_{}", g, part[i]), transit[i], "m s-1");
      putSeries(f, fmt::format("{}/transit_{}_error", g, part[i]), transit_error[i], "m s-1");
      putSeries(f, fmt::format("{}/transit_{}_lower_bound", g, part[i]), transit_bound[i], "m s-1");
    }
    f.writeStringAttribute(g, "difference_on", gap_on);
    f.writeStringAttribute(g, "scene", s.scene);
    f.writeStringAttribute(g, "models", models);
    f.writeStringAttribute(g, "reproduces", reproduces);
    f.writeStringAttribute(g, "cheapest", s.models[static_cast<std::size_t>(s.cheapest)].model);
    f.writeStringAttribute(g, "cheaper_but_open", open);
  }
}

}  // namespace granwave
